// Sphere radius zmin zmax thetamax: the part of a sphere about the origin
// between two heights, swept thetamax degrees about z.
#pragma once

#include "scene/shapes/Quadric.h"

namespace bxdflab {

class Sphere final : public Quadric {
public:
    Sphere(float radius, float zmin, float zmax, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse);
    const char* kind() const override { return "Sphere"; }
    std::optional<LocalHit> intersectLocal(DVec3 const& org, DVec3 const& dir, double tnear, double tfar) const override;
    bool hitsLocal(DVec3 const& org, DVec3 const& dir, double tnear, double tfar) const override;
    LocalSurface surfaceLocal(float u, float v) const override;
    LocalSurface surfaceAtHit(HitRecord const& hit) const override;
    void boundsLocal(Vec3& lower, Vec3& upper) const override;

private:
    /// The surface at object-space point p on the sphere, where p's azimuth is
    /// given by (cosPhi, sinPhi).
    LocalSurface surfaceAt(DVec3 const& p, double cosPhi, double sinPhi) const;
    double m_radius, m_zMin, m_zMax, m_thetaZMin, m_thetaZMax;
    bool m_whole;  ///< every height and the full sweep: any root in range is a hit
};

}  // namespace bxdflab
