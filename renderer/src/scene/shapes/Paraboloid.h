// Paraboloid rmax zmin zmax thetamax: the paraboloid x^2 + y^2 = rmax^2 z / zmax.
#pragma once

#include "scene/shapes/Quadric.h"

namespace bxdflab {

/// Paraboloid rmax zmin zmax thetamax: x^2 + y^2 = rmax^2 z / zmax.
class Paraboloid final : public Quadric {
public:
    Paraboloid(float rmax, float zmin, float zmax, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse);
    const char* kind() const override { return "Paraboloid"; }
    std::optional<LocalHit> intersectLocal(DVec3 const& org, DVec3 const& dir, double tnear, double tfar) const override;
    LocalSurface surfaceLocal(float u, float v) const override;
    void boundsLocal(Vec3& lower, Vec3& upper) const override;

private:
    double m_rmax, m_zMin, m_zMax;
};

}  // namespace bxdflab
