#include "scene/lights/PointLights.h"

#include <algorithm>
#include <cmath>

namespace bxdflab {

PointLight::PointLight(Vec3 const& position, Vec3 const& axis, float coneAngle, float coneDeltaAngle, float beamDistribution)
    : m_position(position), m_spot(true), m_axis(safeNormalize(axis)), m_beam(beamDistribution) {
    m_cosOutside = std::cos(coneAngle);
    m_cosInside = std::cos(std::max(0.0f, coneAngle - coneDeltaAngle));
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
    float falloff = 1.0f / distSq;
    if (m_spot) {
        // The spotlight shader: cos^beam times a smooth step across the cone's edge.
        float cosAngle = glm::dot(-s.wi, m_axis);
        if (cosAngle <= m_cosOutside) return s;
        float t = m_cosInside > m_cosOutside ? std::clamp((cosAngle - m_cosOutside) / (m_cosInside - m_cosOutside), 0.0f, 1.0f)
                                             : 1.0f;
        falloff *= std::pow(std::max(cosAngle, 0.0f), m_beam) * t * t * (3.0f - 2.0f * t);
    }
    s.radiance = color * falloff;
    return s;
}

}  // namespace bxdflab
