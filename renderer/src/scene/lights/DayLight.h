// PxrEnvDayLight: a clear sky and the sun, as RenderMan documents it. The sky
// is Preetham, Shirley and Smits' analytic daylight model ("A Practical
// Analytic Model for Daylight", 1999) for a turbidity (RenderMan's
// "haziness"); the sun is a disk of 0.55 degrees whose colour is the
// extraterrestrial sun seen through the same atmosphere (Rayleigh and
// aerosol extinction along the air mass). Photometric values are scaled by
// 1e-5, as RenderMan does, so a clear noon gives an irradiance near 1.
//
// Directions are in the light's space: +y is the zenith, the horizon is the
// xz plane; for a sun placed by date, time and place, +z is north and +x east
// (facing +z in RenderMan's left-handed space, east is on the right).
#pragma once

#include <memory>

#include "parse/ParamList.h"
#include "scene/lights/InfiniteLights.h"

namespace bxdflab {

/// What places the sun and colours the sky.
struct DaylightParams {
    Vec3 sunDirection{0.0f, 1.0f, 0.0f};  ///< toward the sun, light space; used when month is 0
    int month = 0, day = 1, year = 2015;
    float hour = 14.633f, zone = -8.0f, latitude = 47.602f, longitude = -122.332f;
    float haziness = 2.0f;  ///< turbidity: 1.7 (very clear) to 10 (hazy)
    float sunSize = 1.0f;   ///< times 0.55 degrees; the sun's irradiance stays the same
    Vec3 skyTint{1.0f}, sunTint{1.0f};

    static DaylightParams from(ParamList const& params);
};

/// The unit direction toward the sun (light space) for a date, a local
/// standard time and a place; its y is negative when the sun has set.
Vec3 sunDirectionAt(DaylightParams const& p);

/// The sky's radiance (linear sRGB, RenderMan's scale) toward `dir` (light
/// space, unit) for the sun toward `sun` and a turbidity; black below the horizon.
Vec3 skyRadiance(Vec3 const& dir, Vec3 const& sun, float turbidity);

/// The sun's irradiance on a surface facing it (linear sRGB, RenderMan's
/// scale) after the atmosphere; black once the sun has set.
Vec3 sunIrradiance(Vec3 const& sun, float turbidity);

class DayLight final : public Light {
public:
    DayLight(Mat4 const& lightToWorld, DaylightParams const& params);
    const char* kind() const override { return "PxrEnvDayLight"; }
    LightSample sample(Vec3 const& P, Vec2 const& xi) const override;
    bool intersect(Vec3 const& org, Vec3 const& dir, float& distance, RtColorRGB& radiance, float& pdf) const override;
    bool isInfinite() const override { return true; }

private:
    /// Sky and sun toward `dir` together: their radiance and the pdf sample() gives `dir`.
    void both(Vec3 const& dir, RtColorRGB& radiance, float& pdf) const;

    std::unique_ptr<DomeLight> m_sky;
    std::unique_ptr<DistantLight> m_sun;  ///< null when the sun is down
    float m_sunProbability = 0.0f;        ///< of sampling the sun rather than the sky
};

}  // namespace bxdflab
