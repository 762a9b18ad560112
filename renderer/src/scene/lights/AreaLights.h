// Lights with a shape: PxrDiskLight, PxrRectLight, PxrSphereLight.
// Disk and rect lights lie in their local xy plane (unit diameter / unit
// square) and emit toward their local +z only, as in RenderMan (a light under
// a ceiling is placed with Rotate 90 1 0 0, which turns +z down); sphere
// lights (unit diameter) emit outward everywhere.
#pragma once

#include "scene/lights/EmissionShaping.h"
#include "scene/lights/ShapedLight.h"

namespace bxdflab {

/// A flat light: a disk or a rectangle spanned by axes ex, ey around center.
class PlanarLight final : public ShapedLight {
public:
    enum class Shape { Disk, Rect };
    PlanarLight(Shape shape, Mat4 const& lightToWorld);
    const char* kind() const override { return m_shape == Shape::Disk ? "PxrDiskLight" : "PxrRectLight"; }
    LightSample sample(Vec3 const& P, Vec2 const& xi) const override;
    bool intersect(Vec3 const& org, Vec3 const& dir, float& distance, RtColorRGB& radiance, float& pdf) const override;
    bool sampleEmission(Vec2 const& xiPosition, Vec2 const& xiDirection, LightEmission& out) const override;
    EmissionDensity emissionDensity(Vec3 const& point, Vec3 const& dir) const override;
    /// coneAngle, coneSoftness, emissionFocus (see EmissionShaping.h).
    void setShaping(EmissionShaping const& shaping) { m_shaping = shaping; }

private:
    float solidAnglePdf(Vec3 const& towardLight, float distance) const;
    /// The radiance sent at cos(theta) to the emitting normal (> 0).
    RtColorRGB emitted(float cosTheta) const;
    Shape m_shape;
    EmissionShaping m_shaping;
    Vec3 m_axisX, m_axisY, m_emitNormal, m_planeNormal;
};

/// A sphere light, sampled uniformly inside the cone it subtends (exact
/// solid-angle sampling).
class SphereLight final : public ShapedLight {
public:
    explicit SphereLight(Mat4 const& lightToWorld);
    const char* kind() const override { return "PxrSphereLight"; }
    LightSample sample(Vec3 const& P, Vec2 const& xi) const override;
    bool intersect(Vec3 const& org, Vec3 const& dir, float& distance, RtColorRGB& radiance, float& pdf) const override;
    bool sampleEmission(Vec2 const& xiPosition, Vec2 const& xiDirection, LightEmission& out) const override;
    EmissionDensity emissionDensity(Vec3 const& point, Vec3 const& dir) const override;
    float radius() const { return m_radius; }

private:
    /// 1 - cos(theta_max) of the cone seen from P, or 0 inside the sphere.
    float coneOneMinusCos(Vec3 const& P) const;
    float m_radius;
};

/// PxrCylinderLight: a tube along its local x axis, 1 long and 1 across
/// (x from -0.5 to 0.5, radius 0.5), that emits outward from its side only;
/// its open ends emit nothing. Points are sampled uniformly over the side.
/// As in RenderMan, the cross-section's scale should be uniform; an uneven
/// one is averaged, as a sphere light's is.
class CylinderLight final : public ShapedLight {
public:
    explicit CylinderLight(Mat4 const& lightToWorld);
    const char* kind() const override { return "PxrCylinderLight"; }
    LightSample sample(Vec3 const& P, Vec2 const& xi) const override;
    bool intersect(Vec3 const& org, Vec3 const& dir, float& distance, RtColorRGB& radiance, float& pdf) const override;
    bool sampleEmission(Vec2 const& xiPosition, Vec2 const& xiDirection, LightEmission& out) const override;
    EmissionDensity emissionDensity(Vec3 const& point, Vec3 const& dir) const override;

private:
    /// The point of the side at axial fraction s (-0.5 to 0.5) and angle phi, and its outward normal.
    Vec3 pointAt(float s, float phi, Vec3& normal) const;
    float solidAnglePdf(Vec3 const& towardLight, float distance, Vec3 const& normal) const;
    Vec3 m_axis, m_across1, m_across2;  ///< unit axis; the two unit directions across it
    float m_length, m_radius;
};

}  // namespace bxdflab
