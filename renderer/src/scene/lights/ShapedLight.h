// A light with a surface (disk, rectangle, sphere, tube, polygons): what all of
// them share is an emitting area and a ball that holds them.
#pragma once

#include "scene/lights/Light.h"

namespace bxdflab {

class ShapedLight : public Light {
public:
    /// A light with no area (a shape scaled to nothing) cannot start a light subpath.
    bool canEmit() const override { return m_area > 0.0f; }
    float surfaceArea() const override { return m_area; }
    bool boundingSphere(Vec3& center, float& radius) const override {
        center = m_center;
        radius = m_boundingRadius;
        return true;
    }

protected:
    /// Set by each light's constructor, once its shape is placed in world space.
    Vec3 m_center{0.0f};
    float m_area = 0.0f;
    float m_boundingRadius = 0.0f;
};

}  // namespace bxdflab
