// Renders whose answer is known in closed form. Each sets up a white (or
// known-albedo) Lambertian surface, so the radiance toward the camera is
// albedo / pi times the irradiance E, and compares with the formula.
#include <catch2/catch.hpp>
#include <cmath>

#include "render/Film.h"
#include "scene/lights/InfiniteLights.h"
#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {

/// An 8x8 orthographic view of a tiny patch around the origin of a white
/// diffuse plane at z = 5 facing the camera, lit by `lights` (RIB text).
std::string planeScene(std::string const& lights, std::string const& integrator) {
    return "Format 8 8 1\n"
           "Projection \"orthographic\"\n"
           "ScreenWindow -0.01 0.01 -0.01 0.01\n" +
           integrator +
           "WorldBegin\n"
           "  AttributeBegin\n"
           "    Attribute \"visibility\" \"int camera\" [0]\n" +
           lights +
           "  AttributeEnd\n"
           "  Bxdf \"diffuse\" \"white\" \"color diffuseColor\" [1 1 1]\n"
           "  Polygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\n"
           "WorldEnd\n";
}

/// A diffuse sphere of the given albedo in front of a 32x32 camera, lit by `dome` only.
std::string sphereUnderDome(std::string const& dome, std::string const& albedo) {
    return "Format 32 32 1\nProjection \"perspective\" \"fov\" [30]\n"
           "Integrator \"PxrDirectLighting\" \"d\"\n"
           "WorldBegin\n" +
           dome + "  Translate 0 0 5\n  Bxdf \"diffuse\" \"grey\" \"color diffuseColor\" [" + albedo +
           "]\n  Sphere 1 -1 1 360\nWorldEnd\n";
}

/// Mean of channel c over the pixels the sphere fully covers.
double coveredMean(test::RenderOutcome const& r, int c) {
    return test::meanChannel(r, c, [&](int x, int y) { return r.channel(x, y, 3) == 1.0f; });
}

double centreRadiance(test::RenderOutcome const& r) {
    return test::meanChannel(r, 1, [](int, int) { return true; });
}

}  // namespace

TEST_CASE("disk light: radiance below its centre is L r^2 / (r^2 + h^2) for every sampling strategy", "[closed-form]") {
    const float r = 1.0f, h = 2.0f, L = 10.0f;
    std::string light = "    Translate 0 0 " + std::to_string(5.0f - h) +
                        "\n    Scale " + std::to_string(2 * r) + " " + std::to_string(2 * r) +
                        " 1\n    Light \"PxrDiskLight\" \"disk\" \"float intensity\" [" + std::to_string(L) + "]\n";
    // E = pi L r^2 / (r^2 + h^2); a white Lambertian reflects E / pi.
    const double expected = L * r * r / (r * r + h * h);
    struct Strategy {
        const char* name;
        const char* integrator;
    };
    auto strategy = GENERATE(values<Strategy>({
        {"MIS", "Integrator \"PxrDirectLighting\" \"d\" \"int numLightSamples\" [1] \"int numBxdfSamples\" [1]\n"},
        {"light only", "Integrator \"PxrDirectLighting\" \"d\" \"int numLightSamples\" [1] \"int numBxdfSamples\" [0]\n"},
        {"bxdf only", "Integrator \"PxrDirectLighting\" \"d\" \"int numLightSamples\" [0] \"int numBxdfSamples\" [1]\n"},
    }));
    CAPTURE(strategy.name);
    RenderSettings settings;
    settings.spp = 1024;
    auto result = test::renderRib(planeScene(light, strategy.integrator), settings);
    CHECK(centreRadiance(result) == Approx(expected).epsilon(0.01));
    CHECK(result.stats.nonFiniteSamples == 0u);
}

TEST_CASE("sphere light: radiance of a facing point is L (r/d)^2", "[closed-form]") {
    const float d = 3.0f, L = 36.0f;  // unit-diameter light: r = 0.5
    std::string light = "    Translate 0 0 " + std::to_string(5.0f - d) +
                        "\n    Light \"PxrSphereLight\" \"ball\" \"float intensity\" [" + std::to_string(L) + "]\n";
    const double expected = L * 0.25 / (d * d);  // E = pi L (r/d)^2
    RenderSettings settings;
    settings.spp = 512;
    auto result = test::renderRib(
        planeScene(light, "Integrator \"PxrDirectLighting\" \"d\" \"int numLightSamples\" [1] \"int numBxdfSamples\" [1]\n"),
        settings);
    CHECK(centreRadiance(result) == Approx(expected).epsilon(0.01));
}

TEST_CASE("cylinder light: radiance of a facing point is the irradiance of its lit side, for every sampling strategy",
          "[closed-form]") {
    // A tube 4 long and 1 across, its axis along x at height h below the plane's centre.
    const double length = 4.0, radius = 0.5, h = 2.0, L = 10.0;
    std::string light = "    Translate 0 0 " + std::to_string(5.0 - h) + "\n    Scale " + std::to_string(length) +
                        " 1 1\n    Light \"PxrCylinderLight\" \"tube\" \"float intensity\" [" + std::to_string(L) + "]\n";
    // E = L * integral over the side of cos(at the plane) cos(at the tube) / d^2 dA, by the midpoint rule;
    // the plane's point is at the origin of this sum, facing the tube along -z.
    double E = 0.0;
    const int steps = 1000;
    const double ds = length / steps, dphi = 2.0 * F_PI / steps;
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
            double const x = -0.5 * length + (i + 0.5) * ds, phi = (j + 0.5) * dphi;
            double const ny = std::cos(phi), nz = std::sin(phi);
            double const qx = x, qy = radius * ny, qz = -h + radius * nz;  // the point on the side, from the plane's
            double const d2 = qx * qx + qy * qy + qz * qz, d = std::sqrt(d2);
            double const cosPlane = -qz / d, cosTube = -(qy * ny + qz * nz) / d;
            if (cosPlane > 0.0 && cosTube > 0.0) E += L * cosPlane * cosTube / d2 * radius * dphi * ds;
        }
    const double expected = E / F_PI;
    // Against the infinitely long tube's irradiance, pi L r / h: the finite one is a little less.
    CHECK(expected < L * radius / h);
    CHECK(expected > 0.8 * L * radius / h);
    auto strategy = GENERATE(values<const char*>({
        "Integrator \"PxrDirectLighting\" \"d\" \"int numLightSamples\" [1] \"int numBxdfSamples\" [1]\n",
        "Integrator \"PxrDirectLighting\" \"d\" \"int numLightSamples\" [1] \"int numBxdfSamples\" [0]\n",
        "Integrator \"PxrDirectLighting\" \"d\" \"int numLightSamples\" [0] \"int numBxdfSamples\" [1]\n",
    }));
    CAPTURE(strategy);
    RenderSettings settings;
    settings.spp = 2048;
    auto result = test::renderRib(planeScene(light, strategy), settings);
    CHECK(centreRadiance(result) == Approx(expected).epsilon(0.015));
    CHECK(result.stats.nonFiniteSamples == 0u);
}

TEST_CASE("distant light: E cos(theta) / pi, exactly (a delta light has no noise)", "[closed-form]") {
    // Light travelling along +z (toward the plane), turned 60 degrees: it arrives at 60 degrees.
    // Its intensity is the radiance of a sun-sized disk: E = intensity * pi sin^2(0.265 degrees).
    const double intensity = 150000.0;
    std::string light =
        "    Rotate 60 0 1 0\n"
        "    Light \"PxrDistantLight\" \"sun\" \"float intensity\" [150000] \"float angleExtent\" [0]\n";
    auto result = test::renderRib(planeScene(light, "Integrator \"PxrDirectLighting\" \"d\"\n"));
    const double sinHalf = std::sin(0.5 * 0.53 * F_PI / 180.0);
    const double E = intensity * F_PI * sinHalf * sinHalf;
    CHECK(E == Approx(intensity * distantLightIrradianceScale(0.0f, false)).epsilon(1e-5));
    const double expected = E * 0.5 / F_PI;
    for (int y = 0; y < result.height; ++y)
        for (int x = 0; x < result.width; ++x) REQUIRE(result.channel(x, y, 0) == Approx(expected).epsilon(1e-5));
}

TEST_CASE("constant dome light: a convex diffuse object renders to albedo x L", "[closed-form]") {
    std::string dome =
        "  AttributeBegin\n    Attribute \"visibility\" \"int camera\" [0]\n"
        "    Light \"PxrDomeLight\" \"sky\" \"float intensity\" [2] \"color lightColor\" [1 0.5 0.25]\n"
        "  AttributeEnd\n";
    RenderSettings settings;
    settings.spp = 256;
    auto result = test::renderRib(sphereUnderDome(dome, "0.5 0.5 0.5"), settings);
    CHECK(coveredMean(result, 0) == Approx(1.0).epsilon(0.01));
    CHECK(coveredMean(result, 1) == Approx(0.5).epsilon(0.01));
    CHECK(coveredMean(result, 2) == Approx(0.25).epsilon(0.01));
    // The background is black: the dome is invisible to the camera.
    CHECK(result.channel(0, 0, 0) == 0.0f);
}

TEST_CASE("image dome light: a constant lat-long map is importance sampled without bias", "[closed-form]") {
    // A 64 x 32 map of constant colour: the sampling density follows sin(theta)
    // over the image, so a wrong pdf conversion would show up as a wrong mean.
    std::string path = test::outputDir() + "/constant-sky.exr";
    std::vector<float> pixels(64 * 32 * 3);
    for (size_t i = 0; i < pixels.size(); i += 3) {
        pixels[i] = 0.5f;
        pixels[i + 1] = 1.0f;
        pixels[i + 2] = 2.0f;
    }
    writeImage(path, pixels, 64, 32, 3);
    std::string dome = "  Light \"PxrDomeLight\" \"sky\" \"string lightColorMap\" [\"" + path + "\"]\n";
    RenderSettings settings;
    settings.spp = 256;
    auto result = test::renderRib(sphereUnderDome(dome, "1 1 1"), settings);
    CHECK(coveredMean(result, 0) == Approx(0.5).epsilon(0.01));
    CHECK(coveredMean(result, 2) == Approx(2.0).epsilon(0.01));
    // The camera sees the dome itself behind the sphere.
    CHECK(result.channel(0, 0, 1) == Approx(1.0f));
}

TEST_CASE("image dome light: NaN and negative pixels are taken as black, counted and warned about", "[closed-form][errors]") {
    // A white sky with one row at -5 (64 pixels) and one NaN pixel: a bad export.
    std::string path = test::outputDir() + "/damaged-sky.exr";
    std::vector<float> pixels(64 * 32 * 3, 1.0f);
    for (int x = 0; x < 64; ++x)
        for (int c = 0; c < 3; ++c) pixels[(16 * 64 + x) * 3 + c] = -5.0f;
    pixels[(3 * 64 + 3) * 3 + 1] = std::numeric_limits<float>::quiet_NaN();
    writeImage(path, pixels, 64, 32, 3);
    std::string dome = "  Light \"PxrDomeLight\" \"sky\" \"string lightColorMap\" [\"" + path + "\"]\n";
    RenderSettings settings;
    settings.spp = 64;
    auto result = test::renderRib(sphereUnderDome(dome, "1 1 1"), settings);
    CHECK(result.anyMessageContains("65 pixels of lightColorMap"));
    for (float v : result.rgba) REQUIRE(std::isfinite(v));
    CHECK(result.stats.nonFiniteSamples == 0u);
    // One dark row of 32 costs a little light, no more (a negative one would subtract).
    CHECK(coveredMean(result, 0) > 0.9);
    CHECK(coveredMean(result, 0) <= 1.0);
}
