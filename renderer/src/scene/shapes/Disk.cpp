#include "scene/shapes/Disk.h"

#include <algorithm>
#include <cmath>


namespace bxdflab {

Disk::Disk(float height, float radius, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse)
    : Quadric(toWorld, reverse, thetaMaxDegrees), m_height(height), m_radius(radius) {}

std::optional<Quadric::LocalHit> Disk::intersectLocal(DVec3 const& o, DVec3 const& d, double tnear,
                                                      double tfar) const {
    if (d.z == 0.0) return std::nullopt;
    double t = (m_height - o.z) / d.z;
    if (t <= tnear || t >= tfar) return std::nullopt;
    DVec3 p = o + t * d;
    double distSq = p.x * p.x + p.y * p.y;
    if (distSq > m_radius * m_radius) return std::nullopt;
    std::optional<Uv> uv = swept(azimuth(p.x, p.y), 1.0 - std::sqrt(distSq) / m_radius);
    if (!uv) return std::nullopt;
    return LocalHit{t, uv->u, uv->v};
}

Quadric::LocalSurface Disk::surfaceLocal(float u, float v) const {
    double phi = u * phiMax();
    double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    double rho = m_radius * (1.0 - v);
    DVec3 p(rho * cosPhi, rho * sinPhi, m_height);
    LocalSurface s;
    s.P = Vec3(p);
    s.N = Vec3(0.0f, 0.0f, 1.0f);
    s.dPdu = sweepTangent(p);
    s.dPdv = Vec3(-m_radius * cosPhi, -m_radius * sinPhi, 0.0);
    return s;
}

void Disk::boundsLocal(Vec3& lower, Vec3& upper) const {
    boundsOfRevolution(m_radius, m_height, m_height, lower, upper);
}

}  // namespace bxdflab
