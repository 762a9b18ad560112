// Numerical robustness of the renderer: no shadow acne, no light leaks,
// non-finite values never reach the image, and the variance output.
#include <catch2/catch.hpp>
#include <cmath>

#include "support/RenderHelpers.h"

using namespace bxdflab;

TEST_CASE("no shadow acne: every visible point of a sphere lit from the camera side is lit", "[spawn]") {
    // The light travels along +z (from behind the camera), so N.L > 0 wherever the camera sees the sphere.
    std::string rib =
        "Format 64 64 1\nProjection \"perspective\" \"fov\" [20]\n"
        "Integrator \"PxrDirectLighting\" \"d\"\n"
        "WorldBegin\n"
        "  AttributeBegin\n"
        "  Light \"PxrDistantLight\" \"sun\" \"float intensity\" [50000] \"float angleExtent\" [0]\n  AttributeEnd\n"
        "  Translate 0.3 -0.2 1000\n  Scale 150 150 150\n"  // far away and large: a hard case for offsets
        "  Bxdf \"diffuse\" \"d\"\n  Sphere 1 -1 1 360\nWorldEnd\n";
    RenderSettings settings;
    settings.spp = 2;
    auto r = test::renderRib(rib, settings);
    int covered = 0;
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x)
            if (r.channel(x, y, 3) == 1.0f) {
                ++covered;
                REQUIRE(r.channel(x, y, 0) > 0.0f);
            }
    CHECK(covered > 1000);
}

TEST_CASE("no light leaks: closed surfaces and thin walls stop light completely", "[spawn]") {
    std::string const head = "Format 16 16 1\nProjection \"perspective\" \"fov\" [60]\nIntegrator \"PxrDirectLighting\" \"d\"\n";
    SECTION("camera inside a closed sphere, light outside") {
        auto r = test::renderRib(head +
                                 "WorldBegin\n  AttributeBegin\n  Translate 0 0 20\n"
                                 "  Light \"PxrSphereLight\" \"out\" \"float intensity\" [1000]\n  AttributeEnd\n"
                                 "  Bxdf \"diffuse\" \"d\"\n  Sphere 5 -5 5 360\nWorldEnd\n");
        CHECK(test::meanChannel(r, 0, [](int, int) { return true; }) == 0.0);
    }
    SECTION("a light just behind a thin wall does not light its front") {
        auto r = test::renderRib(head +
                                 "WorldBegin\n  AttributeBegin\n  Attribute \"visibility\" \"int camera\" [0]\n"
                                 "  Translate 0 0 5.001\n  Rotate 180 1 0 0\n  Scale 4 4 1\n"
                                 "  Light \"PxrRectLight\" \"behind\" \"float intensity\" [1000]\n  AttributeEnd\n"
                                 "  Bxdf \"diffuse\" \"d\"\n  Polygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\n"
                                 "WorldEnd\n");
        CHECK(test::meanChannel(r, 0, [](int, int) { return true; }) == 0.0);
    }
    SECTION("the same light in front of the wall does light it (the test can fail)") {
        auto r = test::renderRib(head +
                                 "WorldBegin\n  AttributeBegin\n  Attribute \"visibility\" \"int camera\" [0]\n"
                                 "  Translate 0 0 4.5\n  Scale 4 4 1\n"
                                 "  Light \"PxrRectLight\" \"front\" \"float intensity\" [10]\n  AttributeEnd\n"
                                 "  Bxdf \"diffuse\" \"d\"\n  Polygon \"P\" [-10 -10 5  10 -10 5  10 10 5  -10 10 5]\n"
                                 "WorldEnd\n");
        CHECK(test::meanChannel(r, 0, [](int, int) { return true; }) > 0.1);
    }
}

TEST_CASE("non-finite Bxdf values are counted, reported and kept out of the image", "[nonfinite]") {
    std::string rib =
        "Format 16 16 1\nProjection \"perspective\" \"fov\" [30]\nIntegrator \"PxrDirectLighting\" \"d\"\n"
        "WorldBegin\n  AttributeBegin\n  Translate 0 2 4\n  Rotate 90 1 0 0\n"
        "  Light \"PxrDiskLight\" \"key\" \"float intensity\" [20]\n  AttributeEnd\n"
        "  Translate 0 0 5\n  Bxdf \"probe_nan\" \"broken\"\n  Sphere 1 -1 1 360\nWorldEnd\n";
    auto r = test::renderRib(rib);
    CHECK(r.stats.nonFiniteSamples > 0u);
    for (float v : r.rgba) REQUIRE(std::isfinite(v));
    CHECK(r.anyMessageContains("non-finite"));
    // Points whose values were fine still contribute light.
    CHECK(test::meanChannel(r, 0, [](int, int) { return true; }) > 0.0);
}

TEST_CASE("pdfs a Bxdf must not return are counted, reported and never used", "[nonfinite]") {
    // probe_negative_pdf returns FPdf < 0 on odd points from GenerateSample and EvaluateSample.
    std::string const scene =
        "Format 16 16 1\nProjection \"perspective\" \"fov\" [30]\nINTEGRATOR\n"
        "WorldBegin\n  AttributeBegin\n  Translate 0 2 4\n  Rotate 90 1 0 0\n"
        "  Light \"PxrDiskLight\" \"key\" \"float intensity\" [20]\n  AttributeEnd\n"
        "  Translate 0 0 5\n  Bxdf \"BXDF\" \"b\"\n  Sphere 1 -1 1 360\nWorldEnd\n";
    auto rib = [&](std::string const& integrator, std::string const& bxdf) {
        std::string text = scene;
        text.replace(text.find("INTEGRATOR"), 10, integrator);
        return text.replace(text.find("BXDF"), 4, bxdf);
    };
    for (std::string integrator : {"Integrator \"PxrDirectLighting\" \"d\"", "Integrator \"PxrPathTracer\" \"p\""}) {
        CAPTURE(integrator);
        auto broken = test::renderRib(rib(integrator, "probe_negative_pdf"));
        auto sound = test::renderRib(rib(integrator, "probe"));
        CHECK(broken.stats.invalidPdfSamples > 0u);
        CHECK(sound.stats.invalidPdfSamples == 0u);
        CHECK(broken.anyMessageContains("pdf a Bxdf must not return"));
        for (float v : broken.rgba) REQUIRE(std::isfinite(v));
        // The points whose pdfs were fine still reflect light.
        CHECK(test::meanChannel(broken, 0, [](int, int) { return true; }) > 0.0);
    }
}

TEST_CASE("the variance image estimates the variance of each pixel mean", "[film]") {
    std::string rib =
        "Format 16 16 1\nProjection \"perspective\" \"fov\" [30]\nIntegrator \"PxrDirectLighting\" \"d\"\n"
        "WorldBegin\n  AttributeBegin\n  Translate 0 2 4\n  Rotate 90 1 0 0\n"
        "  Light \"PxrDiskLight\" \"key\" \"float intensity\" [20]\n  AttributeEnd\n"
        "  AttributeBegin\n  Translate -1.2 0 5\n  Bxdf \"emissive\" \"e\"\n  Sphere 1 -1 1 360\n  AttributeEnd\n"
        "  Translate 1.2 0 5\n  Bxdf \"diffuse\" \"d\"\n  Sphere 1 -1 1 360\nWorldEnd\n";
    RenderSettings settings;
    settings.spp = 16;
    auto low = test::renderRib(rib, settings);
    settings.spp = 64;
    auto high = test::renderRib(rib, settings);
    auto variance = [](test::RenderOutcome const& r, int x, int y) { return r.variance[3 * (static_cast<size_t>(y) * r.width + x)]; };
    // A constant emitter has no noise at all...
    CHECK(variance(low, 4, 8) == 0.0f);
    CHECK(low.channel(4, 8, 0) == 1.0f);
    // ...a lit diffuse surface has some, and 4x the samples cut it about 4x.
    double sumLow = 0, sumHigh = 0;
    for (int y = 4; y < 12; ++y)
        for (int x = 10; x < 14; ++x) {
            sumLow += variance(low, x, y);
            sumHigh += variance(high, x, y);
        }
    REQUIRE(sumLow > 0.0);
    CHECK(sumLow / sumHigh > 2.5);
    CHECK(sumLow / sumHigh < 6.5);
}

TEST_CASE("an exception from a plugin names the plugin, its Bxdf statement and the shared object", "[errors][plugins]") {
    std::string rib =
        "Format 8 8 1\nProjection \"perspective\" \"fov\" [30]\nIntegrator \"PxrPathTracer\" \"p\"\n"
        "WorldBegin\n  Light \"PxrDomeLight\" \"sky\"\n  Translate 0 0 5\n  Bxdf \"probe_throws\" \"thrower\"\n"
        "  Sphere 1 -1 1 360\nWorldEnd\n";
    try {
        test::renderRib(rib, {}, "thrower.rib");
        FAIL("expected the plugin's exception to stop the render");
    } catch (PluginFault const& e) {
        std::string message = e.what();
        CHECK_THAT(message, Catch::Matchers::Contains("plugin \"probe_throws\""));
        CHECK_THAT(message, Catch::Matchers::Contains("Bxdf \"thrower\" at thrower.rib:7:3"));
        CHECK_THAT(message, Catch::Matchers::Contains("probe_throws.so"));
        CHECK_THAT(message, Catch::Matchers::Contains("probe: GenerateSample gave up"));
    }
}
