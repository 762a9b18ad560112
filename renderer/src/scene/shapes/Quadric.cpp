#include "scene/shapes/Quadric.h"

#include <algorithm>
#include <cmath>

namespace bxdflab {
namespace {

constexpr double kTwoPi = 6.283185307179586;

// Embree callbacks: the geometry's user pointer is the Quadric.
void quadricBounds(const RTCBoundsFunctionArguments* args) {
    auto const* quadric = static_cast<Quadric const*>(args->geometryUserPtr);
    Vec3 lo, hi;
    quadric->boundsLocal(lo, hi);
    Vec3 worldLo(kInfinity), worldHi(-kInfinity);
    for (int corner = 0; corner < 8; ++corner) {
        Vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
        Vec3 w = transformPoint(quadric->objectToWorld(), p);
        worldLo = glm::min(worldLo, w);
        worldHi = glm::max(worldHi, w);
    }
    // Pad by a relative epsilon so rays grazing the box are not lost.
    Vec3 pad = 1e-5f * (glm::abs(worldLo) + glm::abs(worldHi)) + Vec3(1e-6f);
    worldLo -= pad;
    worldHi += pad;
    args->bounds_o->lower_x = worldLo.x;
    args->bounds_o->lower_y = worldLo.y;
    args->bounds_o->lower_z = worldLo.z;
    args->bounds_o->upper_x = worldHi.x;
    args->bounds_o->upper_y = worldHi.y;
    args->bounds_o->upper_z = worldHi.z;
}

struct LocalRay {
    DVec3 org, dir;
};

LocalRay toObjectSpace(Mat4 const& worldToObject, RTCRayN* ray, unsigned n, unsigned i) {
    glm::dmat4 m(worldToObject);
    DVec3 org(RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i));
    DVec3 dir(RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i));
    return {DVec3(m * glm::dvec4(org, 1.0)), glm::dmat3(m) * dir};
}

void quadricIntersect(const RTCIntersectFunctionNArguments* args) {
    auto const* quadric = static_cast<Quadric const*>(args->geometryUserPtr);
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    Mat4 const& worldToObject = quadric->worldToObject();
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        LocalRay local = toObjectSpace(worldToObject, ray, args->N, i);
        auto found = quadric->intersectLocal(local.org, local.dir, RTCRayN_tnear(ray, args->N, i),
                                             RTCRayN_tfar(ray, args->N, i));
        if (!found) continue;
        RTCRayN_tfar(ray, args->N, i) = static_cast<float>(found->t);
        RTCHitN_Ng_x(hit, args->N, i) = 0.0f;  // the shading context recomputes normals
        RTCHitN_Ng_y(hit, args->N, i) = 0.0f;
        RTCHitN_Ng_z(hit, args->N, i) = 1.0f;
        RTCHitN_u(hit, args->N, i) = found->u;
        RTCHitN_v(hit, args->N, i) = found->v;
        RTCHitN_primID(hit, args->N, i) = args->primID;
        RTCHitN_geomID(hit, args->N, i) = args->geomID;
        RTCHitN_instID(hit, args->N, i, 0) = args->context->instID[0];
    }
}

void quadricOccluded(const RTCOccludedFunctionNArguments* args) {
    auto const* quadric = static_cast<Quadric const*>(args->geometryUserPtr);
    Mat4 const& worldToObject = quadric->worldToObject();
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        LocalRay local = toObjectSpace(worldToObject, args->ray, args->N, i);
        if (quadric->intersectLocal(local.org, local.dir, RTCRayN_tnear(args->ray, args->N, i),
                                    RTCRayN_tfar(args->ray, args->N, i)))
            RTCRayN_tfar(args->ray, args->N, i) = -kInfinity;
    }
}

/// Both roots of a t^2 + b t + c = 0 in increasing order, computed without
/// cancellation (the "citardauq" form); false when there is no real root.
bool solveQuadratic(double a, double b, double c, double& t0, double& t1) {
    if (a == 0.0) {
        if (b == 0.0) return false;
        t0 = t1 = -c / b;
        return true;
    }
    double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return false;
    double root = std::sqrt(discriminant);
    double q = b < 0.0 ? -0.5 * (b - root) : -0.5 * (b + root);
    t0 = q / a;
    t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

double sweepRadians(float degrees) { return std::clamp(static_cast<double>(degrees), 0.0, 360.0) * kTwoPi / 360.0; }

}  // namespace

Quadric::Quadric(Mat4 const& objectToWorld, bool reverseOrientation)
    : m_objectToWorld(objectToWorld),
      m_worldToObject(glm::inverse(objectToWorld)),
      m_orientation(reverseOrientation ? -1.0f : 1.0f) {}

double Quadric::azimuth(double x, double y) {
    double phi = std::atan2(y, x);
    return phi < 0.0 ? phi + kTwoPi : phi;
}

RTCGeometry Quadric::build(RTCDevice device) const {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, 1);
    rtcSetGeometryUserData(geometry, const_cast<Quadric*>(this));
    rtcSetGeometryBoundsFunction(geometry, quadricBounds, nullptr);
    rtcSetGeometryIntersectFunction(geometry, quadricIntersect);
    rtcSetGeometryOccludedFunction(geometry, quadricOccluded);
    rtcCommitGeometry(geometry);
    return geometry;
}

SurfaceBasics Quadric::basics(HitRecord const& hit) const {
    LocalSurface local = surfaceLocal(hit.u, hit.v);
    SurfaceBasics out;
    out.P = transformPoint(m_objectToWorld, local.P);
    out.Ng = m_orientation * safeNormalize(transformNormal(m_worldToObject, local.N));
    out.N = out.Ng;
    // P is evaluated from (u, v) on the exact surface; its error is a few ulps
    // of the magnitudes involved in the transform. Bound it generously.
    Mat3 linear(m_objectToWorld);
    Mat3 absolute(glm::abs(linear[0]), glm::abs(linear[1]), glm::abs(linear[2]));
    Vec3 magnitude = absolute * glm::abs(local.P) + glm::abs(Vec3(m_objectToWorld[3]));
    out.pError = 4e-6f * magnitude + Vec3(1e-7f);
    out.u = hit.u;
    out.v = hit.v;
    out.s = hit.u;
    out.t = hit.v;
    return out;
}

SurfaceTangents Quadric::tangents(HitRecord const& hit) const {
    LocalSurface local = surfaceLocal(hit.u, hit.v);
    return {transformVector(m_objectToWorld, local.dPdu), transformVector(m_objectToWorld, local.dPdv)};
}

// ---------------------------------------------------------------- Sphere

Sphere::Sphere(float radius, float zmin, float zmax, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse)
    : Quadric(toWorld, reverse), m_radius(radius), m_phiMax(sweepRadians(thetaMaxDegrees)) {
    m_zMin = std::clamp(static_cast<double>(std::min(zmin, zmax)), -m_radius, m_radius);
    m_zMax = std::clamp(static_cast<double>(std::max(zmin, zmax)), -m_radius, m_radius);
    m_thetaZMin = std::acos(m_zMin / m_radius);
    m_thetaZMax = std::acos(m_zMax / m_radius);
}

std::optional<Quadric::LocalHit> Sphere::intersectLocal(DVec3 const& o, DVec3 const& d, double tnear,
                                                        double tfar) const {
    double t0, t1;
    if (!solveQuadratic(glm::dot(d, d), 2.0 * glm::dot(o, d), glm::dot(o, o) - m_radius * m_radius, t0, t1))
        return std::nullopt;
    for (double t : {t0, t1}) {
        if (t <= tnear || t >= tfar) continue;
        DVec3 p = o + t * d;
        p *= m_radius / glm::length(p);  // reproject onto the surface
        if (p.x == 0.0 && p.y == 0.0) p.x = 1e-9 * m_radius;
        double phi = azimuth(p.x, p.y);
        if ((m_zMin > -m_radius && p.z < m_zMin) || (m_zMax < m_radius && p.z > m_zMax) || phi > m_phiMax)
            continue;
        double theta = std::acos(std::clamp(p.z / m_radius, -1.0, 1.0));
        double v = (theta - m_thetaZMin) / (m_thetaZMax - m_thetaZMin);
        return LocalHit{t, static_cast<float>(phi / m_phiMax), static_cast<float>(std::clamp(v, 0.0, 1.0))};
    }
    return std::nullopt;
}

Quadric::LocalSurface Sphere::surfaceLocal(float u, float v) const {
    double phi = u * m_phiMax;
    double deltaTheta = m_thetaZMax - m_thetaZMin;
    double theta = m_thetaZMin + v * deltaTheta;
    double sinTheta = std::sin(theta), cosTheta = std::cos(theta);
    double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    DVec3 p(m_radius * sinTheta * cosPhi, m_radius * sinTheta * sinPhi, m_radius * cosTheta);
    LocalSurface s;
    s.P = Vec3(p);
    s.N = Vec3(p / m_radius);
    s.dPdu = Vec3(-m_phiMax * p.y, m_phiMax * p.x, 0.0);
    s.dPdv = Vec3(deltaTheta * DVec3(p.z * cosPhi, p.z * sinPhi, -m_radius * sinTheta));
    return s;
}

void Sphere::boundsLocal(Vec3& lower, Vec3& upper) const {
    float r = static_cast<float>(m_radius);
    lower = Vec3(-r, -r, static_cast<float>(m_zMin));
    upper = Vec3(r, r, static_cast<float>(m_zMax));
}

// ---------------------------------------------------------------- Cylinder

Cylinder::Cylinder(float radius, float zmin, float zmax, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse)
    : Quadric(toWorld, reverse),
      m_radius(radius),
      m_zMin(std::min(zmin, zmax)),
      m_zMax(std::max(zmin, zmax)),
      m_phiMax(sweepRadians(thetaMaxDegrees)) {}

std::optional<Quadric::LocalHit> Cylinder::intersectLocal(DVec3 const& o, DVec3 const& d, double tnear,
                                                          double tfar) const {
    double a = d.x * d.x + d.y * d.y;
    if (a == 0.0) return std::nullopt;
    double t0, t1;
    if (!solveQuadratic(a, 2.0 * (o.x * d.x + o.y * d.y), o.x * o.x + o.y * o.y - m_radius * m_radius, t0, t1))
        return std::nullopt;
    for (double t : {t0, t1}) {
        if (t <= tnear || t >= tfar) continue;
        DVec3 p = o + t * d;
        double phi = azimuth(p.x, p.y);
        if (p.z < m_zMin || p.z > m_zMax || phi > m_phiMax) continue;
        double height = m_zMax - m_zMin;
        double v = height > 0.0 ? (p.z - m_zMin) / height : 0.0;
        return LocalHit{t, static_cast<float>(phi / m_phiMax), static_cast<float>(v)};
    }
    return std::nullopt;
}

Quadric::LocalSurface Cylinder::surfaceLocal(float u, float v) const {
    double phi = u * m_phiMax;
    double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    DVec3 p(m_radius * cosPhi, m_radius * sinPhi, m_zMin + v * (m_zMax - m_zMin));
    LocalSurface s;
    s.P = Vec3(p);
    s.N = Vec3(static_cast<float>(cosPhi), static_cast<float>(sinPhi), 0.0f);
    s.dPdu = Vec3(-m_phiMax * p.y, m_phiMax * p.x, 0.0);
    s.dPdv = Vec3(0.0f, 0.0f, static_cast<float>(m_zMax - m_zMin));
    return s;
}

void Cylinder::boundsLocal(Vec3& lower, Vec3& upper) const {
    float r = static_cast<float>(m_radius);
    lower = Vec3(-r, -r, static_cast<float>(m_zMin));
    upper = Vec3(r, r, static_cast<float>(m_zMax));
}

// ---------------------------------------------------------------- Disk

Disk::Disk(float height, float radius, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse)
    : Quadric(toWorld, reverse), m_height(height), m_radius(radius), m_phiMax(sweepRadians(thetaMaxDegrees)) {}

std::optional<Quadric::LocalHit> Disk::intersectLocal(DVec3 const& o, DVec3 const& d, double tnear,
                                                      double tfar) const {
    if (d.z == 0.0) return std::nullopt;
    double t = (m_height - o.z) / d.z;
    if (t <= tnear || t >= tfar) return std::nullopt;
    DVec3 p = o + t * d;
    double distSq = p.x * p.x + p.y * p.y;
    if (distSq > m_radius * m_radius) return std::nullopt;
    double phi = azimuth(p.x, p.y);
    if (phi > m_phiMax) return std::nullopt;
    double v = 1.0 - std::sqrt(distSq) / m_radius;
    return LocalHit{t, static_cast<float>(phi / m_phiMax), static_cast<float>(v)};
}

Quadric::LocalSurface Disk::surfaceLocal(float u, float v) const {
    double phi = u * m_phiMax;
    double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    double rho = m_radius * (1.0 - v);
    DVec3 p(rho * cosPhi, rho * sinPhi, m_height);
    LocalSurface s;
    s.P = Vec3(p);
    s.N = Vec3(0.0f, 0.0f, 1.0f);
    s.dPdu = Vec3(-m_phiMax * p.y, m_phiMax * p.x, 0.0);
    s.dPdv = Vec3(-m_radius * cosPhi, -m_radius * sinPhi, 0.0);
    return s;
}

void Disk::boundsLocal(Vec3& lower, Vec3& upper) const {
    float r = static_cast<float>(m_radius), h = static_cast<float>(m_height);
    lower = Vec3(-r, -r, h);
    upper = Vec3(r, r, h);
}

// ---------------------------------------------------------------- Cone

Cone::Cone(float height, float radius, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse)
    : Quadric(toWorld, reverse), m_height(height), m_radius(radius), m_phiMax(sweepRadians(thetaMaxDegrees)) {}

std::optional<Quadric::LocalHit> Cone::intersectLocal(DVec3 const& o, DVec3 const& d, double tnear, double tfar) const {
    // x^2 + y^2 = (r (1 - z/h))^2
    double k = (m_radius / m_height) * (m_radius / m_height);
    double a = d.x * d.x + d.y * d.y - k * d.z * d.z;
    double b = 2.0 * (o.x * d.x + o.y * d.y - k * d.z * (o.z - m_height));
    double c = o.x * o.x + o.y * o.y - k * (o.z - m_height) * (o.z - m_height);
    double t0, t1;
    if (!solveQuadratic(a, b, c, t0, t1)) return std::nullopt;
    for (double t : {t0, t1}) {
        if (t <= tnear || t >= tfar) continue;
        DVec3 p = o + t * d;
        double v = p.z / m_height;
        double phi = azimuth(p.x, p.y);
        if (v < 0.0 || v > 1.0 || phi > m_phiMax) continue;
        return LocalHit{t, static_cast<float>(phi / m_phiMax), static_cast<float>(v)};
    }
    return std::nullopt;
}

Quadric::LocalSurface Cone::surfaceLocal(float u, float v) const {
    double phi = u * m_phiMax, cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    double rho = m_radius * (1.0 - v);
    DVec3 p(rho * cosPhi, rho * sinPhi, v * m_height);
    LocalSurface s;
    s.P = Vec3(p);
    s.dPdu = Vec3(-m_phiMax * p.y, m_phiMax * p.x, 0.0);
    s.dPdv = Vec3(DVec3(-m_radius * cosPhi, -m_radius * sinPhi, m_height));
    // The outward normal does not depend on v (so it is defined at the apex too).
    s.N = safeNormalize(Vec3(DVec3(m_height * cosPhi, m_height * sinPhi, m_radius)));
    return s;
}

void Cone::boundsLocal(Vec3& lower, Vec3& upper) const {
    float r = static_cast<float>(m_radius), h = static_cast<float>(m_height);
    lower = Vec3(-r, -r, std::min(0.0f, h));
    upper = Vec3(r, r, std::max(0.0f, h));
}

// ---------------------------------------------------------------- Paraboloid

Paraboloid::Paraboloid(float rmax, float zmin, float zmax, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse)
    : Quadric(toWorld, reverse),
      m_rmax(rmax),
      m_zMin(std::min(zmin, zmax)),
      m_zMax(std::max(zmin, zmax)),
      m_phiMax(sweepRadians(thetaMaxDegrees)) {}

std::optional<Quadric::LocalHit> Paraboloid::intersectLocal(DVec3 const& o, DVec3 const& d, double tnear,
                                                            double tfar) const {
    double k = m_zMax / (m_rmax * m_rmax);  // k (x^2 + y^2) = z
    double t0, t1;
    if (!solveQuadratic(k * (d.x * d.x + d.y * d.y), 2.0 * k * (o.x * d.x + o.y * d.y) - d.z,
                        k * (o.x * o.x + o.y * o.y) - o.z, t0, t1))
        return std::nullopt;
    for (double t : {t0, t1}) {
        if (t <= tnear || t >= tfar) continue;
        DVec3 p = o + t * d;
        double phi = azimuth(p.x, p.y);
        if (p.z < m_zMin || p.z > m_zMax || phi > m_phiMax) continue;
        double height = m_zMax - m_zMin;
        return LocalHit{t, static_cast<float>(phi / m_phiMax), static_cast<float>(height > 0 ? (p.z - m_zMin) / height : 0)};
    }
    return std::nullopt;
}

Quadric::LocalSurface Paraboloid::surfaceLocal(float u, float v) const {
    double phi = u * m_phiMax, cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    double z = m_zMin + v * (m_zMax - m_zMin);
    double rho = m_rmax * std::sqrt(std::max(0.0, z / m_zMax));
    DVec3 p(rho * cosPhi, rho * sinPhi, z);
    LocalSurface s;
    s.P = Vec3(p);
    s.dPdu = Vec3(-m_phiMax * p.y, m_phiMax * p.x, 0.0);
    // d rho / dz = rho / (2 z); at the tip (z = 0) the tangent is horizontal.
    double slope = z > 1e-12 ? 0.5 / z : 0.0;
    s.dPdv = Vec3((m_zMax - m_zMin) * DVec3(p.x * slope, p.y * slope, 1.0));
    // Outward normal of k rho^2 - z = 0: (2 k x, 2 k y, -1), flipped to point away from the axis.
    double k = m_zMax / (m_rmax * m_rmax);
    s.N = safeNormalize(Vec3(DVec3(2.0 * k * p.x, 2.0 * k * p.y, -1.0)));
    return s;
}

void Paraboloid::boundsLocal(Vec3& lower, Vec3& upper) const {
    float r = static_cast<float>(m_rmax);
    lower = Vec3(-r, -r, static_cast<float>(m_zMin));
    upper = Vec3(r, r, static_cast<float>(m_zMax));
}

// ---------------------------------------------------------------- Hyperboloid

Hyperboloid::Hyperboloid(Vec3 const& p1, Vec3 const& p2, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse)
    : Quadric(toWorld, reverse), m_p1(p1), m_p2(p2), m_phiMax(sweepRadians(thetaMaxDegrees)) {}

std::optional<Quadric::LocalHit> Hyperboloid::intersectLocal(DVec3 const& o, DVec3 const& d, double tnear,
                                                             double tfar) const {
    // A point at height z lies on the line at v = (z - p1.z) / (p2.z - p1.z), whose
    // squared distance from the axis is r2(v) = A v^2 + B v + C. The ray meets the
    // surface where x(t)^2 + y(t)^2 = r2(v(t)): a quadratic in t.
    DVec3 e = m_p2 - m_p1;
    double A = e.x * e.x + e.y * e.y, B = 2.0 * (m_p1.x * e.x + m_p1.y * e.y), C = m_p1.x * m_p1.x + m_p1.y * m_p1.y;
    double v0 = (o.z - m_p1.z) / e.z, vd = d.z / e.z;
    double a = d.x * d.x + d.y * d.y - A * vd * vd;
    double b = 2.0 * (o.x * d.x + o.y * d.y) - 2.0 * A * v0 * vd - B * vd;
    double c = o.x * o.x + o.y * o.y - A * v0 * v0 - B * v0 - C;
    double t0, t1;
    if (!solveQuadratic(a, b, c, t0, t1)) return std::nullopt;
    for (double t : {t0, t1}) {
        if (t <= tnear || t >= tfar) continue;
        DVec3 p = o + t * d;
        double v = v0 + t * vd;
        if (v < 0.0 || v > 1.0) continue;
        DVec3 line = m_p1 + v * e;
        double phi = azimuth(p.x, p.y) - azimuth(line.x, line.y);
        if (phi < 0.0) phi += kTwoPi;
        if (phi > m_phiMax) continue;
        return LocalHit{t, static_cast<float>(phi / m_phiMax), static_cast<float>(v)};
    }
    return std::nullopt;
}

Quadric::LocalSurface Hyperboloid::surfaceLocal(float u, float v) const {
    double phi = u * m_phiMax, cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    DVec3 line = m_p1 + static_cast<double>(v) * (m_p2 - m_p1);
    DVec3 e = m_p2 - m_p1;
    DVec3 p(line.x * cosPhi - line.y * sinPhi, line.x * sinPhi + line.y * cosPhi, line.z);
    LocalSurface s;
    s.P = Vec3(p);
    s.dPdu = Vec3(-m_phiMax * p.y, m_phiMax * p.x, 0.0);
    s.dPdv = Vec3(DVec3(e.x * cosPhi - e.y * sinPhi, e.x * sinPhi + e.y * cosPhi, e.z));
    Vec3 n = glm::cross(s.dPdu, s.dPdv);
    if (glm::length(n) < 1e-12f) n = Vec3(float(cosPhi), float(sinPhi), 0.0f);  // on the axis
    s.N = safeNormalize(n);
    return s;
}

void Hyperboloid::boundsLocal(Vec3& lower, Vec3& upper) const {
    float r = static_cast<float>(std::max(glm::length(glm::dvec2(m_p1)), glm::length(glm::dvec2(m_p2))));
    lower = Vec3(-r, -r, static_cast<float>(std::min(m_p1.z, m_p2.z)));
    upper = Vec3(r, r, static_cast<float>(std::max(m_p1.z, m_p2.z)));
}

}  // namespace bxdflab
