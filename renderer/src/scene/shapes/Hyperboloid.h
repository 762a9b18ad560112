// Hyperboloid point1 point2 thetamax: the line from point1 to point2 swept about z.
#pragma once

#include "scene/shapes/Quadric.h"

namespace bxdflab {

/// Hyperboloid point1 point2 thetamax: the line from point1 to point2 swept
/// about the z axis; with both points at one height, a flat ring.
class Hyperboloid final : public Quadric {
public:
    Hyperboloid(Vec3 const& p1, Vec3 const& p2, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse);
    const char* kind() const override { return "Hyperboloid"; }
    std::optional<LocalHit> intersectLocal(DVec3 const& org, DVec3 const& dir, double tnear, double tfar) const override;
    LocalSurface surfaceLocal(float u, float v) const override;
    void boundsLocal(Vec3& lower, Vec3& upper) const override;

private:
    /// The flat ring's intersection; A, B, C give the line's squared distance from the axis.
    std::optional<LocalHit> intersectFlat(DVec3 const& o, DVec3 const& d, double tnear, double tfar, double A, double B,
                                          double C) const;
    DVec3 m_p1, m_p2;
};

}  // namespace bxdflab
