// What the checks share: the shade points they probe (a frame turned away
// from the world axes), directions by angle, comparisons, and how numbers
// are written in messages.
#pragma once

#include <sstream>
#include <string>

#include "checks/Check.h"

namespace bxdflab::checks {

/// The frame every check's shade points use: N and dPdu turned away from the
/// world axes, so a plugin that assumes N = +z or a tangent of +x is caught;
/// dPdu neither unit length nor perpendicular to N (the tangent is dPdu made
/// perpendicular to N and normalised, as the renderer's Tn).
struct Frame {
    /// Turned `degrees` about an axis that leaves no world axis in place; the
    /// checks' usual frame (frame()) is turned 40 degrees, others give the
    /// points of one batch normals of their own.
    explicit Frame(float degrees = 40.0f);
    Vec3 toWorld(Vec3 const& local) const { return m_R * local; }
    Vec3 toLocal(Vec3 const& world) const { return glm::transpose(m_R) * world; }
    /// A shade point with the viewer at local direction V (unit).
    ProbePoint point(Vec3 const& localV) const;
    /// The same with a given local tangent (dPdu), e.g. zero for a degenerate frame.
    ProbePoint point(Vec3 const& localV, Vec3 const& localTangent) const;
    /// The first with the geometric normal at bentGeometricNormal() (the
    /// shading normal stays +z), as on a smooth-shaded mesh.
    ProbePoint bentPoint(Vec3 const& localV) const;

private:
    ProbePoint point(Vec3 const& localV, Vec3 const& localNg, Vec3 const& localTangent) const;
    static Vec3 defaultTangent() { return Vec3(2.5f, 0.0f, 0.8f); }
    Mat3 m_R;
};
Frame const& frame();

/// The local unit direction at polar angle theta and azimuth phi (degrees).
Vec3 direction(double thetaDegrees, double phiDegrees);
/// A local geometric normal 20 degrees from the shading normal (+z), as the
/// interpolated normals of a smooth-shaded mesh bend one from the other.
Vec3 bentGeometricNormal();
/// A shade point in the probe's default frame (N = +z, dPdu = +x) seen from (theta, phi).
ProbePoint viewFrom(double thetaDegrees, double phiDegrees = 0.0);
/// "theta 35 deg, phi 200 deg" for a local direction.
std::string describeDirection(Vec3 const& local);
std::string describe(RtColorRGB const& c);
std::string number(double v);

/// |a - b| within `relative` of the larger, or within `absolute`.
bool close(double a, double b, double relative, double absolute = 1e-6);

/// Fails when the plugin gives back nothing at all (no light, no valid
/// sample, no emission): every property would then hold trivially.
/// Returns an empty string when the plugin answers, else the message.
std::string notAttempted(CheckContext& context);

/// The density of a sampling mapping xi -> w at one xi, from finite
/// differences (Lajolla's check): 1 / |dw/du x dw/dv|. The mapping is asked
/// at xi + each of jacobianOffsets(); central differences at halving steps
/// are combined by Richardson extrapolation at the pair of steps that agree
/// best (too large a step meets the mapping's curvature, too small one its
/// float rounding). Returns false where no pair agrees within 5% -- a fold,
/// seam or kink of the mapping, where finite differences say nothing.
std::vector<RtFloat2> const& jacobianOffsets();
bool jacobianDensity(Vec3 const* directions, double& density);

/// The refractive index on the side of a local direction for a transmitting
/// model: 1 above the surface (outside), ior below it.
inline double indexOfSide(double ior, Vec3 const& local) { return local.z >= 0.0f ? 1.0 : ior; }

/// Joins parameter sets for messages: "with [params]".
std::string withParams(std::string const& params);

}  // namespace bxdflab::checks
