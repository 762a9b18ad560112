// Sphere radius zmin zmax thetamax: the part of a sphere about the origin
// between two heights, swept thetamax degrees about z.
#pragma once

#include <optional>

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
    /// A whole sphere's from the hit point (its hits carry none); a cut one's from the hit.
    SurfaceParameters parametersUnmoved(HitRecord const& hit) const override;
    std::optional<Vec4> placedSphere() const override { return m_placed; }

private:
    /// The hit point put back on the sphere, in object space.
    DVec3 pointOnSphere(HitRecord const& hit) const;
    /// (u, v) of a point on the sphere, or nothing where it lies outside the
    /// heights or the sweep.
    std::optional<Uv> parametersOf(DVec3 p) const;
    /// The surface at object-space point p on the sphere, where p's azimuth is
    /// given by (cosPhi, sinPhi).
    LocalSurface surfaceAt(DVec3 const& p, double cosPhi, double sinPhi) const;
    double m_radius, m_zMin, m_zMax, m_thetaZMin, m_thetaZMax;
    /// Every height and the full sweep: any root in range is a hit, and a hit's
    /// (u, v) are worked out from its point only when shading asks.
    bool m_whole;
    std::optional<Vec4> m_placed;  ///< see placedSphere
};

}  // namespace bxdflab
