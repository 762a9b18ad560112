// Bits shared by the plugin-inspection tools (rixwarp, rixlobe).
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/Math.h"
#include "checks/CheckSupport.h"
#include "probe/BxdfProbe.h"
#include "shade/PluginSearchPath.h"

namespace bxdflab::tools {

using bxdflab::checks::direction;  // labkit's: the unit direction at (theta, phi) degrees about +z
using bxdflab::checks::viewFrom;   // labkit's: the default shade point seen from (theta, phi)
using bxdflab::checks::number;     // labkit's: a number as the reports print it

/// Writes a diagram (a plot or a colour map, already in display colours) as
/// 8 bits per channel, with no colour conversion; throws on failure.
void writeDisplayImage(OIIO::ImageBuf const& image, std::string const& path);

/// Writes `text` with its baseline at (x, y) in DejaVu Sans (package
/// fonts-dejavu-core); a figure without its labels is still written, with a warning.
void label(OIIO::ImageBuf& image, int x, int y, std::string const& text, std::vector<float> const& colour = {0.15f, 0.15f, 0.15f},
           int size = 15);

/// A heat map of `values` (row-major, height x width) with colours scaled to [0, maxValue], each cell
/// drawn as a `cell` x `cell` block.
OIIO::ImageBuf heatmap(std::vector<double> const& values, int width, int height, double maxValue, int cell);

}  // namespace bxdflab::tools
