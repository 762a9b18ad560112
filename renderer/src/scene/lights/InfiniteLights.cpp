#include "scene/lights/InfiniteLights.h"

#include <cmath>

#include "core/Error.h"
#include "core/ImageFiles.h"

namespace bxdflab {

float distantLightIrradianceScale(float angleExtentDegrees, bool areaNormalize) {
    float extent = areaNormalize || !(angleExtentDegrees > 0.0f) ? kSunAngleExtent : std::min(angleExtentDegrees, 180.0f);
    float sinHalf = std::sin(0.5f * extent * kPi / 180.0f);
    return kPi * sinHalf * sinHalf;
}

DistantLight::DistantLight(Mat4 const& lightToWorld, float angleExtentDegrees) {
    m_towardLight = safeNormalize(transformVector(lightToWorld, Vec3(0.0f, 0.0f, -1.0f)));
    orthonormalBasis(m_towardLight, m_b1, m_b2);
    float halfAngle = 0.5f * std::clamp(angleExtentDegrees, 0.0f, 180.0f) * kPi / 180.0f;
    m_cosHalfAngle = halfAngle > 0.0f ? std::cos(halfAngle) : 1.0f;
    float sinHalf = std::sin(halfAngle);
    m_radianceScale = halfAngle > 0.0f ? 1.0f / (kPi * sinHalf * sinHalf) : 1.0f;
}

LightSample DistantLight::sample(Vec3 const&, Vec2 const& xi) const {
    LightSample s;
    if (isDelta()) {
        s.wi = m_towardLight;
        s.pdf = 1.0f;
        s.delta = true;
        s.radiance = color;
        return s;
    }
    float cosTheta = 1.0f - xi.x * (1.0f - m_cosHalfAngle);
    float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = 2.0f * kPi * xi.y;
    s.wi = sinTheta * std::cos(phi) * m_b1 + sinTheta * std::sin(phi) * m_b2 + cosTheta * m_towardLight;
    s.pdf = 1.0f / (2.0f * kPi * (1.0f - m_cosHalfAngle));
    s.radiance = color * m_radianceScale;
    return s;
}

bool DistantLight::intersect(Vec3 const&, Vec3 const& dir, float& distance, RtColorRGB& radiance, float& pdf) const {
    if (isDelta() || glm::dot(dir, m_towardLight) < m_cosHalfAngle) return false;
    distance = kInfinity;
    radiance = color * m_radianceScale;
    pdf = 1.0f / (2.0f * kPi * (1.0f - m_cosHalfAngle));
    return true;
}

DomeLight::DomeLight(Mat4 const& lightToWorld, std::string const& imagePath) {
    setOrientation(lightToWorld);
    if (imagePath.empty()) return;
    ImagePixels image = imageFiles().read(imagePath, "PxrDomeLight: cannot read lightColorMap");
    int const channels = image.channels;
    std::vector<Vec3> pixels(static_cast<size_t>(image.width) * image.height);
    for (size_t i = 0; i < pixels.size(); ++i) {
        float const* p = &image.pixels[i * channels];
        pixels[i] = channels >= 3 ? Vec3(p[0], p[1], p[2]) : Vec3(p[0]);
    }
    setPixels(image.width, image.height, std::move(pixels));
}

DomeLight::DomeLight(Mat4 const& lightToWorld, int width, int height, std::vector<Vec3> pixels) {
    setOrientation(lightToWorld);
    setPixels(width, height, std::move(pixels));
}

void DomeLight::setOrientation(Mat4 const& lightToWorld) {
    // Only the rotation matters for a light at infinity.
    Mat3 linear(lightToWorld);
    for (int c = 0; c < 3; ++c) linear[c] = safeNormalize(linear[c]);
    m_toWorld = linear;
    m_toLight = glm::transpose(linear);
}

void DomeLight::setPixels(int width, int height, std::vector<Vec3> pixels) {
    m_width = width;
    m_height = height;
    m_pixels = std::move(pixels);
    std::vector<float> weights(m_pixels.size());
    for (int y = 0; y < m_height; ++y) {
        float sinTheta = std::sin(kPi * (y + 0.5f) / m_height);
        for (int x = 0; x < m_width; ++x) {
            size_t index = static_cast<size_t>(y) * m_width + x;
            Vec3& rgb = m_pixels[index];
            // Light cannot be negative or undefined: such pixels (a bad export) become black,
            // for lookups and for the sampling distribution alike, and are counted.
            if (!isFinite(rgb) || rgb.x < 0.0f || rgb.y < 0.0f || rgb.z < 0.0f) {
                rgb = isFinite(rgb) ? glm::max(rgb, Vec3(0.0f)) : Vec3(0.0f);
                ++m_repairedPixels;
            }
            weights[index] = (0.2126f * rgb.x + 0.7152f * rgb.y + 0.0722f * rgb.z) * sinTheta;
        }
    }
    m_distribution = Distribution2D(weights, m_width, m_height);
}

Vec2 DomeLight::toImage(Vec3 const& worldDir) const {
    Vec3 d = m_toLight * worldDir;
    float u = 0.5f + std::atan2(d.x, -d.z) / (2.0f * kPi);
    float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi;
    return Vec2(u - std::floor(u), v);
}

Vec3 DomeLight::localDirection(Vec2 const& uv) {
    float phi = 2.0f * kPi * (uv.x - 0.5f), theta = kPi * uv.y;
    return Vec3(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
}

Vec3 DomeLight::fromImage(Vec2 const& uv) const { return m_toWorld * localDirection(uv); }

RtColorRGB DomeLight::radiance(Vec3 const& dir) const {
    if (m_pixels.empty()) return color;
    Vec2 uv = toImage(dir);
    int x = std::clamp(static_cast<int>(uv.x * m_width), 0, m_width - 1);
    int y = std::clamp(static_cast<int>(uv.y * m_height), 0, m_height - 1);
    Vec3 const& p = m_pixels[static_cast<size_t>(y) * m_width + x];
    return color * RtColorRGB(p.x, p.y, p.z);
}

float DomeLight::directionPdf(Vec3 const& worldDir) const {
    if (m_pixels.empty()) return 1.0f / (4.0f * kPi);
    Vec2 uv = toImage(worldDir);
    float sinTheta = std::sin(kPi * uv.y);
    if (sinTheta <= 0.0f) return 0.0f;
    return m_distribution.pdf(uv) / (2.0f * kPi * kPi * sinTheta);
}

LightSample DomeLight::sample(Vec3 const&, Vec2 const& xi) const {
    LightSample s;
    if (m_pixels.empty()) {
        float z = 1.0f - 2.0f * xi.x;
        float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        float phi = 2.0f * kPi * xi.y;
        s.wi = Vec3(r * std::cos(phi), r * std::sin(phi), z);
        s.pdf = 1.0f / (4.0f * kPi);
        s.radiance = color;
        return s;
    }
    float uvPdf;
    Vec2 uv = m_distribution.sample(xi, uvPdf);
    s.wi = fromImage(uv);
    float sinTheta = std::sin(kPi * uv.y);
    s.pdf = sinTheta > 0.0f ? uvPdf / (2.0f * kPi * kPi * sinTheta) : 0.0f;
    s.radiance = s.pdf > 0.0f ? radiance(s.wi) : RtColorRGB(0.0f);
    return s;
}

bool DomeLight::intersect(Vec3 const&, Vec3 const& dir, float& distance, RtColorRGB& radianceOut, float& pdf) const {
    distance = kInfinity;
    radianceOut = radiance(dir);
    pdf = directionPdf(dir);
    return true;
}

}  // namespace bxdflab
