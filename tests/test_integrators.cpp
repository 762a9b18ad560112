// Integrators against closed forms and against each other.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <utility>

#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {

using test::readScene;
using test::withIntegrator;

auto const kAll = [](int, int) { return true; };

/// The mean red over `pixels` of a scene (given its Integrator line) rendered by PxrVCM,
/// then by PxrPathTracer, both with paths of up to maxPathLength.
std::pair<double, double> vcmAndPathTracer(std::function<std::string(std::string const&)> const& scene,
                                           int maxPathLength, int spp, std::function<bool(int, int)> const& pixels) {
    std::string const length = " \"int maxPathLength\" [" + std::to_string(maxPathLength) + "]";
    auto vcm = test::renderRib(scene("Integrator \"PxrVCM\" \"v\"" + length), test::withSpp(spp));
    // PxrVCM bounds its paths by maxPathLength alone: so must the path tracer here.
    auto paths =
        test::renderRib(scene("Integrator \"PxrPathTracer\" \"p\"" + length + "\n" + test::kDeepTraceDepth),
                        test::withSpp(spp));
    return {test::meanChannel(vcm, 0, pixels), test::meanChannel(paths, 0, pixels)};
}

}  // namespace

TEST_CASE("path tracer furnace: an emitting, reflecting enclosure converges to E / (1 - a)", "[integrators][pathtracer]") {
    // The camera sits inside a closed sphere whose surface emits E and reflects
    // a fraction a diffusely: every path sees E + a E + a^2 E + ... = E / (1 - a),
    // once the walls allow paths that many diffuse bounces.
    auto furnace = [](std::string const& walls) {
        return "Format 16 16 1\nProjection \"perspective\" \"fov\" [60]\n"
               "Integrator \"PxrPathTracer\" \"pt\" \"int maxPathLength\" [200]\n"
               "WorldBegin\n" +
               walls +
               "  Bxdf \"bookdiffuse\" \"walls\" \"color emissive_color\" [0.5 0.5 0.5] \"color "
               "diffuse_color\" [0.5 0.5 0.5]\n"
               "  Sphere 5 -5 5 360\n"
               "WorldEnd\n";
    };
    RenderSettings settings;
    settings.spp = 1024;
    auto r = test::renderRib(furnace("  Attribute \"trace\" \"int maxdiffusedepth\" [200]\n"), settings);
    CHECK(test::meanChannel(r, 0, kAll) == Approx(1.0).epsilon(0.02));
    CHECK(r.stats.indirectRays > 0u);
    CHECK(r.stats.shadowRays == 0u);  // no lights: nothing to sample
    // Without the attribute the walls allow RenderMan's one diffuse bounce: E + a E.
    auto oneBounce = test::renderRib(furnace(""), settings);
    CHECK(test::meanChannel(oneBounce, 0, kAll) == Approx(0.75).epsilon(1e-5));
}

TEST_CASE("chapter 10 furnace: a smooth glass sphere in a white sky vanishes, a rough one loses light", "[integrators][ch10]") {
    // Radiance / eta^2 crosses a lossless boundary unchanged, so inside a sky of
    // radiance 1 the smooth sphere is 1 everywhere; the single-scattering rough
    // one is darker. The inner disks (0.7 of the radius) keep the rim, where
    // paths trapped by total internal reflection grow long, out of the mean.
    std::string rib = readScene("ch10/furnace.rib");
    rib.replace(rib.find("Format 400 200 1"), 16, "Format 200 100 1");
    RenderSettings settings;
    settings.spp = 64;
    auto r = test::renderRib(rib, settings);
    double const pixelsPerUnit = 50.0 / (6.0 * std::tan(15.0 * kPi / 180.0));
    auto disk = [&](double centreX) {
        return [=](int x, int y) {
            double dx = x + 0.5 - (100.0 + centreX * pixelsPerUnit), dy = y + 0.5 - 50.0;
            return std::sqrt(dx * dx + dy * dy) < 0.7 * pixelsPerUnit;
        };
    };
    auto sky = [&](int x, int) { return x < 10 || x >= 190; };
    CHECK(test::meanChannel(r, 1, sky) == Approx(1.0).epsilon(1e-6));
    CHECK(test::meanChannel(r, 1, disk(-1.2)) == Approx(1.0).epsilon(0.005));
    double rough = test::meanChannel(r, 1, disk(1.2));
    CHECK(rough < 0.95);
    CHECK(rough > 0.6);
    CHECK(r.stats.indirectRays > 0u);
}

TEST_CASE("PxrPathTracer with maxPathLength 1 (maxIndirectBounces 0) is PxrDirectLighting",
          "[integrators][pathtracer][heavy]") {
    std::string rib = readScene("ch06/plastic.rib");
    RenderSettings settings;
    settings.spp = 2;
    auto direct = test::renderRib(withIntegrator(rib, "Integrator \"PxrDirectLighting\" \"d\""), settings);
    auto paths = test::renderRib(withIntegrator(rib, "Integrator \"PxrPathTracer\" \"p\" \"int maxPathLength\" [1]"), settings);
    CHECK(paths.stats.indirectRays == 0u);
    CHECK(paths.rgba == direct.rgba);  // the same estimator, sample for sample
    // RenderMan 23 and later count bounces instead: maxIndirectBounces 0 is direct lighting,
    // 2 is maxPathLength 3.
    auto bounces0 =
        test::renderRib(withIntegrator(rib, "Integrator \"PxrPathTracer\" \"p\" \"int maxIndirectBounces\" [0]"), settings);
    CHECK(bounces0.rgba == direct.rgba);
    auto bounces2 =
        test::renderRib(withIntegrator(rib, "Integrator \"PxrPathTracer\" \"p\" \"int maxIndirectBounces\" [2]"), settings);
    auto length3 =
        test::renderRib(withIntegrator(rib, "Integrator \"PxrPathTracer\" \"p\" \"int maxPathLength\" [3]"), settings);
    CHECK(bounces2.stats.indirectRays > 0u);
    CHECK(bounces2.rgba == length3.rgba);
    CHECK_FALSE(bounces2.anyMessageContains("maxIndirectBounces"));
}

TEST_CASE("PxrPathTracer reads an exporter's full parameter list: roulette and clamping as written",
          "[integrators][pathtracer]") {
    // A white sphere on a white floor in the sun: each receives light the other bounced. (The sun is
    // not seen by the camera, so every pixel's light comes through the integrator.)
    auto scene = [](std::string const& parameters) {
        return "Format 24 18 1\nProjection \"perspective\" \"fov\" [50]\n"
               "Integrator \"PxrPathTracer\" \"p\" \"int maxPathLength\" [6] " + parameters + "\n" +
               test::kDeepTraceDepth + "Translate 0 -0.3 4\nRotate -20 1 0 0\nWorldBegin\n"
               "AttributeBegin\nRotate 60 1 0 0\nLight \"PxrDistantLight\" \"sun\" \"float intensity\" [30000]\n"
               "AttributeEnd\nBxdf \"PxrDiffuse\" \"white\" \"color diffuseColor\" [0.9 0.9 0.9]\n"
               "Sphere 1 -1 1 360\nTranslate 0 -1 0\nRotate 90 1 0 0\nDisk 0 4 360\nWorldEnd\n";
    };
    RenderSettings settings;
    settings.spp = 16;
    // What RenderMan for Maya and Blender exporters write, all at RenderMan's defaults but the clamp.
    std::string const exported =
        "\"string sampleMode\" [\"bxdf\"] \"int numIndirectSamples\" [1] \"int numDiffuseSamples\" [1] "
        "\"int numSpecularSamples\" [1] \"int numSubsurfaceSamples\" [1] \"int numRefractionSamples\" [1] "
        "\"int maxContinuationLength\" [-1] \"int maxNonStochasticOpacityEvents\" [0] \"int accumOpacity\" [0] "
        "\"string imagePlaneSubset\" [\"rman__imageplane\"] \"int rouletteDepth\" [4] "
        "\"float rouletteThreshold\" [0.2] \"int clampDepth\" [2]";
    auto plain = test::renderRib(scene(""), settings);
    auto written = test::renderRib(scene(exported), settings);
    CHECK(written.messages.empty());
    // Unbiased either way (roulette only changes which paths go on): the same picture within noise.
    double const plainMean = test::meanChannel(plain, 1, kAll), writtenMean = test::meanChannel(written, 1, kAll);
    CHECK(writtenMean == Approx(plainMean).epsilon(0.03));
    // Roulette below 0.2 only spares the paths it used to end above it: more bounces are traced.
    CHECK(written.stats.indirectRays > plain.stats.indirectRays);
    // No roulette at all, by either parameter: the same paths, sample for sample.
    auto noThreshold = test::renderRib(scene("\"float rouletteThreshold\" [0]"), settings);
    auto lateRoulette = test::renderRib(scene("\"int rouletteDepth\" [10000000]"), settings);  // as a public scene writes
    CHECK(noThreshold.rgba == lateRoulette.rgba);
    CHECK(noThreshold.stats.indirectRays > plain.stats.indirectRays);

    // Clamping from the camera ray (depth 1): no pixel sample is brighter than the clamp.
    auto clampAll = test::renderRib(scene("\"int clampDepth\" [1] \"float clampLuminance\" [0.05]"), settings);
    CHECK(test::meanChannel(clampAll, 1, kAll) > 0.01);  // not black: clamped, not cut
    for (size_t i = 0; i + 3 < clampAll.rgba.size(); i += 4) {
        float const luminance = 0.2126f * clampAll.rgba[i] + 0.7152f * clampAll.rgba[i + 1] + 0.0722f * clampAll.rgba[i + 2];
        CHECK(luminance <= 0.05f + 1e-4f);
    }
    // From the first bounce (depth 2): direct light stays whole, the bounced light is clamped away to
    // almost nothing, so the picture lies between direct lighting alone and the unclamped one.
    auto direct = test::renderRib(scene("").replace(scene("").find("\"int maxPathLength\" [6]"), 24,
                                                      "\"int maxPathLength\" [1]"),
                                  settings);
    auto clampBounces = test::renderRib(scene("\"float clampLuminance\" [0.001]"), settings);
    double const directMean = test::meanChannel(direct, 1, kAll);
    double const clampedMean = test::meanChannel(clampBounces, 1, kAll);
    CHECK(plainMean > 1.08 * directMean);  // the scene has bounced light to clamp
    CHECK(clampedMean == Approx(directMean).epsilon(0.05));

    // Four paths from each camera hit: four times the first bounces, the same picture with less noise
    // in the light that bounced.
    auto four = test::renderRib(scene("\"int numIndirectSamples\" [4]"), settings);
    CHECK(four.messages.empty());
    CHECK(four.stats.indirectRays > 3 * plain.stats.indirectRays);
    CHECK(test::meanChannel(four, 1, kAll) == Approx(plainMean).epsilon(0.03));
    double plainVariance = 0, fourVariance = 0;
    for (size_t i = 0; i < plain.variance.size(); i += 3) {
        plainVariance += plain.variance[i + 1];
        fourVariance += four.variance[i + 1];
    }
    CHECK(fourVariance < 0.8 * plainVariance);
    // What it does not do is said: per-lobe counts.
    auto manual = test::renderRib(scene("\"string sampleMode\" [\"manual\"] \"int numDiffuseSamples\" [4]"), settings);
    CHECK(manual.anyMessageContains("sampleMode \"manual\" is read as \"bxdf\""));
}

TEST_CASE("light-only, Bxdf-only and MIS estimates agree on a glossy surface", "[integrators][mis][heavy]") {
    std::string rib = readScene("ch06/specular.rib");
    RenderSettings settings;
    settings.spp = 64;
    double means[3];
    const char* integrators[3] = {
        "Integrator \"PxrDirectLighting\" \"d\" \"int numLightSamples\" [1] \"int numBxdfSamples\" [1]",
        "Integrator \"PxrDirectLighting\" \"d\" \"int numLightSamples\" [1] \"int numBxdfSamples\" [0]",
        "Integrator \"PxrDirectLighting\" \"d\" \"int numLightSamples\" [0] \"int numBxdfSamples\" [1]",
    };
    for (int k = 0; k < 3; ++k) {
        std::string scene = withIntegrator(rib, integrators[k]);
        scene.replace(scene.find("Format 800 700 1"), 16, "Format 200 175 1");
        // Importance-sample the Phong lobe so Bxdf-only sampling finds the small light.
        scene.replace(scene.find("\"float gloss\" [200]"), 19, "\"float gloss\" [200] \"int samplingMode\" [1]");
        means[k] = test::meanChannel(test::renderRib(scene, settings), 1, kAll);
    }
    CHECK(means[0] > 0.001);
    CHECK(means[1] == Approx(means[0]).epsilon(0.03));
    CHECK(means[2] == Approx(means[0]).epsilon(0.03));
}


TEST_CASE("chapter 7: PxrValidateBxdf shows the planted bugs and equal channels after the fix", "[integrators][ch07]") {
    std::string rib = readScene("ch07/validate.rib");
    rib.replace(rib.find("Format 400 350 1"), 16, "Format 100 88 1");
    auto covered = [](test::RenderOutcome const& r) {
        return [&r](int x, int y) { return r.channel(x, y, 3) == 1.0f; };
    };
    RenderSettings starter;
    starter.pluginPath = STARTER_PLUGIN_DIR;
    auto buggy = test::renderRib(rib, starter);
    double red = test::meanChannel(buggy, 0, covered(buggy)), green = test::meanChannel(buggy, 1, covered(buggy)),
           blue = test::meanChannel(buggy, 2, covered(buggy));
    CHECK(std::fabs(red - blue) > 0.1);  // pdf and sampling disagree
    CHECK(green < 0.1 * red);             // EvaluateSample disagrees with GenerateSample

    auto fixed = test::renderRib(rib);  // the solution
    red = test::meanChannel(fixed, 0, covered(fixed));
    green = test::meanChannel(fixed, 1, covered(fixed));
    blue = test::meanChannel(fixed, 2, covered(fixed));
    CHECK(red == Approx(1.0).epsilon(1e-4));
    CHECK(green == Approx(red).epsilon(1e-6));
    CHECK(blue == Approx(red).epsilon(0.01));
}

TEST_CASE("PxrDebugShadingContext shows builtins, unknown channels are located errors", "[integrators][debug]") {
    auto view = [](std::string const& channel, bool inside) {
        return "Format 9 9 1\nProjection \"perspective\" \"fov\" [10]\n"
               "Integrator \"PxrDebugShadingContext\" \"dbg\" \"string viewchannel\" [\"" + channel + "\"]\n"
               "WorldBegin\n  Translate 0 0 " + std::string(inside ? "0" : "5") + "\n  Sphere 1 -1 1 360\nWorldEnd\n";
    };
    auto normal = test::renderRib(view("Nn", false));
    // The sphere's centre faces the camera: N = (0, 0, -1) maps to (0.5, 0.5, 0).
    CHECK(normal.channel(4, 4, 0) == Approx(0.5).margin(0.02));
    CHECK(normal.channel(4, 4, 2) == Approx(0.0).margin(0.01));
    auto outside = test::renderRib(view("InsideOutside", false));
    CHECK(outside.channel(4, 4, 1) == 1.0f);
    auto inside = test::renderRib(view("InsideOutside", true));
    CHECK(inside.channel(4, 4, 0) == 1.0f);
    CHECK(inside.channel(4, 4, 1) == 0.0f);
    try {
        test::renderRib(view("Normals", false));
        FAIL("expected an error");
    } catch (RibError const& e) {
        CHECK_THAT(e.what(), Catch::Matchers::StartsWith("test.rib:3:1"));
        CHECK_THAT(e.what(), Catch::Matchers::Contains("InsideOutside"));
    }
}

TEST_CASE("PxrOcclusion: an open plane is white, a corner under a sphere is darker", "[integrators][occlusion]") {
    std::string rib =
        "Format 32 32 1\nProjection \"orthographic\"\nScreenWindow -2 2 -2 2\n"
        "Integrator \"PxrOcclusion\" \"ao\" \"int numSamples\" [16] \"float maxDistance\" [1.5]\n"
        "Rotate -90 1 0 0\nTranslate 0 -10 0\n"  // looking straight down at the plane y = 0
        "WorldBegin\n"
        "  Polygon \"P\" [-10 0 -10  10 0 -10  10 0 10  -10 0 10]\n"
        "  AttributeBegin\n  Translate 1 1 1\n  Attribute \"visibility\" \"int camera\" [0]\n  Sphere 1 -1 1 360\n  AttributeEnd\n"
        "WorldEnd\n";
    auto r = test::renderRib(rib);
    // Far from the sphere the plane sees the whole sky; next to its contact point it does not.
    double open = r.channel(2, 2, 0), shadowed = 0.0;
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) shadowed = std::max(shadowed, 1.0 - r.channel(x, y, 0));
    CHECK(open == Approx(1.0));
    CHECK(shadowed > 0.5);
}

TEST_CASE("PxrOcclusion reads RenderMan's parameters: distributions and maxDistance 0 as no limit",
          "[integrators][occlusion]") {
    // A point on a plane under a parallel disk (unseen by the camera) at height 1 and radius 1: the
    // disk covers the cone of half-angle 45 degrees about the normal. Open share of the sky: cosine
    // weighted 1 - sin^2(45) = 0.5, uniform cos(45) = 0.707.
    auto open = [](std::string const& parameters) {
        std::string const rib =
            "Format 4 4 1\nProjection \"orthographic\"\nScreenWindow -0.01 0.01 -0.01 0.01\n"
            "Integrator \"PxrOcclusion\" \"ao\" \"int numSamples\" [64] " + parameters + "\n"
            "Rotate -90 1 0 0\nTranslate 0 -10 0\n"  // looking straight down at the plane y = 0
            "WorldBegin\n"
            "  Polygon \"P\" [-10 0 -10  10 0 -10  10 0 10  -10 0 10]\n"
            "  AttributeBegin\n  Attribute \"visibility\" \"int camera\" [0]\n  Translate 0 1 0\n"
            "  Rotate 90 1 0 0\n  Disk 0 1 360\n  AttributeEnd\n"
            "WorldEnd\n";
        auto r = test::renderRib(rib, test::withSpp(64));
        double sum = 0.0;
        for (int y = 0; y < r.height; ++y)
            for (int x = 0; x < r.width; ++x) sum += r.channel(x, y, 0);
        return std::make_pair(sum / (r.width * r.height), r);
    };
    // RenderMan's defaults, written out as exporters write them: maxDistance 0 is no limit.
    auto cosine = open("\"int distribution\" [1] \"float maxDistance\" [0] \"float cosineSpread\" [1] "
                       "\"float falloff\" [0] \"int useAlbedo\" [0]");
    CHECK(cosine.first == Approx(0.5).margin(0.02));
    CHECK_FALSE(cosine.second.anyMessageContains("not used"));
    CHECK(open("").first == Approx(0.5).margin(0.02));
    CHECK(open("\"int distribution\" [0]").first == Approx(std::sqrt(0.5)).margin(0.02));
    // Seen from straight above, the mirror direction is the normal: reflection matches cosine.
    CHECK(open("\"int distribution\" [2]").first == Approx(0.5).margin(0.02));
    // The disk is 1 away: within a reach of 0.5 nothing blocks.
    CHECK(open("\"float maxDistance\" [0.5]").first == Approx(1.0));
    // What is not rendered is said.
    auto spread = open("\"float cosineSpread\" [0.5] \"float falloff\" [1] \"int useAlbedo\" [1]");
    CHECK(spread.second.anyMessageContains("cosineSpread 0.5 is not used"));
    CHECK(spread.second.anyMessageContains("falloff 1 is not used"));
    CHECK(spread.second.anyMessageContains("useAlbedo 1 is not used"));
    try {
        open("\"int distribution\" [3]");
        FAIL("expected an error");
    } catch (RibError const& e) {
        CHECK_THAT(e.what(), Catch::Matchers::StartsWith("test.rib:4:1"));
        CHECK_THAT(e.what(), Catch::Matchers::Contains("distribution must be between 0 and 2"));
    }
}

TEST_CASE(
    "PxrVisualizer: shaded by facing ratio and bxdf as PxrDefault and normals and st and flat and a normal "
    "check",
    "[integrators]") {
    std::string const scene =
        "Format 16 16 1\nProjection \"orthographic\"\nScreenWindow -2 2 -2 2\nWorldBegin\n"
        "Translate 0 0 5\nBxdf \"PxrDiffuse\" \"a\"\nAttributeBegin\nRotate -90 1 0 0\n"
        "Sphere 1 -1 1 360\nAttributeEnd\n"
        "Translate 0 0 -10\nBxdf \"PxrDiffuse\" \"b\"\nPatch \"bilinear\" \"P\" "
        "[-2 -2 20  2 -2 20  -2 2 20  2 2 20]\nWorldEnd\n";
    auto withIntegrator = [&](std::string const& integrator) {
        RenderSettings settings;
        settings.spp = 4;
        return test::renderRib(integrator + "\n" + scene, settings);
    };
    // The default style, with RenderMan's default wireframe, which is said not to be drawn.
    auto shaded = withIntegrator("Integrator \"PxrVisualizer\" \"v\"");
    CHECK(shaded.anyMessageContains("the tessellation is not drawn"));
    // Pixel (x, y) looks along z at the point (x + 0.5) / 4 - 2 across and about as far down of the
    // sphere of radius 1, where |Nn . Vn| is the height of the sphere there.
    auto facing = [](float x, float y) {
        float const a = (x + 0.5f) / 4.0f - 2.0f, b = (y + 0.5f) / 4.0f - 2.0f;
        return std::sqrt(1.0f - a * a - b * b);
    };
    CHECK(shaded.channel(8, 8, 0) == Approx(facing(8, 8)).margin(0.01));
    CHECK(shaded.channel(10, 8, 0) == Approx(facing(10, 8)).margin(0.02));
    CHECK(shaded.channel(10, 8, 1) == Approx(shaded.channel(10, 8, 0)).margin(1e-6));  // grey
    CHECK(shaded.channel(0, 0, 0) ==
          Approx(1.0f).margin(1e-5));  // the wall's back faces the camera: |N . V| = 1

    auto bxdf = withIntegrator(
        "Integrator \"PxrVisualizer\" \"v\" \"string style\" [\"bxdf\"] \"int wireframe\" [0]");
    auto reference = withIntegrator("Integrator \"PxrDefault\" \"d\"");
    CHECK_FALSE(bxdf.anyMessageContains("tessellation"));
    CHECK(bxdf.channel(8, 8, 0) == Approx(reference.channel(8, 8, 0)).epsilon(1e-5));
    CHECK(bxdf.channel(10, 8, 0) == Approx(reference.channel(10, 8, 0)).epsilon(1e-5));

    // The sphere is turned -90 degrees about x: the normal facing the camera, (0, 0, -1) in the world,
    // is (0, 1, 0) in the sphere's own space.
    auto normals = withIntegrator("Integrator \"PxrVisualizer\" \"v\" \"string style\" [\"normals\"]");
    CHECK(normals.channel(8, 8, 0) == Approx(0.5f).margin(0.1));
    CHECK(normals.channel(8, 8, 1) > 0.95f);
    CHECK(normals.channel(8, 8, 2) == Approx(0.5f).margin(0.1));

    auto flat = withIntegrator("Integrator \"PxrVisualizer\" \"v\" \"string style\" [\"flat\"]");
    float const sphere = flat.channel(8, 8, 0) + 2 * flat.channel(8, 8, 1), wall = flat.channel(0, 0, 0) + 2 * flat.channel(0, 0, 1);
    CHECK(std::fabs(sphere - wall) > 0.1f);  // two Bxdf statements, two colours

    auto matcap = withIntegrator("Integrator \"PxrVisualizer\" \"v\" \"string style\" [\"matcap\"]");
    CHECK(matcap.anyMessageContains("shown as style shaded"));
    CHECK(matcap.channel(10, 8, 0) == Approx(shaded.channel(10, 8, 0)).epsilon(1e-6));

    // The patch's front (the side its normal points to) faces away from the camera: the check paints it
    // orange.
    auto check = withIntegrator(
        "Integrator \"PxrVisualizer\" \"v\" \"string style\" [\"st\"] \"int normalCheck\" [1]");
    CHECK(check.channel(0, 0, 0) == Approx(1.0f));
    CHECK(check.channel(0, 0, 1) == Approx(0.5f));
    CHECK(check.channel(0, 0, 2) == Approx(0.0f));
    CHECK_THROWS_WITH(withIntegrator("Integrator \"PxrVisualizer\" \"v\" \"string style\" [\"wire\"]"),
                      Catch::Matchers::Contains("unknown style \"wire\""));
}

namespace {

/// A point light at the centre of a closed sphere of radius 5 with Lambertian walls of
/// albedo 0.5 (the probe Bxdf `probe`), seen from inside. Every wall point gets the
/// irradiance pi I / R^2 from the light (a classic light's intensity is pi times its
/// radiant intensity, see LightFactory.cpp), and a wall of radiance L gives every other
/// wall point the irradiance pi L: a path of k surfaces adds 0.5^k I / R^2. With
/// I = 2 R^2 the first surface is 1, so maxPathLength 3 gives 1 + 0.5 + 0.25.
/// `integrator` is rendered with maxPathLength 3.
/// `walls` replaces the one Sphere with other shapes (and attributes), and `traceDepth` is
/// written before WorldBegin (by default, RenderMan's bounce limits out of the way).
std::string pointLitSphere(std::string const& integrator, std::string const& bxdf,
                           std::string const& walls = "  Sphere 5 -5 5 360\n",
                           std::string const& traceDepth = test::kDeepTraceDepth) {
    std::string const options = "Format 16 16 1\nProjection \"perspective\" \"fov\" [60]\nIntegrator \"" +
                                integrator + "\" \"i\" \"int maxPathLength\" [3]\n" + traceDepth;
    std::string const material = "  Bxdf \"" + bxdf + "\" \"walls\"\n";
    return options +
           "Translate 0 0 -2.5\n"
           "WorldBegin\n"
           "  LightSource \"pointlight\" 1 \"intensity\" [50] \"from\" [0 0 0]\n" +
           material + walls + "WorldEnd\n";
}

/// Half the mean squared difference of two renders with different seeds (red channel):
/// the variance of one, per pixel.
double noise(test::RenderOutcome const& a, test::RenderOutcome const& b) {
    double sum = 0.0;
    for (size_t k = 0; k < a.rgba.size(); k += 4) {
        double d = a.rgba[k] - b.rgba[k];
        sum += d * d;
    }
    return 0.5 * sum / static_cast<double>(a.rgba.size() / 4);
}

}  // namespace

TEST_CASE("PxrVCM furnace: a point light inside a diffuse sphere gives 1 + a + a^2", "[integrators][vcm]") {
    auto vcm = test::renderRib(pointLitSphere("PxrVCM", "probe"), test::withSpp(256));
    auto paths = test::renderRib(pointLitSphere("PxrPathTracer", "probe"), test::withSpp(256));
    CHECK(test::meanChannel(paths, 0, kAll) == Approx(1.75).epsilon(0.01));
    CHECK(test::meanChannel(vcm, 0, kAll) == Approx(1.75).epsilon(0.01));
    // The light subpaths are traced: more rays leave surfaces than the path tracer's.
    CHECK(vcm.stats.indirectRays > 2 * paths.stats.indirectRays);
    CHECK(vcm.stats.invalidPdfSamples == 0u);
}

TEST_CASE("PxrVCM reads an exporter's full parameter list, warning only where it does otherwise",
          "[integrators][vcm]") {
    // What exporters write for PxrVCM, at RenderMan's defaults (merging off, so mergeRadius and the like
    // do nothing; roulette changes noise, not the mean): the same image as without them, and no warning.
    std::string const defaults = "\"int connectPaths\" [1] \"int mergePaths\" [0] \"int numLightSamples\" [1] "
                                 "\"int numBxdfSamples\" [1] \"float specularCurvatureFilter\" [1] "
                                 "\"int rouletteDepth\" [4] \"float rouletteThreshold\" [0.2] \"int clampDepth\" [2] "
                                 "\"float mergeRadius\" [5] \"float timeRadius\" [1] \"float photonGuiding\" [0] "
                                 "\"point photonGuidingBBoxMin\" [1e30 1e30 1e30] "
                                 "\"point photonGuidingBBoxMax\" [-1e30 -1e30 -1e30] ";
    std::string const plainRib = pointLitSphere("PxrVCM", "probe");
    auto withParameters = [&](std::string const& parameters) {
        std::string rib = plainRib;
        std::string const handle = "\"PxrVCM\" \"i\" ";
        rib.insert(rib.find(handle) + handle.size(), parameters);
        return rib;
    };
    std::string const written = withParameters(defaults);
    auto plain = test::renderRib(plainRib, test::withSpp(4));
    auto exported = test::renderRib(written, test::withSpp(4));
    CHECK(exported.messages.empty());
    CHECK(exported.rgba == plain.rgba);
    // Clamping and other sample counts are not done here: said once each.
    auto warned = test::renderRib(withParameters("\"float clampLuminance\" [10] \"int numLightSamples\" [4] "),
                                  test::withSpp(4));
    CHECK(warned.anyMessageContains("clampLuminance is not applied"));
    CHECK(warned.anyMessageContains("numLightSamples 4: each camera vertex takes one light sample"));
    CHECK(warned.rgba == plain.rgba);
}

TEST_CASE("PxrPathTracer keeps RenderMan's per-object trace depths", "[integrators][pathtracer]") {
    // The point-lit sphere: a path of k surfaces adds 0.5^(k-1), every path alike, so each
    // value below is exact. maxPathLength 3 allows two bounces; the walls may allow fewer.
    auto mean = [](std::string const& walls, std::string const& traceDepth) {
        return test::meanChannel(
            test::renderRib(pointLitSphere("PxrPathTracer", "probe", walls, traceDepth), test::withSpp(16)),
            0, kAll);
    };
    std::string const sphere = "  Sphere 5 -5 5 360\n";
    auto diffuseDepth = [](int depth) {
        return "Attribute \"trace\" \"int maxdiffusedepth\" [" + std::to_string(depth) + "]\n";
    };
    CHECK(mean(sphere, "") == Approx(1.5).epsilon(1e-5));  // RenderMan's default: one diffuse bounce
    CHECK(mean(sphere, diffuseDepth(0)) == Approx(1.0).epsilon(1e-5));
    CHECK(mean(sphere, diffuseDepth(2)) == Approx(1.75).epsilon(1e-5));
    // The standard names need no type.
    CHECK(mean(sphere, "Attribute \"trace\" \"maxdiffusedepth\" 2\n") == Approx(1.75).epsilon(1e-5));
    // A surface's limit counts from the bounces a path has taken when it arrives, and never
    // raises the limit the path brings. The camera sees only the far half (z > 0); a first
    // bounce lands on either half with probability 1/2.
    auto halves = [](int seen, int unseen) {
        return "  AttributeBegin\n    Attribute \"trace\" \"int maxdiffusedepth\" [" + std::to_string(seen) +
               "]\n    Sphere 5 0 5 360\n  AttributeEnd\n"
               "  AttributeBegin\n    Attribute \"trace\" \"int maxdiffusedepth\" [" +
               std::to_string(unseen) + "]\n    Sphere 5 -5 0 360\n  AttributeEnd\n";
    };
    // The unseen half cannot lift the seen half's 1; paths that reach an unseen half of 0 stop there.
    CHECK(mean(halves(1, 5), "") == Approx(1.5).epsilon(1e-5));
    CHECK(mean(halves(2, 0), "") == Approx(1.625).epsilon(0.01));
    CHECK(mean(halves(2, 2), "") == Approx(1.75).epsilon(1e-5));
    // PxrUnified, for which the path tracer stands in, ignores them unless its useTraceDepth is 1.
    std::string unified = pointLitSphere("PxrUnified", "probe", sphere, "");
    CHECK(test::meanChannel(test::renderRib(unified, test::withSpp(16)), 0, kAll) == Approx(1.75).epsilon(1e-5));
    unified.replace(unified.find("[3]\n"), 4, "[3] \"int useTraceDepth\" [1]\n");
    CHECK(test::meanChannel(test::renderRib(unified, test::withSpp(16)), 0, kAll) == Approx(1.5).epsilon(1e-5));
}

TEST_CASE(
    "PxrPathTracer: a specular trace depth of 0 is direct lighting, and the diffuse one leaves specular "
    "bounces alone",
    "[integrators][pathtracer]") {
    std::string const rib = readScene("ch06/specular.rib");
    auto render = [&](std::string const& integrator) {
        std::string scene = withIntegrator(rib, integrator);
        scene.replace(scene.find("Format 800 700 1"), 16, "Format 80 70 1");
        return test::renderRib(scene, test::withSpp(4));
    };
    std::string const paths = "Integrator \"PxrPathTracer\" \"p\" \"int maxPathLength\" [4]\n";
    auto direct = render("Integrator \"PxrDirectLighting\" \"d\"");
    auto noSpecular = render(paths + "Attribute \"trace\" \"int maxspeculardepth\" [0]");
    CHECK(noSpecular.stats.indirectRays == 0u);  // every Bxdf sample is specular: none continues
    CHECK(noSpecular.rgba == direct.rgba);       // and the light they find is weighted as before
    auto noDiffuse = render(paths + "Attribute \"trace\" \"int maxdiffusedepth\" [0]");
    CHECK(noDiffuse.stats.indirectRays > 0u);
    CHECK(noDiffuse.rgba == render(paths).rgba);  // the specular lobe never met the diffuse limit
}

TEST_CASE("PxrVCM: a wrong RPdf biases a bidirectional image and leaves a path tracer's alone",
          "[integrators][vcm][heavy]") {
    // RPdf is only read to weigh the ways a path can be made; with the wrong one the
    // weights no longer add up to one for every path, and the furnace is off.
    auto vcm = test::renderRib(pointLitSphere("PxrVCM", "probe_forward_rpdf"), test::withSpp(1024));
    auto paths = test::renderRib(pointLitSphere("PxrPathTracer", "probe_forward_rpdf"), test::withSpp(1024));
    CHECK(test::meanChannel(paths, 0, kAll) == Approx(1.75).epsilon(0.01));
    CHECK(std::fabs(test::meanChannel(vcm, 0, kAll) - 1.75) > 0.02);  // measured: 1.718
}

TEST_CASE("PxrVCM and PxrPathTracer agree on a box lit through its ceiling", "[integrators][vcm][heavy]") {
    // The gold sphere throws glossy caustics on the walls: the path tracer must
    // be allowed them (without, it is 1.6% darker).
    std::string rib = readScene("ch11/box.rib");
    rib.replace(rib.find("Format 320 320 1"), 16, "Format 48 48 1");
    RenderSettings settings;
    settings.spp = 256;
    std::string const file = std::string(SCENES_DIR) + "/ch11/box.rib";  // its archive is found beside it
    auto vcm = test::renderRib(withIntegrator(rib, "Integrator \"PxrVCM\" \"v\" \"int maxPathLength\" [5]"), settings, file);
    auto paths =
        test::renderRib(withIntegrator(rib,
                                       "Integrator \"PxrPathTracer\" \"p\" \"int maxPathLength\" [5] "
                                       "\"int allowCaustics\" [1]\n" +
                                           std::string(test::kDeepTraceDepth)),
                        settings, file);
    for (int c = 0; c < 3; ++c)
        CHECK(test::meanChannel(vcm, c, kAll) == Approx(test::meanChannel(paths, c, kAll)).epsilon(0.006));
}

TEST_CASE("PxrVCM and PxrPathTracer agree where the camera sees a light in front of what it lights",
          "[integrators][vcm][heavy]") {
    // A light just in front of a lit wall: the camera sees the light (or, for a one-sided
    // light turned away, its dark back), never the bright wall behind it. Light subpaths
    // joined to the camera must be hidden by the light just as camera rays are; they were
    // not, and this scene came out 9% (sphere) to 39% (disk) too bright.
    for (char const* light : {"PxrSphereLight", "PxrDiskLight", "PxrCylinderLight"}) {
        CAPTURE(light);
        auto scene = [&](char const* integrator) {
            return std::string("Format 32 32 1\nProjection \"perspective\" \"fov\" [45]\n") + integrator +
                   "\nTranslate 0 0 4\nWorldBegin\n  AttributeBegin\n    Scale 0.6 0.6 0.6\n    Light \"" + light +
                   "\" \"l\" \"float intensity\" [8]\n  AttributeEnd\n"
                   "  Bxdf \"PxrDiffuse\" \"wall\" \"color diffuseColor\" [0.6 0.6 0.6]\n"
                   "  Polygon \"P\" [-5 -5 0.5  5 -5 0.5  5 5 0.5  -5 5 0.5]\nWorldEnd\n";
        };
        RenderSettings settings;
        settings.spp = 256;
        auto vcm = test::renderRib(scene("Integrator \"PxrVCM\" \"v\" \"int maxPathLength\" [2]"), settings);
        auto paths = test::renderRib(scene("Integrator \"PxrPathTracer\" \"p\" \"int maxPathLength\" [2]"), settings);
        CHECK(test::meanChannel(vcm, 0, kAll) == Approx(test::meanChannel(paths, 0, kAll)).epsilon(0.005));
    }
}

TEST_CASE("PxrVCM and PxrPathTracer agree on a ceiling above a light that faces down", "[integrators][vcm][heavy]") {
    // The ceiling is lit only by the sphere below the light, through the light's
    // place. Light subpaths stopped at the light's face, as camera paths that
    // reach a light do, though lights are no surface they can land on: the
    // ceiling above the light came out half as bright.
    std::string const rib =
        "Format 32 32 1\nProjection \"perspective\" \"fov\" [40]\nINTEGRATOR\nTranslate 0 0 5\nWorldBegin\n"
        "  AttributeBegin\n    Translate 0 1 0\n    Rotate 90 1 0 0\n    Attribute \"visibility\" \"int camera\" [0]\n"
        "    Light \"PxrRectLight\" \"l\" \"float intensity\" [5]\n  AttributeEnd\n"
        "  Bxdf \"PxrDiffuse\" \"w\" \"color diffuseColor\" [0.7 0.7 0.7]\n  Sphere 0.7 -0.7 0.7 360\n"
        "  Polygon \"P\" [-2 2 -2  2 2 -2  2 2 2  -2 2 2]\nWorldEnd\n";
    auto with = [&](std::string const& integrator) {
        std::string scene = rib;
        return scene.replace(scene.find("INTEGRATOR"), 10, integrator);
    };
    auto const [vcm, paths] = vcmAndPathTracer(with, 2, 4096, [](int, int y) { return y < 8; });  // the ceiling
    CHECK(paths > 0.005);
    CHECK(vcm == Approx(paths).epsilon(0.03));
}

TEST_CASE("PxrVCM and PxrPathTracer agree on a floor under a rect light: a light subpath does not stop at its own light",
          "[integrators][vcm]") {
    // Light subpaths leave the light's own plane; looking for lights in their way from
    // there found the light they leave, and the floor came out half as bright.
    auto scene = [](std::string const& integrator) {
        return "Format 24 24 1\nProjection \"perspective\" \"fov\" [30]\n" + integrator +
               "\nRotate -30 1 0 0\nTranslate 0 -1 8\nWorldBegin\n  AttributeBegin\n"
               "    Attribute \"visibility\" \"int camera\" [0]\n    Translate 0 -1 0\n    Rotate 90 1 0 0\n"
               "    Scale 3 3 1\n    Light \"PxrRectLight\" \"panel\" \"float intensity\" [1]\n  AttributeEnd\n"
               "  Bxdf \"PxrDiffuse\" \"white\" \"color diffuseColor\" [1 1 1]\n"
               "  Polygon \"P\" [-4 -2 -4  4 -2 -4  4 -2 4  -4 -2 4]\nWorldEnd\n";
    };
    auto const [vcm, paths] = vcmAndPathTracer(scene, 1, 256, kAll);
    CHECK(paths > 0.05);
    CHECK(vcm == Approx(paths).epsilon(0.02));
}

TEST_CASE("PxrVCM and PxrPathTracer agree on a room lit by a two-sided panel just under its ceiling",
          "[integrators][vcm][heavy]") {
    // Both faces of the panel are lit: a camera path from the ceiling that meets it ends
    // there, so a light path or a connection crossing the panel must be stopped too; they
    // were not, and the room came out 25% too bright.
    auto scene = [](std::string const& integrator) {
        return "Format 32 32 1\nProjection \"perspective\" \"fov\" [40]\n" + integrator +
               "\nTranslate 0 0 5\nWorldBegin\n  AttributeBegin\n    Translate 0 1.9 0\n    Rotate 90 1 0 0\n"
               "    Attribute \"visibility\" \"int camera\" [0]\n"
               "    Light \"PxrMeshLight\" \"panel\" \"float intensity\" [5]\n"
               "    Polygon \"P\" [-0.5 -0.5 0  0.5 -0.5 0  0.5 0.5 0  -0.5 0.5 0]\n  AttributeEnd\n"
               "  Bxdf \"PxrDiffuse\" \"w\" \"color diffuseColor\" [0.7 0.7 0.7]\n"
               "  Polygon \"P\" [-2 -2 -2  2 -2 -2  2 -2 2  -2 -2 2]\n  Polygon \"P\" [-2 2 -2  2 2 -2  2 2 2  -2 2 2]\n"
               "  Polygon \"P\" [-2 -2 2  2 -2 2  2 2 2  -2 2 2]\n  Sphere 0.7 -0.7 0.7 360\nWorldEnd\n";
    };
    auto const [vcm, paths] = vcmAndPathTracer(scene, 3, 1024, kAll);
    CHECK(vcm == Approx(paths).epsilon(0.02));
}

TEST_CASE("PxrVCM renders a caustic as a path tracer does, and finds it from a small light",
          "[integrators][vcm][heavy]") {
    std::string scene = readScene("ch04/caustic.rib");
    scene.replace(scene.find("Format 320 240 1"), 16, "Format 64 48 1");
    auto pathTracer = [](std::string const& rib) {
        return withIntegrator(
            rib, "Integrator \"PxrPathTracer\" \"p\" \"int maxPathLength\" [6] \"int allowCaustics\" [1]\n" +
                     std::string(test::kDeepTraceDepth));
    };
    RenderSettings settings;
    // The same picture: with a larger light (the same power), the path tracer's
    // reference converges in a test's time, and both agree.
    std::string large = scene;
    large.replace(large.find("Scale 0.3 0.3 0.3"), 17, "Scale 0.8 0.8 0.8");
    large.replace(large.find("[400]"), 5, "[56.25]");
    settings.spp = 128;
    auto vcm = test::renderRib(large, settings);
    settings.spp = 2048;
    auto reference = test::renderRib(pathTracer(large), settings);
    CHECK(test::meanChannel(vcm, 0, kAll) == Approx(test::meanChannel(reference, 0, kAll)).epsilon(0.02));
    // With the scene's own small light, the path tracer finds the caustic only when a
    // path through the ball happens to hit the light; the light subpaths find it at
    // once: at 64 samples two seeds of the bidirectional render agree, and its noise
    // is well below the path tracer's.
    settings.spp = 64;
    settings.seed = 0;
    auto a = test::renderRib(scene, settings), b = test::renderRib(pathTracer(scene), settings);
    settings.seed = 1;
    auto a2 = test::renderRib(scene, settings), b2 = test::renderRib(pathTracer(scene), settings);
    CHECK(test::meanChannel(a, 0, kAll) == Approx(test::meanChannel(a2, 0, kAll)).epsilon(0.03));
    CHECK(noise(a, a2) < 0.75 * noise(b, b2));  // measured: 0.089 against 0.158
}

TEST_CASE("a Bxdf's evaluation domain is kept: no light through a reflecting surface where its shading normal bends",
          "[integrators][domain]") {
    // A square faces the camera, its shading normals bent 30 degrees toward +x; a
    // point light behind it, off to +x, is above the shading normal's horizon
    // and below the geometric one's. A Bxdf that declares reflection only
    // (k_RixBXReflect) gets no light from it, whether or not it tests the
    // geometric normal itself (bookdiffuse, written as the course text writes
    // it, does not). The same light in front of the square lights it.
    auto scene = [](std::string const& bxdf, std::string const& integrator, float lightZ) {
        return "Format 8 8 1\nProjection \"perspective\" \"fov\" [20]\n" + integrator +
               "\nWorldBegin\n  Translate 0 0 5\n"
               "  LightSource \"pointlight\" 1 \"from\" [3 0 " + std::to_string(lightZ) + "] \"intensity\" [20]\n"
               "  Bxdf \"" + bxdf + "\" \"m\"\n"
               "  Polygon \"P\" [-1 -1 0  1 -1 0  1 1 0  -1 1 0]\n"
               "          \"N\" [0.5 0 -0.866  0.5 0 -0.866  0.5 0 -0.866  0.5 0 -0.866]\n"
               "WorldEnd\n";
    };
    for (std::string integrator : {"Integrator \"PxrDirectLighting\" \"d\"", "Integrator \"PxrPathTracer\" \"p\""})
        for (std::string bxdf : {"bookdiffuse", "diffuse"}) {
            INFO(integrator << ", " << bxdf);
            RenderSettings settings;
            settings.spp = 16;
            auto behind = test::renderRib(scene(bxdf, integrator, 0.6f), settings);
            auto inFront = test::renderRib(scene(bxdf, integrator, -0.6f), settings);
            CHECK(test::meanChannel(behind, 0, kAll) == 0.0);
            CHECK(test::meanChannel(inFront, 0, kAll) > 0.05);
        }
}

TEST_CASE("an integrator may ask the batch it traces from for builtins and memory inside TraceIndirect's callback",
          "[integrators][memory]") {
    // A floor facing the camera and a wall behind the camera facing the floor: every floor point's
    // ray toward the viewer is shaded on the wall while the floor's batch is still open. The test
    // integrator paints a pixel white when what it took from the floor's batch there outlived the
    // callback, red when it changed, blue when there was nothing to shade.
    std::string const rib = "Format 16 16 1\nProjection \"orthographic\"\nScreenWindow -1 1 -1 1\n"
                            "Integrator \"parentmemory\" \"test\"\nTranslate 0 0 5\nWorldBegin\n"
                            "Bxdf \"PxrDiffuse\" \"d\"\n"
                            "Polygon \"P\" [-2 -2 0  2 -2 0  2 2 0  -2 2 0]\n"
                            "Polygon \"P\" [-9 -9 -6  9 -9 -6  9 9 -6  -9 9 -6]\nWorldEnd\n";
    test::RenderOutcome const image = test::renderRib(rib, test::withSpp(2));
    REQUIRE(image.width == 16);
    int white = 0, red = 0, blue = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            float const r = image.channel(x, y, 0), g = image.channel(x, y, 1), b = image.channel(x, y, 2);
            white += r == 1.0f && g == 1.0f && b == 1.0f;
            red += r > 0.0f && g == 0.0f && b == 0.0f;
            blue += r == 0.0f && g == 0.0f && b > 0.0f;
        }
    CHECK(blue == 0);  // every floor point's ray was shaded on the wall
    CHECK(red == 0);
    CHECK(white == 16 * 16);
}
