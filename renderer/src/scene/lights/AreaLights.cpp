#include "scene/lights/AreaLights.h"

#include <cmath>

namespace bxdflab {

PlanarLight::PlanarLight(Shape shape, Mat4 const& lightToWorld) : m_shape(shape) {
    m_center = transformPoint(lightToWorld, Vec3(0.0f));
    m_axisX = transformVector(lightToWorld, Vec3(0.5f, 0.0f, 0.0f));
    m_axisY = transformVector(lightToWorld, Vec3(0.0f, 0.5f, 0.0f));
    m_emitNormal = safeNormalize(transformNormal(glm::inverse(lightToWorld), Vec3(0.0f, 0.0f, 1.0f)));
    m_planeNormal = safeNormalize(glm::cross(m_axisX, m_axisY));
    float parallelogram = glm::length(glm::cross(m_axisX, m_axisY));
    m_area = shape == Shape::Disk ? kPi * parallelogram : 4.0f * parallelogram;
}

float PlanarLight::solidAnglePdf(Vec3 const& towardLight, float distance) const {
    float cosLight = -glm::dot(towardLight, m_emitNormal);
    if (cosLight <= 0.0f || m_area <= 0.0f) return 0.0f;
    return distance * distance / (cosLight * m_area);
}

LightSample PlanarLight::sample(Vec3 const& P, Vec2 const& xi) const {
    Vec2 local = m_shape == Shape::Disk ? concentricDisk(xi) : 2.0f * xi - Vec2(1.0f);
    Vec3 onLight = m_center + local.x * m_axisX + local.y * m_axisY;
    LightSample s;
    Vec3 toLight = onLight - P;
    s.distance = glm::length(toLight);
    if (!(s.distance > 0.0f)) return s;
    s.wi = toLight / s.distance;
    s.pdf = solidAnglePdf(s.wi, s.distance);
    if (s.pdf > 0.0f) s.radiance = color;
    return s;
}

bool PlanarLight::intersect(Vec3 const& org, Vec3 const& dir, float& distance, RtColorRGB& radiance,
                            float& pdf) const {
    float denom = glm::dot(dir, m_planeNormal);
    if (std::fabs(denom) < 1e-12f) return false;
    float t = glm::dot(m_center - org, m_planeNormal) / denom;
    if (!(t > 0.0f)) return false;
    Vec3 q = org + t * dir - m_center;
    float a = glm::dot(q, m_axisX) / glm::dot(m_axisX, m_axisX);
    float b = glm::dot(q, m_axisY) / glm::dot(m_axisY, m_axisY);
    bool inside = m_shape == Shape::Disk ? a * a + b * b <= 1.0f : std::fabs(a) <= 1.0f && std::fabs(b) <= 1.0f;
    if (!inside) return false;
    distance = t;
    pdf = solidAnglePdf(dir, t);
    radiance = pdf > 0.0f ? color : RtColorRGB(0.0f);
    return true;
}

// Light subpaths leave a point chosen uniformly over the light, in a
// cosine-weighted direction about its emitting normal (the emitted radiance
// is the same in every direction, so this follows the emitted power).
bool PlanarLight::sampleEmission(Vec2 const& xiPosition, Vec2 const& xiDirection, LightEmission& out) const {
    if (color.IsBlack() || !(m_area > 0.0f)) return false;
    Vec2 local = m_shape == Shape::Disk ? concentricDisk(xiPosition) : 2.0f * xiPosition - Vec2(1.0f);
    out.origin = m_center + local.x * m_axisX + local.y * m_axisY;
    out.normal = m_emitNormal;
    out.dir = cosineDirection(m_emitNormal, xiDirection);
    out.radiance = color;
    out.pdfArea = 1.0f / m_area;
    out.pdfDir = std::max(0.0f, glm::dot(out.dir, m_emitNormal)) / kPi;
    return out.pdfDir > 0.0f;
}

EmissionDensity PlanarLight::emissionDensity(Vec3 const&, Vec3 const& dir) const {
    float cosine = glm::dot(dir, m_emitNormal);
    return {1.0f / m_area, std::max(0.0f, cosine) / kPi, std::fabs(cosine)};
}

SphereLight::SphereLight(Mat4 const& lightToWorld) {
    m_center = transformPoint(lightToWorld, Vec3(0.0f));
    // A sphere light stays a sphere: non-uniform scales are averaged.
    m_radius = 0.5f * std::cbrt(std::fabs(glm::determinant(Mat3(lightToWorld))));
}

float SphereLight::coneOneMinusCos(Vec3 const& P) const {
    Vec3 toCenter = m_center - P;
    float distSq = glm::dot(toCenter, toCenter);
    float sin2Max = m_radius * m_radius / distSq;
    if (!(sin2Max < 1.0f)) return 0.0f;
    float cosMax = std::sqrt(1.0f - sin2Max);
    return sin2Max / (1.0f + cosMax);  // = 1 - cosMax without cancellation
}

LightSample SphereLight::sample(Vec3 const& P, Vec2 const& xi) const {
    LightSample s;
    float oneMinusCos = coneOneMinusCos(P);
    if (oneMinusCos <= 0.0f) return s;  // inside the light: it emits outward only
    Vec3 toCenter = m_center - P;
    float dist = glm::length(toCenter);
    Vec3 axis = toCenter / dist, b1, b2;
    orthonormalBasis(axis, b1, b2);
    float cosTheta = 1.0f - xi.x * oneMinusCos;
    float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = 2.0f * kPi * xi.y;
    s.wi = sinTheta * std::cos(phi) * b1 + sinTheta * std::sin(phi) * b2 + cosTheta * axis;
    // Nearest intersection along wi; clamp for rays that graze the silhouette.
    float perpendicularSq = dist * dist * sinTheta * sinTheta;
    s.distance = dist * cosTheta - std::sqrt(std::max(0.0f, m_radius * m_radius - perpendicularSq));
    s.pdf = 1.0f / (2.0f * kPi * oneMinusCos);
    s.radiance = color;
    return s;
}

bool SphereLight::intersect(Vec3 const& org, Vec3 const& dir, float& distance, RtColorRGB& radiance,
                            float& pdf) const {
    Vec3 oc = org - m_center;
    float b = glm::dot(oc, dir);
    float c = glm::dot(oc, oc) - m_radius * m_radius;
    float discriminant = b * b - c;
    if (discriminant < 0.0f || c <= 0.0f) return false;  // miss, or starting inside
    float t = -b - std::sqrt(discriminant);
    if (!(t > 0.0f)) return false;
    float oneMinusCos = coneOneMinusCos(org);
    if (oneMinusCos <= 0.0f) return false;
    distance = t;
    radiance = color;
    pdf = 1.0f / (2.0f * kPi * oneMinusCos);
    return true;
}

bool SphereLight::sampleEmission(Vec2 const& xiPosition, Vec2 const& xiDirection, LightEmission& out) const {
    if (color.IsBlack() || !(m_radius > 0.0f)) return false;
    out.normal = uniformConeDirection(Vec3(0.0f, 0.0f, 1.0f), -1.0f, xiPosition);
    out.origin = m_center + m_radius * out.normal;
    out.dir = cosineDirection(out.normal, xiDirection);
    out.radiance = color;
    out.pdfArea = 1.0f / (4.0f * kPi * m_radius * m_radius);
    out.pdfDir = std::max(0.0f, glm::dot(out.dir, out.normal)) / kPi;
    return out.pdfDir > 0.0f;
}

EmissionDensity SphereLight::emissionDensity(Vec3 const& point, Vec3 const& dir) const {
    float cosine = glm::dot(dir, safeNormalize(point - m_center));
    return {1.0f / (4.0f * kPi * m_radius * m_radius), std::max(0.0f, cosine) / kPi, std::fabs(cosine)};
}

}  // namespace bxdflab
