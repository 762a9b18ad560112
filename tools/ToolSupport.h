// Bits shared by the plugin-inspection tools (rixwarp, rixlobe).
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/Math.h"
#include "probe/BxdfProbe.h"
#include "shade/PluginSearchPath.h"

namespace bxdflab::tools {

/// The unit direction at polar angle theta and azimuth phi (degrees) about +z.
inline Vec3 direction(float thetaDegrees, float phiDegrees) {
    float t = glm::radians(thetaDegrees), p = glm::radians(phiDegrees);
    return Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

/// A shade point with N = +z, dPdu = +x and the viewer at (theta, phi).
inline ProbePoint viewPoint(float thetaDegrees, float phiDegrees) {
    ProbePoint point;
    point.V = direction(thetaDegrees, phiDegrees);
    return point;
}

/// Writes a diagram (a plot or a colour map, already in display colours) as
/// 8 bits per channel, with no colour conversion; throws on failure.
void writeDisplayImage(OIIO::ImageBuf const& image, std::string const& path);

/// A heat map of `values` (row-major, height x width) with colours scaled to [0, maxValue], each cell
/// drawn as a `cell` x `cell` block.
OIIO::ImageBuf heatmap(std::vector<double> const& values, int width, int height, double maxValue, int cell);

}  // namespace bxdflab::tools
