#include "scene/shapes/Hyperboloid.h"

#include <algorithm>
#include <cmath>

#include "scene/shapes/QuadricMath.h"

namespace bxdflab {

using quadric::kTwoPi;
using quadric::solveQuadratic;

Hyperboloid::Hyperboloid(Vec3 const& p1, Vec3 const& p2, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse)
    : Quadric(toWorld, reverse, thetaMaxDegrees), m_p1(p1), m_p2(p2) {}

std::optional<Quadric::LocalHit> Hyperboloid::intersectLocal(DVec3 const& o, DVec3 const& d, double tnear,
                                                             double tfar) const {
    // A point at height z lies on the line at v = (z - p1.z) / (p2.z - p1.z), whose
    // squared distance from the axis is r2(v) = A v^2 + B v + C. The ray meets the
    // surface where x(t)^2 + y(t)^2 = r2(v(t)): a quadratic in t.
    DVec3 e = m_p2 - m_p1;
    double A = e.x * e.x + e.y * e.y, B = 2.0 * (m_p1.x * e.x + m_p1.y * e.y), C = m_p1.x * m_p1.x + m_p1.y * m_p1.y;
    if (e.z == 0.0) return intersectFlat(o, d, tnear, tfar, A, B, C);
    double v0 = (o.z - m_p1.z) / e.z, vd = d.z / e.z;
    double a = d.x * d.x + d.y * d.y - A * vd * vd;
    double b = 2.0 * (o.x * d.x + o.y * d.y) - 2.0 * A * v0 * vd - B * vd;
    double c = o.x * o.x + o.y * o.y - A * v0 * v0 - B * v0 - C;
    double t0, t1;
    if (!solveQuadratic(a, b, c, t0, t1)) return std::nullopt;
    return firstRoot(t0, t1, tnear, tfar, [&](double t) -> std::optional<Uv> {
        DVec3 p = o + t * d;
        double v = v0 + t * vd;
        if (v < 0.0 || v > 1.0) return std::nullopt;
        DVec3 line = m_p1 + v * e;
        double phi = azimuth(p.x, p.y) - azimuth(line.x, line.y);  // measured from the line's own azimuth
        if (phi < 0.0) phi += kTwoPi;
        return swept(phi, v);
    });
}

std::optional<Quadric::LocalHit> Hyperboloid::intersectFlat(DVec3 const& o, DVec3 const& d, double tnear, double tfar,
                                                             double A, double B, double C) const {
    // Both points at one height: the swept line is a ring in the plane z = p1.z.
    // The ray meets the plane once; the point is on the ring where its squared
    // distance from the axis is r2(v) = A v^2 + B v + C for some v in [0, 1].
    if (d.z == 0.0 || A == 0.0) return std::nullopt;
    double const t = (m_p1.z - o.z) / d.z;
    return firstRoot(t, t, tnear, tfar, [&](double at) -> std::optional<Uv> {
        DVec3 p = o + at * d;
        double v0, v1;
        if (!solveQuadratic(A, B, C - (p.x * p.x + p.y * p.y), v0, v1)) return std::nullopt;
        for (double v : {v0, v1}) {
            if (v < 0.0 || v > 1.0) continue;
            DVec3 line = m_p1 + v * (m_p2 - m_p1);
            double phi = azimuth(p.x, p.y) - azimuth(line.x, line.y);
            if (phi < 0.0) phi += kTwoPi;
            if (std::optional<Uv> uv = swept(phi, v)) return uv;
        }
        return std::nullopt;
    });
}

Quadric::LocalSurface Hyperboloid::surfaceLocal(float u, float v) const {
    double phi = u * phiMax(), cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    DVec3 line = m_p1 + static_cast<double>(v) * (m_p2 - m_p1);
    DVec3 e = m_p2 - m_p1;
    DVec3 p(line.x * cosPhi - line.y * sinPhi, line.x * sinPhi + line.y * cosPhi, line.z);
    LocalSurface s;
    s.P = Vec3(p);
    s.dPdu = sweepTangent(p);
    s.dPdv = Vec3(DVec3(e.x * cosPhi - e.y * sinPhi, e.x * sinPhi + e.y * cosPhi, e.z));
    Vec3 n = glm::cross(s.dPdu, s.dPdv);
    if (glm::length(n) < 1e-12f)  // on the axis, where the sweep does not move: its direction instead
        n = e.z == 0.0 ? glm::cross(Vec3(float(-sinPhi), float(cosPhi), 0.0f), s.dPdv) : Vec3(float(cosPhi), float(sinPhi), 0.0f);
    s.N = safeNormalize(n);
    return s;
}

void Hyperboloid::boundsLocal(Vec3& lower, Vec3& upper) const {
    boundsOfRevolution(std::max(glm::length(glm::dvec2(m_p1)), glm::length(glm::dvec2(m_p2))), std::min(m_p1.z, m_p2.z),
                       std::max(m_p1.z, m_p2.z), lower, upper);
}

}  // namespace bxdflab
