// Disk height radius thetamax: a flat disk (or sector) at z = height, facing +z.
#pragma once

#include "scene/shapes/Quadric.h"

namespace bxdflab {

class Disk final : public Quadric {
public:
    Disk(float height, float radius, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse);
    const char* kind() const override { return "Disk"; }
    std::optional<LocalHit> intersectLocal(DVec3 const& org, DVec3 const& dir, double tnear, double tfar) const override;
    LocalSurface surfaceLocal(float u, float v) const override;
    void boundsLocal(Vec3& lower, Vec3& upper) const override;

private:
    double m_height, m_radius;
};

}  // namespace bxdflab
