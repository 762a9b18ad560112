#include "scene/lights/PointLights.h"

#include <algorithm>
#include <cmath>

namespace bxdflab {

PointLight::PointLight(Vec3 const& position, Vec3 const& axis, float coneAngle, float coneDeltaAngle, float beamDistribution)
    : m_position(position), m_spot(true), m_axis(safeNormalize(axis)), m_beam(beamDistribution) {
    m_cosOutside = std::cos(coneAngle);
    m_cosInside = std::cos(std::max(0.0f, coneAngle - coneDeltaAngle));
}

float PointLight::falloff(Vec3 const& dir) const {
    if (!m_spot) return 1.0f;
    // The spotlight shader: cos^beam times a smooth step across the cone's edge.
    float cosAngle = glm::dot(dir, m_axis);
    if (cosAngle <= m_cosOutside) return 0.0f;
    float t = m_cosInside > m_cosOutside ? std::clamp((cosAngle - m_cosOutside) / (m_cosInside - m_cosOutside), 0.0f, 1.0f)
                                         : 1.0f;
    return std::pow(std::max(cosAngle, 0.0f), m_beam) * t * t * (3.0f - 2.0f * t);
}

LightSample PointLight::sample(Vec3 const& P, Vec2 const&) const {
    LightSample s;
    Vec3 toLight = m_position - P;
    float distSq = glm::dot(toLight, toLight);
    if (!(distSq > 0.0f)) return s;
    s.distance = std::sqrt(distSq);
    s.wi = toLight / s.distance;
    s.pdf = 1.0f;
    s.delta = true;
    // How much of the light's intensity arrives over this distance.
    float const distanceAttenuation = m_inverseSquare ? 1.0f / distSq
                                      : s.distance > m_falloffReference
                                          ? std::pow(m_falloffReference / s.distance, m_falloffPower)
                                          : 1.0f;
    s.radiance = color * (distanceAttenuation * falloff(-s.wi));
    return s;
}

// Light subpaths leave uniformly in every direction a point light can send
// light: the whole sphere, or a spotlight's cone.
bool PointLight::sampleEmission(Vec2 const&, Vec2 const& xiDirection, LightEmission& out) const {
    if (color.IsBlack()) return false;
    float cosMax = m_spot ? m_cosOutside : -1.0f;
    out.origin = m_position;
    out.normal = Vec3(0.0f);
    out.dir = uniformConeDirection(m_axis, cosMax, xiDirection);
    out.radiance = color * falloff(out.dir);
    out.pdfArea = 1.0f;
    out.pdfDir = 1.0f / (2.0f * kPi * (1.0f - cosMax));
    return !out.radiance.IsBlack();
}

EmissionDensity PointLight::emissionDensity(Vec3 const&, Vec3 const& dir) const {
    float cosMax = m_spot ? m_cosOutside : -1.0f;
    bool inside = !m_spot || glm::dot(dir, m_axis) > cosMax;
    return {1.0f, inside ? 1.0f / (2.0f * kPi * (1.0f - cosMax)) : 0.0f, 1.0f};
}

}  // namespace bxdflab
