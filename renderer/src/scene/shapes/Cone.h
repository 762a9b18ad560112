// Cone height radius thetamax: an open cone, base circle at z = 0, apex at z = height.
#pragma once

#include "scene/shapes/Quadric.h"

namespace bxdflab {

/// Cone height radius thetamax: apex at z = height, base circle at z = 0.
class Cone final : public Quadric {
public:
    Cone(float height, float radius, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse);
    const char* kind() const override { return "Cone"; }
    std::optional<LocalHit> intersectLocal(DVec3 const& org, DVec3 const& dir, double tnear, double tfar) const override;
    LocalSurface surfaceLocal(float u, float v) const override;
    void boundsLocal(Vec3& lower, Vec3& upper) const override;

private:
    double m_height, m_radius;
};

}  // namespace bxdflab
