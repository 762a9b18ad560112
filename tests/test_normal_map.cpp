// PxrNormalMap and PxrBump bend PxrDisney's shading normal: by the angle the
// map encodes (or the height map's slope), toward +dPdu for red and +dPdv for
// green, with RenderMan's flips, from an image or a connected colour, and
// through the PxrSurface stand-in.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/ImageFiles.h"
#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {

// A 16 x 16 orthographic view of the square [-1,1]^2 at z = 5, seen from its
// outside: its normal dPdu x dPdv points at the camera, with u along +x and v
// along -y. A diffuse-only PxrDisney (no specular: every pixel is its diffuse
// term), so a bent normal shows as a change of cosine.
std::string const kHead = "Format 16 16 1\nProjection \"orthographic\"\nScreenWindow -1 1 -1 1\n"
                          "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\n";
std::string const kSquare = "Translate 0 0 5\nPatch \"bilinear\" \"P\" [-1 1 0  1 1 0  -1 -1 0  1 -1 0]\n";
// A delta light travelling along +z, as the camera looks: L = V everywhere.
std::string const kHeadlight = "Light \"PxrDistantLight\" \"sun\" \"float intensity\" [50000] \"float angleExtent\" [0]\n";
std::string const kDisney = "\"color baseColor\" [1 1 1] \"float specular\" [0] \"float roughness\" [0.5]";

std::string bxdf(std::string const& extra = "") { return "Bxdf \"PxrDisney\" \"paint\" " + kDisney + extra + "\n"; }
std::string bumped(std::string const& normalMap) {
    return "Pattern \"PxrNormalMap\" \"bumps\" " + normalMap + "\n" +
           bxdf(" \"reference normal bumpNormal\" [\"bumps:resultN\"]");
}

/// The encoded colour of a tangent-space normal tilted by `degrees` along its x axis.
std::string tiltedAlongX(double degrees) {
    double const a = degrees * M_PI / 180.0;
    return "\"color inputRGB\" [" + std::to_string(0.5 * (std::sin(a) + 1.0)) + " 0.5 " +
           std::to_string(0.5 * (std::cos(a) + 1.0)) + "]";
}

RenderSettings samples(int spp) {
    RenderSettings settings;
    settings.spp = spp;
    return settings;
}

bool sameImage(test::RenderOutcome const& a, test::RenderOutcome const& b) { return a.rgba == b.rgba; }

}  // namespace

TEST_CASE("a normal map tilts PxrDisney's shading normal by the angle it encodes", "[patterns][normalmap]") {
    auto flat = test::renderRib(kHead + kHeadlight + bxdf() + kSquare, samples(4));
    float const facing = flat.channel(8, 8, 0);
    REQUIRE(facing > 0.0f);
    for (double degrees : {20.0, 45.0, 70.0}) {
        CAPTURE(degrees);
        auto tilted = test::renderRib(kHead + kHeadlight + bumped(tiltedAlongX(degrees)) + kSquare, samples(4));
        // L = V = the unbent normal, so cos_L = cos_V = cos(tilt) and L.H = 1: Burley's
        // diffuse is baseColor / pi * F_d cos_L with F_d = (1 + (F_D90 - 1)(1 - cos)^5)^2,
        // F_D90 = 0.5 + 2 roughness. Facing the light, cos = 1 and F_d = 1.
        double const c = std::cos(degrees * M_PI / 180.0);
        double const fd = std::pow(1.0 + 0.5 * std::pow(1.0 - c, 5.0), 2.0);
        for (int x : {2, 8, 13}) CHECK(tilted.channel(x, 8, 0) / facing == Approx(c * fd).epsilon(1e-4));
    }
    SECTION("the flat colour (0.5, 0.5, 1), bumpScale 0 and disable leave the shading as it was") {
        for (std::string const& map : {std::string("\"color inputRGB\" [0.5 0.5 1]"),
                                       tiltedAlongX(40.0) + " \"float bumpScale\" [0]",
                                       tiltedAlongX(40.0) + " \"int disable\" [1]"}) {
            CAPTURE(map);
            auto r = test::renderRib(kHead + kHeadlight + bumped(map) + kSquare, samples(4));
            CHECK(r.channel(8, 8, 0) == Approx(facing).epsilon(1e-5));
        }
    }
    SECTION("bumpScale scales the tilt's tangent part, surfaceNormalMix blends it back") {
        // Encoded (sin 40, 0, cos 40) with bumpScale b: tan(tilt) = b tan(40 degrees).
        auto half = test::renderRib(kHead + kHeadlight + bumped(tiltedAlongX(40.0) + " \"float bumpScale\" [0.5]") +
                                        kSquare,
                                    samples(4));
        double const c = std::cos(std::atan(0.5 * std::tan(40.0 * M_PI / 180.0)));
        double const fd = std::pow(1.0 + 0.5 * std::pow(1.0 - c, 5.0), 2.0);
        CHECK(half.channel(8, 8, 0) / facing == Approx(c * fd).epsilon(1e-4));
        auto mixed = test::renderRib(
            kHead + kHeadlight + bumped(tiltedAlongX(40.0) + " \"float surfaceNormalMix\" [1]") + kSquare, samples(4));
        CHECK(mixed.channel(8, 8, 0) == Approx(facing).epsilon(1e-5));
    }
}

TEST_CASE("a normal map's red bends toward +dPdu, its green toward +dPdv, with RenderMan's flips",
          "[patterns][normalmap]") {
    // A small sphere light off to one side: the normal bent toward it brightens the square.
    auto lightAt = [](char const* where) {
        return std::string("AttributeBegin\nTranslate ") + where +
               "\nScale 0.2 0.2 0.2\nLight \"PxrSphereLight\" \"bulb\" \"float intensity\" [400]\nAttributeEnd\n";
    };
    auto render = [&](char const* where, std::string const& map) {
        return test::renderRib(kHead + lightAt(where) + (map.empty() ? bxdf() : bumped(map)) + kSquare, samples(16));
    };
    std::string const towardU = "\"color inputRGB\" [0.75 0.5 0.93]", awayFromU = "\"color inputRGB\" [0.25 0.5 0.93]";
    std::string const towardV = "\"color inputRGB\" [0.5 0.75 0.93]", awayFromV = "\"color inputRGB\" [0.5 0.25 0.93]";
    std::string const openGL = " \"int orientation\" [0]", directX = " \"int orientation\" [1]";
    SECTION("OpenGL: red toward +u (+x here), where the light is") {
        auto flat = render("3 0 4", "");
        CHECK(render("3 0 4", towardU + openGL).channel(8, 8, 0) > 1.2f * flat.channel(8, 8, 0));
        CHECK(render("3 0 4", awayFromU + openGL).channel(8, 8, 0) < 0.8f * flat.channel(8, 8, 0));
    }
    SECTION("OpenGL: green toward +v (-y here) with invertT (the default), toward -v without") {
        auto flat = render("0 -3 4", "");
        CHECK(render("0 -3 4", towardV + openGL).channel(8, 8, 0) > 1.2f * flat.channel(8, 8, 0));
        CHECK(render("0 -3 4", towardV + openGL + " \"int invertT\" [0]").channel(8, 8, 0) <
              0.8f * flat.channel(8, 8, 0));
    }
    SECTION("DirectX's green runs the other way; RenderMan's own frame (the default) is OpenGL's with red reversed") {
        CHECK(sameImage(render("0 -3 4", towardV + directX), render("0 -3 4", awayFromV + openGL)));
        CHECK(sameImage(render("3 0 4", towardU + directX), render("3 0 4", towardU + openGL)));
        CHECK(sameImage(render("3 0 4", towardU), render("3 0 4", awayFromU + openGL)));
        CHECK(sameImage(render("0 -3 4", towardV), render("0 -3 4", towardV + openGL)));
        // As RenderMan documents its orientations: OpenGL is invertBump with flipY, DirectX invertBump.
        CHECK(sameImage(render("3 0 4", "\"color inputRGB\" [0.75 0.625 0.9]" + openGL),
                        render("3 0 4", "\"color inputRGB\" [0.75 0.625 0.9] \"int invertBump\" [1] \"int flipY\" [1]")));
        CHECK(sameImage(render("3 0 4", "\"color inputRGB\" [0.75 0.625 0.9]" + directX),
                        render("3 0 4", "\"color inputRGB\" [0.75 0.625 0.9] \"int invertBump\" [1]")));
    }
    SECTION("flipX, flipY and invertBump mirror the map exactly; only the default orientation reads the flips") {
        CHECK(sameImage(render("3 0 4", towardU + " \"int flipX\" [1]"), render("3 0 4", awayFromU)));
        CHECK(sameImage(render("0 -3 4", towardV + " \"int flipY\" [1]"), render("0 -3 4", awayFromV)));
        CHECK(sameImage(render("0 -3 4", towardV + openGL + " \"int flipY\" [1]"), render("0 -3 4", towardV + openGL)));
        CHECK(sameImage(render("3 0 4", "\"color inputRGB\" [0.75 0.625 0.9] \"int invertBump\" [1]"),
                        render("3 0 4", "\"color inputRGB\" [0.25 0.375 0.9]")));
    }
}

TEST_CASE("a normal map read from an image, and a bumped PxrSurface", "[patterns][normalmap][textures]") {
    // An image of one colour: every lookup is that colour, so it bends as inputRGB does.
    int const size = 8;
    std::vector<float> pixels;
    for (int i = 0; i < size * size; ++i) pixels.insert(pixels.end(), {0.75f, 0.5f, 0.93f});
    std::string const file = test::outputDir() + "/tilted-normals.exr";
    writeImage(file, pixels, size, size, 3);
    auto fromColor = test::renderRib(kHead + kHeadlight + bumped("\"color inputRGB\" [0.75 0.5 0.93]") + kSquare,
                                     samples(4));
    auto fromImage =
        test::renderRib(kHead + kHeadlight + bumped("\"string filename\" [\"" + file + "\"]") + kSquare, samples(4));
    CHECK(fromImage.stats.textureLookups > 0u);
    CHECK(fromImage.channel(8, 8, 0) == Approx(fromColor.channel(8, 8, 0)).epsilon(1e-4));

    SECTION("a map that is not there: one warning at its RIB line, and the normal stays the surface's") {
        auto flat = test::renderRib(kHead + kHeadlight + bxdf() + kSquare, samples(4));
        auto missing = test::renderRib(
            kHead + kHeadlight + bumped("\"string filename\" [\"no/such/normals.tx\"]") + kSquare, samples(4));
        int said = 0, located = 0;
        for (auto const& m : missing.messages)
            if (m.text.find("no/such/normals.tx") != std::string::npos) {
                ++said;
                located += m.text.rfind("test.rib:", 0) == 0;
            }
        CHECK(said == 1);
        CHECK(located == 1);
        CHECK(missing.anyMessageContains("Pattern \"PxrNormalMap\" \"bumps\": texture \"no/such/normals.tx\" does not "
                                         "exist (looked for from"));
        CHECK(missing.anyMessageContains("the normal is left as it is"));
        CHECK(missing.channel(8, 8, 0) == Approx(flat.channel(8, 8, 0)).epsilon(1e-5));
        // PxrBump's height map is said the same way.
        auto noHeights = test::renderRib(kHead + kHeadlight + "Pattern \"PxrBump\" \"b\" \"string filename\" [\"heights.tx\"]\n" +
                                             bxdf(" \"reference normal bumpNormal\" [\"b:resultN\"]") + kSquare,
                                         samples(4));
        CHECK(noHeights.anyMessageContains("Pattern \"PxrBump\" \"b\": texture \"heights.tx\" does not exist"));
        CHECK(noHeights.channel(8, 8, 0) == Approx(flat.channel(8, 8, 0)).epsilon(1e-5));
    }
    SECTION("a reference declared a colour where the plugin has a normal: connected as a normal, with a warning") {
        // As public scenes write it: the declaration's type is only how the link is spelled.
        auto spelled = test::renderRib(kHead + kHeadlight +
                                           "Pattern \"PxrNormalMap\" \"bumps\" \"color inputRGB\" [0.75 0.5 0.93]\n" +
                                           bxdf(" \"reference color bumpNormal\" [\"bumps:resultN\"]") + kSquare,
                                       samples(4));
        CHECK(spelled.anyMessageContains("parameter \"bumpNormal\" is a normal, and the RIB declares its reference a "
                                         "color; connected as a normal (write \"reference normal bumpNormal\")"));
        CHECK(spelled.channel(8, 8, 0) == fromColor.channel(8, 8, 0));
    }
    SECTION("PxrSurface's stand-in keeps its bumpNormal") {
        std::string const surface = "Pattern \"PxrNormalMap\" \"bumps\" \"color inputRGB\" [0.75 0.5 0.93]\n"
                                    "Bxdf \"PxrSurface\" \"s\" \"color diffuseColor\" [1 1 1] "
                                    "\"color specularFaceColor\" [0 0 0] \"float specularRoughness\" [0.25] "
                                    "\"reference normal bumpNormal\" [\"bumps:resultN\"]\n";
        auto standIn = test::renderRib(kHead + kHeadlight + surface + kSquare, samples(4));
        CHECK_FALSE(standIn.anyMessageContains("bumpNormal"));
        CHECK(standIn.channel(8, 8, 0) == Approx(fromColor.channel(8, 8, 0)).epsilon(1e-4));
    }
}

TEST_CASE("PxrBump tilts the normal against its height map's slope", "[patterns][normalmap][textures]") {
    // A 64-pixel ramp across s: h = (64 s - 0.5) / 63 between pixel centres, a slope of 64/63 per
    // unit of s; s spans the square's 2 units along x, so h rises 32/63 per unit of x.
    int const size = 64;
    std::vector<float> pixels;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) pixels.insert(pixels.end(), 3, static_cast<float>(x) / (size - 1));
    std::string const file = test::outputDir() + "/height-ramp.exr";
    writeImage(file, pixels, size, size, 3);
    auto bump = [&](std::string const& light, std::string const& scale) {
        return test::renderRib(kHead + light + "Pattern \"PxrBump\" \"b\" \"string filename\" [\"" + file +
                                   "\"] \"float scale\" [" + scale + "]\n" +
                                   bxdf(" \"reference normal bumpNormal\" [\"b:resultN\"]") + kSquare,
                               samples(4));
    };
    auto flat = test::renderRib(kHead + kHeadlight + bxdf() + kSquare, samples(4));
    for (double scale : {0.5, 2.0}) {
        CAPTURE(scale);
        auto r = bump(kHeadlight, std::to_string(scale));
        double const c = std::cos(std::atan(scale * 32.0 / 63.0));  // the tilt of N - scale grad h
        double const fd = std::pow(1.0 + 0.5 * std::pow(1.0 - c, 5.0), 2.0);
        for (int x : {4, 8, 11})
            for (int y : {3, 12}) CHECK(r.channel(x, y, 0) / flat.channel(x, y, 0) == Approx(c * fd).epsilon(1e-3));
    }
    SECTION("a slope rising toward +x leans the normal toward -x") {
        std::string const leftLight = "AttributeBegin\nTranslate -3 0 4\nScale 0.2 0.2 0.2\n"
                                      "Light \"PxrSphereLight\" \"bulb\" \"float intensity\" [400]\nAttributeEnd\n";
        auto level = bump(leftLight, "0");
        CHECK(bump(leftLight, "1").channel(8, 8, 0) > 1.2f * level.channel(8, 8, 0));
        CHECK(bump(leftLight, "-1").channel(8, 8, 0) < 0.8f * level.channel(8, 8, 0));
    }
    SECTION("a connected inputBump is not differentiated: a warning, and the normal is the surface's") {
        auto r = test::renderRib(kHead + kHeadlight + "Pattern \"PxrVariable\" \"u\" \"string variable\" [\"u\"]\n" +
                                     "Pattern \"PxrBump\" \"b\" \"reference float inputBump\" [\"u:resultF\"]\n" +
                                     bxdf(" \"reference normal bumpNormal\" [\"b:resultN\"]") + kSquare,
                                 samples(4));
        CHECK(r.anyMessageContains("PxrBump: a connected inputBump is not differentiated here"));
        CHECK(r.channel(8, 8, 0) == Approx(flat.channel(8, 8, 0)).epsilon(1e-5));
    }
}
