#include "scene/shapes/Sphere.h"

#include <algorithm>
#include <cmath>

#include "scene/shapes/QuadricMath.h"

namespace bxdflab {

using quadric::solveQuadratic;

namespace {

/// The ball a whole sphere of this radius becomes under `toWorld`, when its
/// linear part is a rotation (or a mirror) times a uniform scale. The
/// tolerance keeps the ball within a millionth of the radius of the exact
/// surface, well inside the offset at which a ray leaving the surface starts
/// (four millionths, Quadric::basics' error bound), so that such a ray does
/// not find the sphere it leaves.
std::optional<Vec4> ballOf(Mat4 const& toWorld, float radius) {
    constexpr float kTolerance = 1e-6f;
    Mat3 linear(toWorld);
    float const lengths[3] = {glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])};
    float const scale = (lengths[0] + lengths[1] + lengths[2]) / 3.0f;
    Vec3 const centre(toWorld[3]);
    if (!(scale > 0.0f) || !std::isfinite(scale) || !std::isfinite(centre.x + centre.y + centre.z)) return std::nullopt;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(lengths[i] - scale) > kTolerance * scale) return std::nullopt;
        if (std::abs(glm::dot(linear[i], linear[(i + 1) % 3])) > kTolerance * scale * scale) return std::nullopt;
    }
    return Vec4(centre, radius * scale);
}

}  // namespace

Sphere::Sphere(float radius, float zmin, float zmax, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse)
    : Quadric(toWorld, reverse, thetaMaxDegrees), m_radius(radius) {
    m_zMin = std::clamp(static_cast<double>(std::min(zmin, zmax)), -m_radius, m_radius);
    m_zMax = std::clamp(static_cast<double>(std::max(zmin, zmax)), -m_radius, m_radius);
    m_thetaZMin = std::acos(m_zMin / m_radius);
    m_thetaZMax = std::acos(m_zMax / m_radius);
    m_whole = m_zMin <= -m_radius && m_zMax >= m_radius && phiMax() >= quadric::kTwoPi;
    if (m_whole && m_radius > 0.0) m_placed = ballOf(toWorld, static_cast<float>(m_radius));
}

bool Sphere::hitsLocal(DVec3 const& o, DVec3 const& d, double tnear, double tfar) const {
    // A whole sphere refuses no point of its surface, so a shadow ray needs none
    // of the angles (acos, atan2) that (u, v) cost; the same answer as intersectLocal's.
    if (!m_whole) return Quadric::hitsLocal(o, d, tnear, tfar);
    double t0, t1;
    if (!solveQuadratic(glm::dot(d, d), 2.0 * glm::dot(o, d), glm::dot(o, o) - m_radius * m_radius, t0, t1)) return false;
    return (t0 > tnear && t0 < tfar) || (t1 > tnear && t1 < tfar);
}

std::optional<Quadric::LocalHit> Sphere::intersectLocal(DVec3 const& o, DVec3 const& d, double tnear,
                                                        double tfar) const {
    double t0, t1;
    if (!solveQuadratic(glm::dot(d, d), 2.0 * glm::dot(o, d), glm::dot(o, o) - m_radius * m_radius, t0, t1))
        return std::nullopt;
    return firstRoot(t0, t1, tnear, tfar, [&](double t) -> std::optional<Uv> {
        if (m_whole) return Uv{0.0f, 0.0f};  // parameters() works them out for the hit shaded
        DVec3 p = o + t * d;
        return parametersOf(p * (m_radius / glm::length(p)));  // reprojected onto the surface
    });
}

std::optional<Quadric::Uv> Sphere::parametersOf(DVec3 p) const {
    if (p.x == 0.0 && p.y == 0.0) p.x = 1e-9 * m_radius;
    if ((m_zMin > -m_radius && p.z < m_zMin) || (m_zMax < m_radius && p.z > m_zMax)) return std::nullopt;
    double theta = std::acos(std::clamp(p.z / m_radius, -1.0, 1.0));
    double v = (theta - m_thetaZMin) / (m_thetaZMax - m_thetaZMin);
    return swept(azimuth(p.x, p.y), std::clamp(v, 0.0, 1.0));
}

SurfaceParameters Sphere::parametersUnmoved(HitRecord const& hit) const {
    if (!m_whole) return Quadric::parametersUnmoved(hit);
    Uv uv = parametersOf(pointOnSphere(hit)).value_or(Uv{0.0f, 0.0f});  // (a whole sphere refuses no point)
    return {uv.u, uv.v, uv.u, uv.v};
}

DVec3 Sphere::pointOnSphere(HitRecord const& hit) const {
    DVec3 p = hitPointLocal(hit);
    double length = glm::length(p);
    return length > 0.0 ? p * (m_radius / length) : DVec3(0.0, 0.0, m_radius);
}

Quadric::LocalSurface Sphere::surfaceLocal(float u, float v) const {
    double phi = u * phiMax();
    double theta = m_thetaZMin + v * (m_thetaZMax - m_thetaZMin);
    double sinTheta = std::sin(theta), cosTheta = std::cos(theta);
    double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    return surfaceAt(DVec3(m_radius * sinTheta * cosPhi, m_radius * sinTheta * sinPhi, m_radius * cosTheta), cosPhi,
                     sinPhi);
}

Quadric::LocalSurface Sphere::surfaceAtHit(HitRecord const& hit) const {
    // The hit point put back on the sphere: no trigonometry, and as exact as
    // the point evaluated from (u, v).
    DVec3 p = pointOnSphere(hit);
    double rho = std::sqrt(p.x * p.x + p.y * p.y);
    if (!(rho > 0.0)) {  // a pole: the azimuth is u's
        double phi = parametersUnmoved(hit).u * phiMax();
        return surfaceAt(p, std::cos(phi), std::sin(phi));
    }
    return surfaceAt(p, p.x / rho, p.y / rho);
}

Quadric::LocalSurface Sphere::surfaceAt(DVec3 const& p, double cosPhi, double sinPhi) const {
    double sinTheta = std::sqrt(p.x * p.x + p.y * p.y) / m_radius;
    LocalSurface s;
    s.P = Vec3(p);
    s.N = Vec3(p / m_radius);
    s.dPdu = sweepTangent(p);
    s.dPdv = Vec3((m_thetaZMax - m_thetaZMin) * DVec3(p.z * cosPhi, p.z * sinPhi, -m_radius * sinTheta));
    return s;
}

void Sphere::boundsLocal(Vec3& lower, Vec3& upper) const {
    boundsOfRevolution(m_radius, m_zMin, m_zMax, lower, upper);
}

}  // namespace bxdflab
