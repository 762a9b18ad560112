// The classic RenderMan light shaders that are points: pointlight and
// spotlight (RI specification, appendix A). Both are delta lights: no ray can
// hit them, only light sampling finds them. Their `color` is a radiant
// intensity: the irradiance at distance d facing the light is color / d^2.
#pragma once

#include "scene/lights/Light.h"

namespace bxdflab {

/// Light from one point, the same in every direction; a spotlight when a cone is given.
class PointLight final : public Light {
public:
    explicit PointLight(Vec3 const& position) : m_position(position) {}
    /// A spotlight: full strength within coneAngle - coneDeltaAngle of `axis`
    /// (radians), fading smoothly to nothing at coneAngle, times cos^beam.
    PointLight(Vec3 const& position, Vec3 const& axis, float coneAngle, float coneDeltaAngle, float beamDistribution);
    /// Barzel's uberlight falloff instead of the inverse square: (reference / d)^power
    /// beyond `reference`, full strength nearer (power 0: none at all).
    void setDistanceFalloff(float power, float reference) {
        m_falloffPower = power;
        m_falloffReference = reference;
        m_inverseSquare = false;
    }
    const char* kind() const override { return m_spot ? "spotlight" : "pointlight"; }
    LightSample sample(Vec3 const& P, Vec2 const& xi) const override;
    bool intersect(Vec3 const&, Vec3 const&, float&, RtColorRGB&, float&) const override { return false; }
    bool isDelta() const override { return true; }
    /// Light subpaths carry physical light: a light without the inverse square has none to start.
    bool canEmit() const override { return m_inverseSquare; }
    bool sampleEmission(Vec2 const& xiPosition, Vec2 const& xiDirection, LightEmission& out) const override;
    EmissionDensity emissionDensity(Vec3 const& point, Vec3 const& dir) const override;

private:
    /// The fraction of `color` sent along unit dir (the spotlight's cone and beam; 1 for a point light).
    float falloff(Vec3 const& dir) const;
    Vec3 m_position;
    bool m_spot = false;
    Vec3 m_axis{0.0f, 0.0f, 1.0f};
    float m_cosOutside = -1.0f, m_cosInside = -1.0f, m_beam = 0.0f;
    bool m_inverseSquare = true;
    float m_falloffPower = 2.0f, m_falloffReference = 1.0f;
};

}  // namespace bxdflab
