// "Simulate only what the scene calls for", proven by the counters.
#include <catch2/catch.hpp>

#include <algorithm>

#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {
std::string sceneWith(std::string const& bxdf, std::string const& lights,
                      std::string const& integrator = "Integrator \"PxrDirectLighting\" \"d\"\n") {
    return "Format 24 24 1\nProjection \"perspective\" \"fov\" [20]\n" + integrator +
           "WorldBegin\n" + lights + "  Translate 0 0 5\n  " + bxdf + "\n  Sphere 1 -1 1 360\nWorldEnd\n";
}
const std::string kDiskLight =
    "  AttributeBegin\n  Translate 0 3 5\n  Rotate 90 1 0 0\n"
    "  Light \"PxrDiskLight\" \"key\" \"float intensity\" [20]\n  AttributeEnd\n";

bool skipped(RenderStats const& stats, std::string const& effect) {
    for (auto const& [name, reason] : stats.effects.skipped)
        if (name.find(effect) != std::string::npos || reason.find(effect) != std::string::npos) return true;
    return false;
}
}  // namespace

TEST_CASE("an emissive-only scene casts no shadow rays, even with a light present", "[effects]") {
    auto r = test::renderRib(sceneWith("Bxdf \"emissive\" \"glow\" \"color emissiveColor\" [2 2 2]", kDiskLight));
    CHECK(r.stats.cameraRays == 24u * 24u * 16u);
    CHECK(r.stats.shadowRays == 0u);
    CHECK(r.stats.indirectRays == 0u);
    CHECK(r.stats.shadePoints > 0u);
    CHECK(r.channel(12, 12, 0) == 2.0f);  // EmitLocal only
}

TEST_CASE("a scene without lights skips light sampling and casts no shadow rays", "[effects]") {
    auto r = test::renderRib(sceneWith("Bxdf \"diffuse\" \"d\"", ""));
    CHECK(r.stats.shadowRays == 0u);
    CHECK(skipped(r.stats, "light sampling"));
    CHECK(r.channel(12, 12, 0) == 0.0f);
}

TEST_CASE("direct lighting casts shadow rays but never indirect rays", "[effects]") {
    auto r = test::renderRib(sceneWith("Bxdf \"diffuse\" \"d\"", kDiskLight));
    CHECK(r.stats.shadowRays > 0u);
    CHECK(r.stats.indirectRays == 0u);
    CHECK(skipped(r.stats, "indirect rays"));
}

TEST_CASE("tangent frames are computed only when a plugin asks for them", "[effects]") {
    auto plain = test::renderRib(sceneWith("Bxdf \"diffuse\" \"d\"", kDiskLight));
    CHECK(plain.stats.tangentPoints == 0u);
    CHECK(plain.stats.surfacePoints > 0u);
    CHECK(skipped(plain.stats, "tangent frames"));
    auto asking = test::renderRib(sceneWith("Bxdf \"probe_tangents\" \"t\"", kDiskLight));
    CHECK(asking.stats.tangentPoints == asking.stats.shadePoints);
    CHECK_FALSE(skipped(asking.stats, "tangent frames"));
}

TEST_CASE("surface parameters (u, v, s, t) are computed only when a plugin or pattern asks for them", "[effects]") {
    auto plain = test::renderRib(sceneWith("Bxdf \"diffuse\" \"d\"", kDiskLight));
    CHECK(plain.stats.parameterPoints == 0u);
    CHECK(plain.stats.surfacePoints > 0u);
    // A colour from v: the sphere's top (v near 1) lit brighter than its bottom half would be.
    auto asking = test::renderRib(sceneWith("Pattern \"PxrVariable\" \"height\" \"string variable\" [\"v\"]\n"
                                            "  Bxdf \"diffuse\" \"d\" \"reference color diffuseColor\" [\"height:resultRGB\"]",
                                            kDiskLight));
    CHECK(asking.stats.parameterPoints == asking.stats.shadePoints);
    CHECK(asking.stats.tangentPoints == 0u);  // the groups are apart
    double plainSum = 0.0, askingSum = 0.0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            plainSum += plain.channel(x, y, 0);
            askingSum += asking.channel(x, y, 0);
        }
    CHECK(askingSum > 0.2 * plainSum);  // v in (0, 1) darkens the white sphere, and v near 1 where the light is
    CHECK(askingSum < 0.99 * plainSum);
}

TEST_CASE("lights with zero intensity and objects invisible to all rays are dropped at load", "[effects]") {
    std::string lights = kDiskLight +
                         "  Light \"PxrSphereLight\" \"off\" \"float intensity\" [0]\n"
                         "  AttributeBegin\n  Attribute \"visibility\" \"int camera\" [0] \"int indirect\" [0]"
                         " \"int transmission\" [0]\n  Sphere 1 -1 1 360\n  AttributeEnd\n";
    auto r = test::renderRib(sceneWith("Bxdf \"diffuse\" \"d\"", lights));
    CHECK(skipped(r.stats, "zero intensity"));
    CHECK(skipped(r.stats, "invisible to every ray type"));
}

TEST_CASE("presence work is skipped when no Bxdf computes it", "[effects]") {
    auto r = test::renderRib(sceneWith("Bxdf \"diffuse\" \"d\"", kDiskLight));
    CHECK(skipped(r.stats, "presence"));
    CHECK(r.stats.presencePoints == 0u);
    // PxrDiffuse's presence left at 1 asks for nothing either.
    auto full = test::renderRib(sceneWith("Bxdf \"PxrDiffuse\" \"d\" \"float presence\" [1]", kDiskLight));
    CHECK(skipped(full.stats, "presence"));
}

TEST_CASE("PxrDefault lights an unlit scene with a headlight and samples no Bxdf", "[effects]") {
    auto r = test::renderRib(sceneWith("Bxdf \"diffuse\" \"d\" \"color diffuseColor\" [1 1 1]", "", ""));
    CHECK(r.stats.integrator == "PxrDefault");
    // A white Lambertian facing the camera at the centre has radiance ~1 under the headlight.
    CHECK(r.channel(12, 12, 0) == Approx(1.0f).epsilon(0.02));
    CHECK(skipped(r.stats, "bxdf sampling"));
    CHECK_FALSE(r.anyMessageContains("not used"));  // no lights to leave unused

    // With lights of its own, the scene is still lit from the camera, and a note says how to use them.
    auto lit = test::renderRib(sceneWith("Bxdf \"diffuse\" \"d\" \"color diffuseColor\" [1 1 1]", kDiskLight, ""));
    CHECK(lit.channel(12, 12, 0) == Approx(r.channel(12, 12, 0)));
    CHECK(lit.anyMessageContains("the scene names no Integrator, so PxrDefault lights it from the camera, as in "
                                 "RenderMan, and its light is not used; Integrator \"PxrDirectLighting\""));

    // A light this renderer cannot render leaves only the headlight, and a note says that it lights the image.
    auto unrenderable = test::renderRib(
        sceneWith("Bxdf \"diffuse\" \"d\" \"color diffuseColor\" [1 1 1]", "LightSource \"envlight\" \"e\"\n", ""));
    CHECK(unrenderable.channel(12, 12, 0) == Approx(r.channel(12, 12, 0)));
    CHECK(unrenderable.anyMessageContains("the scene's one light is not one this renderer can render, so it is lit "
                                          "from the camera only"));
    CHECK_FALSE(r.anyMessageContains("lit from the camera only"));  // a scene without lights asks for the headlight
}

TEST_CASE("motion blur is simulated only when something moves while the shutter is open", "[effects][motion]") {
    auto still = test::renderRib(sceneWith("Bxdf \"diffuse\" \"d\"", kDiskLight));
    CHECK(skipped(still.stats, "the shutter does not open"));
    auto open = test::renderRib("Shutter 0 1\n" + sceneWith("Bxdf \"diffuse\" \"d\"", kDiskLight));
    CHECK(skipped(open.stats, "nothing in the scene moves"));
    auto moving = test::renderRib(
        "Shutter 0 1\n" + sceneWith("Bxdf \"diffuse\" \"d\"\n  MotionBegin [0 1]\n  Translate 0 0 0\n  Translate 0.2 0 0\n"
                                    "  MotionEnd",
                                    kDiskLight));
    CHECK_FALSE(skipped(moving.stats, "motion blur"));
    CHECK(std::count(moving.stats.effects.simulated.begin(), moving.stats.effects.simulated.end(),
                     "motion blur: 1 shape moves while the shutter is open") == 1);
}
