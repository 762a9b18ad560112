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
    // Every point is center + a axisX + b axisY with |a|, |b| <= 1.
    m_boundingRadius = glm::length(m_axisX) + glm::length(m_axisY);
}

float PlanarLight::solidAnglePdf(Vec3 const& towardLight, float distance) const {
    float cosLight = -glm::dot(towardLight, m_emitNormal);
    if (cosLight <= 0.0f || m_area <= 0.0f) return 0.0f;
    return distance * distance / (cosLight * m_area);
}

RtColorRGB PlanarLight::emitted(float cosTheta) const {
    if (!m_shaping.shapes()) return color;
    Vec3 const f = m_shaping.factor(cosTheta);
    return RtColorRGB(color.r * f.x, color.g * f.y, color.b * f.z);
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
    if (s.pdf > 0.0f) s.radiance = emitted(-glm::dot(s.wi, m_emitNormal));
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
    radiance = pdf > 0.0f ? emitted(-glm::dot(dir, m_emitNormal)) : RtColorRGB(0.0f);
    return true;
}

// Light subpaths leave a point chosen uniformly over the light, in a
// cosine-weighted direction about its emitting normal (unshaped, the emitted
// radiance is the same in every direction, so this follows the emitted power).
bool PlanarLight::sampleEmission(Vec2 const& xiPosition, Vec2 const& xiDirection, LightEmission& out) const {
    if (color.IsBlack() || !(m_area > 0.0f)) return false;
    Vec2 local = m_shape == Shape::Disk ? concentricDisk(xiPosition) : 2.0f * xiPosition - Vec2(1.0f);
    out.origin = m_center + local.x * m_axisX + local.y * m_axisY;
    out.normal = m_emitNormal;
    out.dir = cosineDirection(m_emitNormal, xiDirection);
    out.radiance = emitted(glm::dot(out.dir, m_emitNormal));
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
    m_area = 4.0f * kPi * m_radius * m_radius;
    m_boundingRadius = m_radius;
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

CylinderLight::CylinderLight(Mat4 const& lightToWorld) {
    m_center = transformPoint(lightToWorld, Vec3(0.0f));
    Vec3 const along = transformVector(lightToWorld, Vec3(1.0f, 0.0f, 0.0f));
    Vec3 const acrossY = transformVector(lightToWorld, Vec3(0.0f, 1.0f, 0.0f));
    Vec3 const acrossZ = transformVector(lightToWorld, Vec3(0.0f, 0.0f, 1.0f));
    m_length = glm::length(along);
    m_radius = 0.25f * (glm::length(acrossY) + glm::length(acrossZ));
    m_axis = safeNormalize(along);
    m_across1 = safeNormalize(acrossY - glm::dot(acrossY, m_axis) * m_axis);
    m_across2 = glm::cross(m_axis, m_across1);
    m_area = 2.0f * kPi * m_radius * m_length;
    m_boundingRadius = std::sqrt(0.25f * m_length * m_length + m_radius * m_radius);
}

Vec3 CylinderLight::pointAt(float s, float phi, Vec3& normal) const {
    normal = std::cos(phi) * m_across1 + std::sin(phi) * m_across2;
    return m_center + s * m_length * m_axis + m_radius * normal;
}

float CylinderLight::solidAnglePdf(Vec3 const& towardLight, float distance, Vec3 const& normal) const {
    float cosLight = -glm::dot(towardLight, normal);
    if (cosLight <= 0.0f || !(m_area > 0.0f)) return 0.0f;  // the inside of the tube does not emit
    return distance * distance / (cosLight * m_area);
}

LightSample CylinderLight::sample(Vec3 const& P, Vec2 const& xi) const {
    Vec3 normal;
    Vec3 const onLight = pointAt(xi.x - 0.5f, 2.0f * kPi * xi.y, normal);
    LightSample s;
    Vec3 const toLight = onLight - P;
    s.distance = glm::length(toLight);
    if (!(s.distance > 0.0f)) return s;
    s.wi = toLight / s.distance;
    s.pdf = solidAnglePdf(s.wi, s.distance, normal);
    if (s.pdf > 0.0f) s.radiance = color;
    return s;
}

bool CylinderLight::intersect(Vec3 const& org, Vec3 const& dir, float& distance, RtColorRGB& radiance,
                              float& pdf) const {
    // In the tube's own orthonormal frame the side is y^2 + z^2 = r^2 for |x| <= length / 2.
    Vec3 const o = org - m_center;
    float const ox = glm::dot(o, m_axis), oy = glm::dot(o, m_across1), oz = glm::dot(o, m_across2);
    float const dx = glm::dot(dir, m_axis), dy = glm::dot(dir, m_across1), dz = glm::dot(dir, m_across2);
    double const a = double(dy) * dy + double(dz) * dz;
    if (a < 1e-24) return false;  // along the axis: never meets the side
    double const halfB = double(oy) * dy + double(oz) * dz;
    double const c = double(oy) * oy + double(oz) * oz - double(m_radius) * m_radius;
    double const discriminant = halfB * halfB - a * c;
    if (discriminant < 0.0) return false;
    double const root = std::sqrt(discriminant);
    for (double t : {(-halfB - root) / a, (-halfB + root) / a}) {
        if (!(t > 0.0) || std::fabs(ox + t * dx) > 0.5 * m_length) continue;
        Vec3 const hit = o + static_cast<float>(t) * dir;
        Vec3 const normal = safeNormalize(hit - glm::dot(hit, m_axis) * m_axis);
        distance = static_cast<float>(t);
        pdf = solidAnglePdf(dir, distance, normal);
        radiance = pdf > 0.0f ? color : RtColorRGB(0.0f);
        return true;
    }
    return false;
}

bool CylinderLight::sampleEmission(Vec2 const& xiPosition, Vec2 const& xiDirection, LightEmission& out) const {
    if (color.IsBlack() || !(m_area > 0.0f)) return false;
    out.origin = pointAt(xiPosition.x - 0.5f, 2.0f * kPi * xiPosition.y, out.normal);
    out.dir = cosineDirection(out.normal, xiDirection);
    out.radiance = color;
    out.pdfArea = 1.0f / m_area;
    out.pdfDir = std::max(0.0f, glm::dot(out.dir, out.normal)) / kPi;
    return out.pdfDir > 0.0f;
}

EmissionDensity CylinderLight::emissionDensity(Vec3 const& point, Vec3 const& dir) const {
    Vec3 const fromCenter = point - m_center;
    Vec3 const normal = safeNormalize(fromCenter - glm::dot(fromCenter, m_axis) * m_axis);
    float const cosine = glm::dot(dir, normal);
    return {1.0f / m_area, std::max(0.0f, cosine) / kPi, std::fabs(cosine)};
}

}  // namespace bxdflab
