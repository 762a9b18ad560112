#include "scene/lights/DayLight.h"

#include <algorithm>
#include <cmath>

namespace bxdflab {

namespace {

constexpr float kPhotometricScale = 1e-5f;      // RenderMan's: physical daylight is ~1e5 times too bright
constexpr float kSunDiameterDegrees = 0.55f;    // RenderMan's realistic sun
constexpr float kSolarIlluminance = 128000.0f;  // lux, above the atmosphere
constexpr int kSkyWidth = 256, kSkyHeight = 128;

/// Preetham et al.'s distribution (after Perez): (1 + A e^(B / cos theta)) (1 + C e^(D gamma) + E cos^2 gamma).
struct Perez {
    float A, B, C, D, E;
    float operator()(float cosTheta, float gamma) const {
        float const cosGamma = std::cos(gamma);
        return (1.0f + A * std::exp(B / std::max(cosTheta, 0.01f))) *
               (1.0f + C * std::exp(D * gamma) + E * cosGamma * cosGamma);
    }
};

/// The coefficients' linear fits in turbidity T (the paper's appendix).
Perez luminanceDistribution(float T) {
    return {0.1787f * T - 1.4630f, -0.3554f * T + 0.4275f, -0.0227f * T + 5.3251f, 0.1206f * T - 2.5771f,
            -0.0670f * T + 0.3703f};
}
Perez xDistribution(float T) {
    return {-0.0193f * T - 0.2592f, -0.0665f * T + 0.0008f, -0.0004f * T + 0.2125f, -0.0641f * T - 0.8989f,
            -0.0033f * T + 0.0452f};
}
Perez yDistribution(float T) {
    return {-0.0167f * T - 0.2608f, -0.0950f * T + 0.0092f, -0.0079f * T + 0.2102f, -0.0441f * T - 1.6537f,
            -0.0109f * T + 0.0529f};
}

/// The zenith's chromaticity: [T^2 T 1] M [theta^3 theta^2 theta 1]^T.
float zenithChromaticity(float const (&M)[3][4], float T, float thetaSun) {
    float const t[3] = {T * T, T, 1.0f};
    float const s[4] = {thetaSun * thetaSun * thetaSun, thetaSun * thetaSun, thetaSun, 1.0f};
    float sum = 0.0f;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) sum += t[i] * M[i][j] * s[j];
    return sum;
}

Vec3 xyYToLinearSRGB(float x, float y, float Y) {
    if (!(y > 0.0f) || !(Y > 0.0f)) return Vec3(0.0f);
    float const X = x / y * Y, Z = (1.0f - x - y) / y * Y;
    Vec3 const rgb(3.2406f * X - 1.5372f * Y - 0.4986f * Z, -0.9689f * X + 1.8758f * Y + 0.0415f * Z,
                   0.0557f * X - 0.2040f * Y + 1.0570f * Z);
    return glm::max(rgb, Vec3(0.0f));
}

int dayOfYear(int month, int day, int year) {
    static int const before[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
    bool const leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    int const m = std::clamp(month, 1, 12);
    return before[m - 1] + std::clamp(day, 1, 31) + (leap && m > 2 ? 1 : 0);
}

float luminance(Vec3 const& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

}  // namespace

DaylightParams DaylightParams::from(ParamList const& params) {
    DaylightParams p;
    p.sunDirection = params.getVector("sunDirection", p.sunDirection);
    p.month = static_cast<int>(params.getFloat("month", 0.0f));
    p.day = static_cast<int>(params.getFloat("day", 1.0f));
    p.year = static_cast<int>(params.getFloat("year", 2015.0f));
    p.hour = params.getFloat("hour", p.hour);
    p.zone = params.getFloat("zone", p.zone);
    p.latitude = params.getFloat("latitude", p.latitude);
    p.longitude = params.getFloat("longitude", p.longitude);
    p.haziness = params.getFloat("haziness", p.haziness);
    p.sunSize = params.getFloat("sunSize", p.sunSize);
    p.skyTint = params.getColor("skyTint", p.skyTint);
    p.sunTint = params.getColor("sunTint", p.sunTint);
    return p;
}

Vec3 sunDirectionAt(DaylightParams const& p) {
    if (p.month <= 0) return safeNormalize(p.sunDirection);
    // Solar time from local standard time: the equation of time plus the
    // longitude's distance from the zone's meridian (east positive, 15 degrees an hour).
    float const J = static_cast<float>(dayOfYear(p.month, p.day, p.year));
    float const solarTime = p.hour + 0.170f * std::sin(4.0f * kPi * (J - 80.0f) / 373.0f) -
                            0.129f * std::sin(2.0f * kPi * (J - 8.0f) / 355.0f) + (p.longitude - 15.0f * p.zone) / 15.0f;
    float const declination = 0.4093f * std::sin(2.0f * kPi * (J - 81.0f) / 368.0f);
    float const latitude = glm::radians(p.latitude), hourAngle = kPi * solarTime / 12.0f;
    float const sinElevation = std::sin(latitude) * std::sin(declination) -
                               std::cos(latitude) * std::cos(declination) * std::cos(hourAngle);
    // Azimuth from south, positive toward west.
    float const azimuth = std::atan2(-std::cos(declination) * std::sin(hourAngle),
                                     std::cos(latitude) * std::sin(declination) -
                                         std::sin(latitude) * std::cos(declination) * std::cos(hourAngle));
    float const cosElevation = std::sqrt(std::max(0.0f, 1.0f - sinElevation * sinElevation));
    // South is -z, west is -x.
    return Vec3(-cosElevation * std::sin(azimuth), sinElevation, -cosElevation * std::cos(azimuth));
}

Vec3 skyRadiance(Vec3 const& dir, Vec3 const& sun, float turbidity) {
    if (dir.y <= 0.0f) return Vec3(0.0f);
    float const T = std::clamp(turbidity, 1.7f, 10.0f);
    // The model holds for a sun above the horizon; after sunset the sky is kept as at sunset.
    float const thetaSun = std::acos(std::clamp(sun.y, 0.0f, 1.0f));
    float const gamma = std::acos(std::clamp(glm::dot(dir, safeNormalize(Vec3(sun.x, std::max(sun.y, 0.0f), sun.z))), -1.0f, 1.0f));
    float const chi = (4.0f / 9.0f - T / 120.0f) * (kPi - 2.0f * thetaSun);
    float const zenithY = (4.0453f * T - 4.9710f) * std::tan(chi) - 0.2155f * T + 2.4192f;  // kcd/m^2
    static float const Mx[3][4] = {{0.00166f, -0.00375f, 0.00209f, 0.0f},
                                   {-0.02903f, 0.06377f, -0.03202f, 0.00394f},
                                   {0.11693f, -0.21196f, 0.06052f, 0.25886f}};
    static float const My[3][4] = {{0.00275f, -0.00610f, 0.00317f, 0.0f},
                                   {-0.04214f, 0.08970f, -0.04153f, 0.00516f},
                                   {0.15346f, -0.26756f, 0.06670f, 0.26688f}};
    float const zenithX = zenithChromaticity(Mx, T, thetaSun), zenithYc = zenithChromaticity(My, T, thetaSun);
    Perez const FY = luminanceDistribution(T), Fx = xDistribution(T), Fy = yDistribution(T);
    float const cosTheta = dir.y;
    float const Y = zenithY * FY(cosTheta, gamma) / FY(1.0f, thetaSun);
    float const x = zenithX * Fx(cosTheta, gamma) / Fx(1.0f, thetaSun);
    float const y = zenithYc * Fy(cosTheta, gamma) / Fy(1.0f, thetaSun);
    return xyYToLinearSRGB(x, y, std::max(Y, 0.0f) * 1000.0f * kPhotometricScale);
}

Vec3 sunIrradiance(Vec3 const& sun, float turbidity) {
    if (sun.y <= 0.0f) return Vec3(0.0f);
    float const T = std::clamp(turbidity, 1.7f, 10.0f);
    float const zenithDegrees = glm::degrees(std::acos(std::clamp(sun.y, 0.0f, 1.0f)));
    // Relative optical air mass (Kasten's fit, as the paper's appendix uses it).
    float const airMass = 1.0f / (sun.y + 0.15f * std::pow(93.885f - zenithDegrees, -1.253f));
    // Rayleigh and aerosol (Angstrom, alpha 1.3, beta from turbidity) extinction at
    // wavelengths standing for red, green and blue (micrometres).
    float const beta = 0.04608f * T - 0.04586f;
    Vec3 transmittance;
    float const wavelengths[3] = {0.610f, 0.550f, 0.465f};
    for (int c = 0; c < 3; ++c) {
        float const lambda = wavelengths[c];
        float const rayleigh = 0.008735f * std::pow(lambda, -4.08f), aerosol = beta * std::pow(lambda, -1.3f);
        transmittance[c] = std::exp(-(rayleigh + aerosol) * airMass);
    }
    return kSolarIlluminance * kPhotometricScale * transmittance;
}

DayLight::DayLight(Mat4 const& lightToWorld, DaylightParams const& params) {
    Vec3 const sun = sunDirectionAt(params);
    std::vector<Vec3> pixels(static_cast<size_t>(kSkyWidth) * kSkyHeight);
    float skyPower = 0.0f;  // luminous "irradiance" of the whole sky, for the sun/sky choice
    for (int y = 0; y < kSkyHeight; ++y)
        for (int x = 0; x < kSkyWidth; ++x) {
            Vec2 const uv((x + 0.5f) / kSkyWidth, (y + 0.5f) / kSkyHeight);
            Vec3 const radiance = params.skyTint * skyRadiance(DomeLight::localDirection(uv), sun, params.haziness);
            pixels[static_cast<size_t>(y) * kSkyWidth + x] = radiance;
            float const solidAngle = 2.0f * kPi * kPi * std::sin(kPi * uv.y) / (kSkyWidth * kSkyHeight);
            skyPower += luminance(radiance) * solidAngle;
        }
    m_sky = std::make_unique<DomeLight>(lightToWorld, kSkyWidth, kSkyHeight, std::move(pixels));
    m_sky->color = RtColorRGB(1.0f);

    Vec3 const sunLight = params.sunTint * sunIrradiance(sun, params.haziness);
    if (luminance(sunLight) > 0.0f) {
        // A distant light shines along its +z: toward -sun.
        Vec3 const travel = safeNormalize(transformVector(lightToWorld, -sun));
        Vec3 x, y;
        orthonormalBasis(travel, x, y);
        Mat4 const frame(Vec4(x, 0.0f), Vec4(y, 0.0f), Vec4(travel, 0.0f), Vec4(0.0f, 0.0f, 0.0f, 1.0f));
        m_sun = std::make_unique<DistantLight>(frame, kSunDiameterDegrees * std::max(params.sunSize, 0.01f));
        m_sun->color = RtColorRGB(sunLight.x, sunLight.y, sunLight.z);  // a distant light's colour is its irradiance
        // Sample sun and sky in proportion to the light each brings, but never one alone.
        m_sunProbability = std::clamp(luminance(sunLight) / (luminance(sunLight) + skyPower), 0.1f, 0.9f);
    }
}

void DayLight::both(Vec3 const& dir, RtColorRGB& radiance, float& pdf) const {
    float distance;
    RtColorRGB sky, sun;
    float skyPdf = 0.0f, sunPdf = 0.0f;
    m_sky->intersect(Vec3(0.0f), dir, distance, sky, skyPdf);
    if (!m_sun || !m_sun->intersect(Vec3(0.0f), dir, distance, sun, sunPdf)) sun = RtColorRGB(0.0f);
    radiance = color * (sky + sun);
    pdf = m_sunProbability * sunPdf + (1.0f - m_sunProbability) * skyPdf;
}

LightSample DayLight::sample(Vec3 const& P, Vec2 const& xi) const {
    LightSample s;
    if (xi.x < m_sunProbability) {
        s = m_sun->sample(P, Vec2(xi.x / m_sunProbability, xi.y));
    } else {
        s = m_sky->sample(P, Vec2((xi.x - m_sunProbability) / (1.0f - m_sunProbability), xi.y));
    }
    if (s.pdf > 0.0f) both(s.wi, s.radiance, s.pdf);
    return s;
}

bool DayLight::intersect(Vec3 const&, Vec3 const& dir, float& distance, RtColorRGB& radiance, float& pdf) const {
    distance = kInfinity;
    both(dir, radiance, pdf);
    return true;
}

}  // namespace bxdflab
