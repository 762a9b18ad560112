// Lights at infinity: PxrDistantLight (the sun) and PxrDomeLight (the sky).
#pragma once

#include <string>

#include "core/Distribution.h"
#include "scene/lights/Light.h"

namespace bxdflab {

/// The sun's apparent diameter in degrees: PxrDistantLight's default angleExtent.
constexpr float kSunAngleExtent = 0.53f;

/// The irradiance a PxrDistantLight of radiance 1 gives a surface facing it:
/// the projected solid angle pi sin^2(angleExtent / 2) of its disk. As in
/// RenderMan, a distant light's intensity is the radiance of its disk, so its
/// default of 50000 over the sun's 0.53 degrees gives an irradiance of 3.4.
/// With areaNormalize, or an angleExtent of 0 (a delta light), the disk is
/// taken as the sun's whatever its size: the irradiance no longer depends on it.
float distantLightIrradianceScale(float angleExtentDegrees, bool areaNormalize);

/// Light arriving from one direction: it travels along its local +z, as
/// RenderMan's PxrDistantLight and the classic distantlight shader's default
/// (from 0 0 0 to 0 0 1), so it comes from local -z.
/// With angleExtent > 0 (degrees, the apparent diameter) it is a small cone of
/// directions; with 0 it is a delta light. Either way, `color` is the
/// irradiance on a surface facing the light (the factory converts RenderMan's
/// radiance with distantLightIrradianceScale).
class DistantLight final : public Light {
public:
    DistantLight(Mat4 const& lightToWorld, float angleExtentDegrees);
    const char* kind() const override { return "PxrDistantLight"; }
    LightSample sample(Vec3 const& P, Vec2 const& xi) const override;
    bool intersect(Vec3 const& org, Vec3 const& dir, float& distance, RtColorRGB& radiance, float& pdf) const override;
    bool isDelta() const override { return m_cosHalfAngle >= 1.0f; }
    bool isInfinite() const override { return true; }

private:
    Vec3 m_towardLight, m_b1, m_b2;
    float m_cosHalfAngle;
    float m_radianceScale;  ///< 1 / (pi sin^2(half angle)): irradiance -> radiance
};

/// An environment surrounding the scene: a constant colour, or a lat-long
/// image ("lightColorMap") with +y up in the light's space. Images are
/// importance sampled by luminance.
class DomeLight final : public Light {
public:
    /// Loads the image if `imagePath` is not empty (throws RenderError if it cannot).
    DomeLight(Mat4 const& lightToWorld, std::string const& imagePath);
    /// A lat-long image made in memory (`pixels`: width * height, rows from the zenith down).
    DomeLight(Mat4 const& lightToWorld, int width, int height, std::vector<Vec3> pixels);
    /// The direction, in the light's own space (+y up), of the image point (u, v) in [0,1]^2.
    static Vec3 localDirection(Vec2 const& uv);
    /// Pixels of the image that were NaN, infinite or negative (taken as black).
    long repairedPixels() const { return m_repairedPixels; }
    const char* kind() const override { return "PxrDomeLight"; }
    LightSample sample(Vec3 const& P, Vec2 const& xi) const override;
    bool intersect(Vec3 const& org, Vec3 const& dir, float& distance, RtColorRGB& radiance, float& pdf) const override;
    bool isInfinite() const override { return true; }
    /// Radiance arriving from direction dir (world space, unit).
    RtColorRGB radiance(Vec3 const& dir) const;

private:
    void setOrientation(Mat4 const& lightToWorld);
    /// Takes the pixels (NaN, infinite or negative ones become black) and builds the sampling distribution.
    void setPixels(int width, int height, std::vector<Vec3> pixels);
    Vec2 toImage(Vec3 const& worldDir) const;
    Vec3 fromImage(Vec2 const& uv) const;
    float directionPdf(Vec3 const& worldDir) const;

    Mat3 m_toWorld, m_toLight;
    int m_width = 0, m_height = 0;
    long m_repairedPixels = 0;
    std::vector<Vec3> m_pixels;
    Distribution2D m_distribution;
};

}  // namespace bxdflab
