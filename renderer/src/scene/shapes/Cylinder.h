// Cylinder radius zmin zmax thetamax: an open cylinder about the z axis.
#pragma once

#include "scene/shapes/Quadric.h"

namespace bxdflab {

class Cylinder final : public Quadric {
public:
    Cylinder(float radius, float zmin, float zmax, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse);
    const char* kind() const override { return "Cylinder"; }
    std::optional<LocalHit> intersectLocal(DVec3 const& org, DVec3 const& dir, double tnear, double tfar) const override;
    LocalSurface surfaceLocal(float u, float v) const override;
    void boundsLocal(Vec3& lower, Vec3& upper) const override;

private:
    double m_radius, m_zMin, m_zMax;
};

}  // namespace bxdflab
