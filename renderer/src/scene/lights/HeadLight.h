// PxrDefault's "headlight": a light at the camera that illuminates whatever
// the camera sees, so a scene without lights is still visible. It has no
// distance falloff, and its strength (pi) makes a white diffuse surface
// facing the camera appear with radiance 1.
#pragma once

#include "scene/lights/Light.h"

namespace bxdflab {

class HeadLight final : public Light {
public:
    explicit HeadLight(Vec3 const& position) : m_position(position) {
        color = RtColorRGB(kPi);
        handle = "headlight";
        visibility.camera = false;
    }
    const char* kind() const override { return "headlight"; }
    LightSample sample(Vec3 const& P, Vec2 const&) const override {
        LightSample s;
        Vec3 toLight = m_position - P;
        s.distance = glm::length(toLight);
        if (!(s.distance > 0.0f)) return s;
        s.wi = toLight / s.distance;
        s.radiance = color;
        s.pdf = 1.0f;
        s.delta = true;
        return s;
    }
    bool intersect(Vec3 const&, Vec3 const&, float&, RtColorRGB&, float&) const override { return false; }
    bool isDelta() const override { return true; }

private:
    Vec3 m_position;
};

}  // namespace bxdflab
