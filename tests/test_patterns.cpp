// Pattern networks: connected parameters are varying and carry the pattern's
// per-point values; patterns run only when asked, once per batch; textures
// match OpenImageIO's own lookups; bad networks give located messages.
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <catch2/catch.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/ImageFiles.h"
#include "scene/SceneBuilder.h"
#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {

// A 16 x 16 orthographic view of the square [-1,1]^2; the patch's u runs
// along x and v along y, so at pixel (x, y): u = (x + 0.5) / 16, v = 1 - (y + 0.5) / 16.
std::string const kHead = "Format 16 16 1\nProjection \"orthographic\"\nScreenWindow -1 1 -1 1\n"
                          "Integrator \"PxrDefault\" \"d\"\nWorldBegin\nTranslate 0 0 5\n";
std::string const kSquare = "Patch \"bilinear\" \"P\" [-1 -1 0  1 -1 0  -1 1 0  1 1 0]\n";

float pixelU(int x) { return (static_cast<float>(x) + 0.5f) / 16.0f; }
float pixelV(int y) { return 1.0f - (static_cast<float>(y) + 0.5f) / 16.0f; }

RenderSettings fewSamples() {
    RenderSettings settings;
    settings.spp = 4;
    return settings;
}

/// The colour a network's `output` ("handle:resultRGB") gives the middle of the square, emitted as is:
/// for patterns that write one colour over the whole square.
RtColorRGB colour(std::string const& patterns, std::string const& output) {
    auto r = test::renderRib(kHead + patterns + "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"" +
                                 output + "\"]\n" + kSquare,
                             fewSamples());
    return RtColorRGB(r.channel(8, 8, 0), r.channel(8, 8, 1), r.channel(8, 8, 2));
}

void near(RtColorRGB const& c, float r, float g, float b) {
    CHECK(c.r == Approx(r).margin(1e-4));
    CHECK(c.g == Approx(g).margin(1e-4));
    CHECK(c.b == Approx(b).margin(1e-4));
}

}  // namespace

TEST_CASE("a connected parameter takes the pattern's value at every point", "[patterns]") {
    SECTION("PxrVariable u into an emissive colour") {
        auto r = test::renderRib(kHead + "Pattern \"PxrVariable\" \"u\" \"string variable\" [\"u\"]\n"
                                         "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"u:resultRGB\"]\n" +
                                     kSquare,
                                 fewSamples());
        for (int x : {0, 5, 11, 15})
            for (int y : {2, 13}) CHECK(r.channel(x, y, 0) == Approx(pixelU(x)).margin(0.01));
    }
    SECTION("PxrVariable: what is not displaced or moving equals what is") {
        auto shown = [](std::string const& variable) {
            return test::renderRib(kHead + "Pattern \"PxrVariable\" \"x\" \"string variable\" [\"" + variable +
                                       "\"]\nBxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"x:resultRGB\"]\n"
                                       "Rotate 30 0 1 0\n" + kSquare,
                                   fewSamples());
        };
        auto P = shown("P"), Po = shown("Po"), Nn = shown("Nn"), Non = shown("Non"), dPdtime = shown("dPdtime");
        for (int c = 0; c < 3; ++c) {
            CHECK(Po.channel(3, 8, c) == Approx(P.channel(3, 8, c)));
            CHECK(Non.channel(8, 8, c) == Approx(Nn.channel(8, 8, c)));
            CHECK(dPdtime.channel(8, 8, c) == 0.0f);
        }
        CHECK(Nn.channel(8, 8, 0) != 0.0f);  // the tilted square's normal has an x part to compare
    }
    SECTION("PxrMix of a uniform colour and a connected one, through a manifold-free chain") {
        auto r = test::renderRib(kHead + "Pattern \"PxrVariable\" \"v\" \"string variable\" [\"v\"]\n"
                                         "Pattern \"PxrMix\" \"m\" \"color color1\" [1 0 0] "
                                         "\"reference color color2\" [\"v:resultRGB\"] \"float mix\" [0.25]\n"
                                         "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"m:resultRGB\"]\n" +
                                     kSquare,
                                 fewSamples());
        for (int y : {1, 8, 14}) {
            CHECK(r.channel(7, y, 0) == Approx(0.75f + 0.25f * pixelV(y)).margin(0.01));
            CHECK(r.channel(7, y, 1) == Approx(0.25f * pixelV(y)).margin(0.01));
        }
        // Its green channel alone (resultG, a float) as another mix's amount: grey of that value.
        auto green = test::renderRib(kHead + "Pattern \"PxrVariable\" \"v\" \"string variable\" [\"v\"]\n"
                                             "Pattern \"PxrMix\" \"m\" \"color color1\" [1 0 0] "
                                             "\"reference color color2\" [\"v:resultRGB\"] \"float mix\" [0.25]\n"
                                             "Pattern \"PxrMix\" \"grey\" \"color color1\" [0 0 0] "
                                             "\"reference float mix\" [\"m:resultG\"]\n"
                                             "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"grey:resultRGB\"]\n" +
                                         kSquare,
                                     fewSamples());
        for (int y : {1, 8, 14}) CHECK(green.channel(7, y, 0) == Approx(0.25f * pixelV(y)).margin(0.01));
    }
    SECTION("PxrPrimvar hands a mesh's per-vertex colour on") {
        auto r = test::renderRib(kHead + "Pattern \"PxrPrimvar\" \"cs\" \"string varname\" [\"Cs\"]\n"
                                         "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"cs:resultRGB\"]\n"
                                         "Polygon \"P\" [-1 -1 0  1 -1 0  1 1 0  -1 1 0] "
                                         "\"varying color Cs\" [0 0 1  1 0 1  1 0 1  0 0 1]\n",
                                 fewSamples());
        for (int x : {0, 8, 15}) CHECK(r.channel(x, 8, 0) == Approx(pixelU(x)).margin(0.02));
        CHECK(r.channel(8, 8, 2) == Approx(1.0f).margin(1e-4));
    }
    SECTION("PxrManifold2D scales, offsets and turns s and t") {
        // 90 degrees turns (s, t) into (-t, s); then s' = 2 * (-t) + 2.
        auto r = test::renderRib(kHead + "Pattern \"PxrManifold2D\" \"m\" \"float angle\" [90] \"float scaleS\" [2] "
                                         "\"float offsetS\" [2]\n"
                                         "Pattern \"PxrTexture\" \"unused\" \"string filename\" [\"none.tx\"]\n"
                                         "Pattern \"PxrVariable\" \"probe\" \"string variable\" [\"s\"]\n"
                                         "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"m:result\"]\n" +
                                     kSquare,
                                 fewSamples());
        for (int y : {1, 8, 14}) {
            CHECK(r.channel(4, y, 0) == Approx(2.0f - 2.0f * pixelV(y)).margin(0.02));
            CHECK(r.channel(4, y, 1) == Approx(pixelU(4)).margin(0.02));
        }
    }
    SECTION("PxrManifold2D flips s with invertS and t with invertT before it turns them") {
        auto r =
            test::renderRib(kHead +
                                "Pattern \"PxrManifold2D\" \"m\" \"int invertS\" [1] \"int invertT\" [1]\n"
                                "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"m:result\"]\n" +
                                kSquare,
                            fewSamples());
        CHECK_FALSE(r.anyMessageContains("has no parameter"));
        for (int x : {1, 8, 14})
            for (int y : {1, 8, 14}) {
                CHECK(r.channel(x, y, 0) == Approx(1.0f - pixelU(x)).margin(0.02));
                CHECK(r.channel(x, y, 1) == Approx(1.0f - pixelV(y)).margin(0.02));
            }
    }
    SECTION(
        "PxrManifold2D reads s from the primvar primvarS names; a name the surface lacks leaves t as it is") {
        std::string const polygon =
            "Polygon \"P\" [-1 -1 0  1 -1 0  1 1 0  -1 1 0] \"varying float mapS\" [1 0 0 1]\n";
        auto plain =
            test::renderRib(kHead +
                                "Pattern \"PxrManifold2D\" \"m\"\n"
                                "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"m:result\"]\n" +
                                polygon,
                            fewSamples());
        auto mapped =
            test::renderRib(kHead +
                                "Pattern \"PxrManifold2D\" \"m\" \"string primvarS\" [\"mapS\"] "
                                "\"string primvarT\" [\"noSuchPrimvar\"]\n"
                                "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"m:result\"]\n" +
                                polygon,
                            fewSamples());
        CHECK_FALSE(mapped.anyMessageContains("has no parameter"));
        for (int x : {1, 8, 14})
            for (int y : {2, 13}) {
                CHECK(mapped.channel(x, y, 0) == Approx(1.0f - pixelU(x)).margin(0.02));
                CHECK(mapped.channel(x, y, 1) == Approx(plain.channel(x, y, 1)).margin(1e-6));
            }
    }
}

TEST_CASE("PxrRamp interpolates its knots along the ramp shape and PxrChecker alternates two colours",
          "[patterns]") {
    auto emitted = [](std::string const& patterns, std::string const& output) {
        return test::renderRib(kHead + patterns + "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"" +
                                   output + "\"]\n" + kSquare,
                               fewSamples());
    };
    std::string const knots = "\"int colorRamp\" [3] \"float[3] colorRamp_Knots\" [0.25 0.5 0.75] "
                              "\"color[3] colorRamp_Colors\" [1 0 0  0 1 0  0 0 1] ";
    SECTION("linear along s: the first colour before the first knot, the last after the last, lines between") {
        auto r = emitted("Pattern \"PxrRamp\" \"r\" " + knots + "\"string colorRamp_Interpolation\" [\"linear\"]\n",
                         "r:resultRGB");
        for (int x : {0, 3, 5, 7, 9, 11, 15}) {
            float const s = pixelU(x);
            float const red = s <= 0.25f ? 1.0f : s < 0.5f ? (0.5f - s) / 0.25f : 0.0f;
            float const blue = s >= 0.75f ? 1.0f : s > 0.5f ? (s - 0.5f) / 0.25f : 0.0f;
            CHECK(r.channel(x, 8, 0) == Approx(red).margin(0.02));
            CHECK(r.channel(x, 8, 2) == Approx(blue).margin(0.02));
            CHECK(r.channel(x, 8, 1) == Approx(1.0f - red - blue).margin(0.02));
        }
        CHECK(r.channel(5, 1, 0) == Approx(r.channel(5, 14, 0)).margin(0.01));  // an S ramp does not change along t
    }
    SECTION("constant, along t and reversed: each knot's colour up to the next") {
        auto r = emitted("Pattern \"PxrRamp\" \"r\" \"int rampType\" [1] \"int reverse\" [1] " + knots +
                             "\"string colorRamp_Interpolation\" [\"constant\"]\n",
                         "r:resultRGB");
        for (int y : {0, 2, 5, 7, 9, 12, 15}) {
            float const x = 1.0f - pixelV(y);  // reversed
            int const expected = x < 0.5f ? 0 : x < 0.75f ? 1 : 2;
            for (int c = 0; c < 3; ++c) CHECK(r.channel(8, y, c) == Approx(c == expected ? 1.0f : 0.0f).margin(1e-5));
        }
    }
    SECTION("catmull-rom passes through its knots and runs smoothly between them") {
        // Knots at the centres of pixel columns 4, 8 and 12: the colour there is the knot's (a pixel
        // averages the curve over its width, which lifts a minimum a little).
        auto r = emitted("Pattern \"PxrRamp\" \"r\" \"int colorRamp\" [3] "
                         "\"float[3] colorRamp_Knots\" [0.28125 0.53125 0.78125] "
                         "\"color[3] colorRamp_Colors\" [0 0 0  1 1 1  0 0 0]\n",
                         "r:resultRGB");
        CHECK(r.channel(8, 8, 0) == Approx(1.0f).margin(0.04));
        CHECK(r.channel(4, 8, 0) == Approx(0.0f).margin(0.04));
        CHECK(r.channel(12, 8, 0) == Approx(0.0f).margin(0.04));
        // Halfway between knots the curve is above the straight line (0.5): it rises smoothly into the peak.
        CHECK(r.channel(6, 8, 0) > 0.55f);
        CHECK(r.channel(6, 8, 0) < 1.0f);
    }
    SECTION("box and circular ramps measure from the centre; RenderMan 21's positions and colors are read too") {
        auto box = emitted("Pattern \"PxrRamp\" \"r\" \"int rampType\" [5] \"int colorRamp\" [2] "
                           "\"float[2] colorRamp_Knots\" [0 1] \"color[2] colorRamp_Colors\" [0 0 0  1 1 1] "
                           "\"string colorRamp_Interpolation\" [\"linear\"]\n",
                           "r:resultRGB");
        CHECK(box.channel(2, 8, 0) == Approx(2.0f * std::fabs(pixelU(2) - 0.5f)).margin(0.02));
        CHECK(box.channel(8, 13, 0) == Approx(2.0f * std::fabs(pixelV(13) - 0.5f)).margin(0.02));
        // RenderMan 21: a linear basis (3) whose first and last points only shape the ends.
        auto old = emitted("Pattern \"PxrRamp\" \"r\" \"int rampType\" [4] \"int useNewRamp\" [0] \"int basis\" [3] "
                           "\"float positions\" [0 0 1 1] \"color colors\" [0 0 0  0 0 0  1 1 1  1 1 1]\n",
                           "r:resultRGB");
        float const dx = pixelU(3) - 0.5f, dy = pixelV(6) - 0.5f;
        CHECK(old.channel(3, 6, 0) == Approx(2.0f * std::sqrt(dx * dx + dy * dy)).margin(0.02));
    }
    SECTION("an interpolation or shape it does not have is a warning, not a silent change") {
        auto r = emitted("Pattern \"PxrRamp\" \"r\" \"int rampType\" [9] " + knots +
                             "\"string colorRamp_Interpolation\" [\"hermite\"]\n",
                         "r:resultRGB");
        CHECK(r.anyMessageContains("PxrRamp: rampType 9 is not one of the shapes this renderer has"));
        CHECK(r.anyMessageContains("PxrRamp: colorRamp_Interpolation \"hermite\" is read as \"catmull-rom\""));
    }
    SECTION("PxrChecker: half-unit squares of s and t, colorA at (0, 0), finer through a manifold") {
        auto r = emitted("Pattern \"PxrChecker\" \"k\" \"color colorA\" [1 0 0] \"color colorB\" [0 0 1]\n",
                         "k:resultRGB");
        CHECK(r.channel(2, 13, 0) == 1.0f);  // s, t < 0.5
        CHECK(r.channel(13, 2, 0) == 1.0f);  // s, t > 0.5
        CHECK(r.channel(13, 13, 2) == 1.0f);
        CHECK(r.channel(2, 2, 2) == 1.0f);
        auto fine = emitted("Pattern \"PxrManifold2D\" \"m\" \"float scaleS\" [4] \"float scaleT\" [4]\n"
                            "Pattern \"PxrChecker\" \"k\" \"reference struct manifold\" [\"m:result\"]\n"
                            "Pattern \"PxrMix\" \"grey\" \"color color1\" [0 0 0] \"reference float mix\" [\"k:resultR\"]\n",
                            "grey:resultRGB");  // its red channel alone, as a float
        for (int x = 0; x < 16; ++x) {
            int const cells = static_cast<int>(std::floor(8.0f * pixelU(x))) + static_cast<int>(std::floor(8.0f * pixelV(5)));
            CHECK(fine.channel(x, 5, 0) == (cells % 2 == 0 ? 1.0f : 0.0f));
        }
    }
    SECTION("PxrChecker in three dimensions: cubes of the object's own space") {
        // The square lies at object z = 0: x and y decide, in object units (the square spans -1..1).
        auto r = emitted("Pattern \"PxrChecker\" \"k\" \"int dimensions\" [3]\n", "k:resultRGB");
        for (int x : {1, 6, 9, 14}) {
            float const objectX = 2.0f * pixelU(x) - 1.0f, objectY = 2.0f * pixelV(3) - 1.0f;
            int const cells = static_cast<int>(std::floor(2.0f * objectX)) + static_cast<int>(std::floor(2.0f * objectY));
            CHECK(r.channel(x, 3, 0) == ((cells % 2 + 2) % 2 == 0 ? 1.0f : 0.0f));
        }
    }
}

TEST_CASE("PxrBlend and PxrRemap and PxrExposure and PxrToFloat3 combine and adjust colours as documented",
          "[patterns]") {
    std::string const layers = "\"color topRGB\" [0.2 0.6 1] \"color bottomRGB\" [0.5 0.5 0.25] ";
    SECTION("PxrBlend: Normal (19, the default) shows the top by its alpha; the modes blend channel by channel") {
        near(colour("Pattern \"PxrBlend\" \"b\" " + layers + "\"float topA\" [0.25]\n", "b:resultRGB"),
             0.75f * 0.5f + 0.25f * 0.2f, 0.75f * 0.5f + 0.25f * 0.6f, 0.75f * 0.25f + 0.25f * 1.0f);
        near(colour("Pattern \"PxrBlend\" \"b\" \"int operation\" [18] " + layers + "\n", "b:resultRGB"),
             0.1f, 0.3f, 0.25f);  // Multiply
        near(colour("Pattern \"PxrBlend\" \"b\" \"int operation\" [23] " + layers + "\n", "b:resultRGB"),
             0.6f, 0.8f, 1.0f);  // Screen: 1 - (1 - b)(1 - t)
        near(colour("Pattern \"PxrBlend\" \"b\" \"int operation\" [3] " + layers + "\n", "b:resultRGB"),
             0.2f, 0.5f, 0.25f);  // Darken
        near(colour("Pattern \"PxrBlend\" \"b\" \"int operation\" [20] " + layers + "\n", "b:resultRGB"),
             0.2f, 0.6f, 0.5f);  // Overlay: 2bt where b <= 0.5
        // Linear Dodge (add) goes past 1 only when clampOutput is off.
        near(colour("Pattern \"PxrBlend\" \"b\" \"int operation\" [15] " + layers + "\n", "b:resultRGB"),
             0.7f, 1.0f, 1.0f);
        near(colour("Pattern \"PxrBlend\" \"b\" \"int operation\" [15] \"int clampOutput\" [0] " + layers + "\n",
                    "b:resultRGB"),
             0.7f, 1.1f, 1.25f);
        // A bottom with alpha stands on black; the result's alpha is the two alphas composited.
        near(colour("Pattern \"PxrBlend\" \"b\" " + layers + "\"float topA\" [0.5] \"float bottomA\" [0.5]\n"
                    "Pattern \"PxrMix\" \"alpha\" \"color color1\" [0 0 0] \"reference float mix\" [\"b:resultA\"]\n",
                    "alpha:resultRGB"),
             0.75f, 0.75f, 0.75f);
        near(colour("Pattern \"PxrBlend\" \"b\" " + layers + "\"float topA\" [0] \"float bottomA\" [0.5]\n", "b:resultRGB"),
             0.25f, 0.25f, 0.125f);
        // Luminosity keeps the bottom's hue and takes the top's luminosity (0.3 r + 0.59 g + 0.11 b).
        RtColorRGB const lum = colour("Pattern \"PxrBlend\" \"b\" \"int operation\" [17] " + layers + "\n", "b:resultRGB");
        CHECK(0.3f * lum.r + 0.59f * lum.g + 0.11f * lum.b == Approx(0.3f * 0.2f + 0.59f * 0.6f + 0.11f).margin(1e-4));
        CHECK(lum.r == Approx(lum.g).margin(1e-4));  // the bottom's red and green are equal: so are the result's
        auto r = test::renderRib(kHead + "Pattern \"PxrBlend\" \"b\" \"int operation\" [40]\n"
                                         "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"b:resultRGB\"]\n" +
                                     kSquare,
                                 fewSamples());
        CHECK(r.anyMessageContains("PxrBlend: operation 40 is not one of the blend modes (0-26); Normal (19) is used"));
    }
    SECTION("PxrRemap: from one range to another; bias and gain of 0.5 change nothing") {
        near(colour("Pattern \"PxrRemap\" \"m\" \"color inputRGB\" [0.3 0.5 0.9]\n", "m:resultRGB"), 0.3f, 0.5f, 0.9f);
        near(colour("Pattern \"PxrRemap\" \"m\" \"color inputRGB\" [2 3 5] \"float inputMin\" [2] \"float inputMax\" [4] "
                    "\"float outputMin\" [0.2] \"float outputMax\" [0.6]\n",
                    "m:resultRGB"),
             0.2f, 0.4f, 0.6f);  // 5 is past inputMax: clamped to it
        RtColorRGB const biased =
            colour("Pattern \"PxrRemap\" \"m\" \"color inputRGB\" [0.5 0.25 0.5] \"color bias\" [0.8 0.5 0.5] "
                   "\"color gain\" [0.5 0.5 0.8]\n",
                   "m:resultRGB");
        CHECK(biased.r == Approx(0.8f).margin(1e-4));  // bias(0.5) = the bias
        CHECK(biased.g == Approx(0.25f).margin(1e-4));
        CHECK(biased.b == Approx(0.5f).margin(1e-4));  // gain keeps 0.5 where it is
    }
    SECTION("PxrExposure doubles a colour per stop, PxrToFloat3 makes a colour of floats") {
        near(colour("Pattern \"PxrExposure\" \"e\" \"color inputRGB\" [0.1 0.2 0.4] \"float stops\" [2]\n", "e:resultRGB"),
             0.4f, 0.8f, 1.6f);
        near(colour("Pattern \"PxrToFloat3\" \"f\" \"float input\" [0.3]\n", "f:resultRGB"), 0.3f, 0.3f, 0.3f);
        // A connected channel makes it build the colour channel by channel; the others keep their values.
        near(colour("Pattern \"PxrMix\" \"half\" \"float mix\" [0.5]\n"
                    "Pattern \"PxrToFloat3\" \"f\" \"float input\" [0.3] \"reference float inputG\" [\"half:resultG\"] "
                    "\"float inputB\" [0.9]\n",
                    "f:resultRGB"),
             0.0f, 0.5f, 0.9f);
    }
}

TEST_CASE("PxrColorCorrect, PxrGamma, PxrHSL, PxrInvert, PxrClamp and PxrToFloat adjust colours as documented",
          "[patterns]") {
    auto warns = [](std::string const& pattern, std::string const& message) {
        auto r = test::renderRib(kHead + pattern + "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"x:resultRGB\"]\n" +
                                     kSquare,
                                 fewSamples());
        CHECK(r.anyMessageContains(message));
    };
    SECTION("PxrColorCorrect: each correction in the order of its parameters; the defaults change nothing") {
        std::string const cc = "Pattern \"PxrColorCorrect\" \"x\" \"color inputRGB\" ";
        near(colour(cc + "[0.2 0.5 0.9]\n", "x:resultRGB"), 0.2f, 0.5f, 0.9f);
        near(colour(cc + "[0.4 0.4 0.4] \"color rgbGain\" [1.25 0.85 0.55]\n", "x:resultRGB"), 0.5f, 0.34f, 0.22f);
        near(colour(cc + "[0.5 0.25 1] \"vector gamma\" [2 2 2]\n", "x:resultRGB"), 0.25f, 0.0625f, 1.0f);
        near(colour(cc + "[0.25 0.5 0.75] \"vector contrast\" [0.5 0.5 0.5]\n", "x:resultRGB"), 0.0f, 0.5f, 1.0f);
        near(colour(cc + "[0.25 0.5 0.75] \"vector contrast\" [-1 -1 -1]\n", "x:resultRGB"), 0.5f, 0.5f, 0.5f);
        near(colour(cc + "[0.4 0.2 0.6] \"vector inputMin\" [0.2 0.2 0.2] \"vector inputMax\" [0.6 0.6 0.6] "
                         "\"vector outputMin\" [0.2 0.2 0.2] \"vector outputMax\" [0.6 0.6 0.6]\n",
                    "x:resultRGB"),
             0.4f, 0.2f, 0.6f);  // levels in then the same levels out: back where it was
        near(colour(cc + "[0.4 0.2 0.6] \"vector inputMin\" [0.2 0.2 0.2] \"vector inputMax\" [0.6 0.6 0.6]\n",
                    "x:resultRGB"),
             0.5f, 0.0f, 1.0f);
        near(colour(cc + "[1 0 0] \"vector hsv\" [0.5 1 1]\n", "x:resultRGB"), 0.0f, 1.0f, 1.0f);  // red's complement
        near(colour(cc + "[1 0.5 0] \"vector hsv\" [0 0 1]\n", "x:resultRGB"), 1.0f, 1.0f, 1.0f);  // no saturation
        near(colour(cc + "[0.1 0.2 0.4] \"float exposure\" [1]\n", "x:resultRGB"), 0.2f, 0.4f, 0.8f);
        near(colour(cc + "[2 -1 0.5]\n", "x:resultRGB"), 2.0f, -1.0f, 0.5f);
        near(colour(cc + "[2 -1 0.5] \"int clampOutput\" [1]\n", "x:resultRGB"), 1.0f, 0.0f, 0.5f);
        // The mask mixes the corrected colour (here twice the input) into the input.
        std::string const doubled = cc + "[0.2 0.4 0.6] \"color rgbGain\" [2 2 2] ";
        near(colour(doubled + "\"float inputMask\" [0.25]\n", "x:resultRGB"), 0.25f, 0.5f, 0.75f);
        near(colour(doubled + "\"float inputMask\" [0.25] \"int invertMask\" [1]\n", "x:resultRGB"), 0.35f, 0.7f,
             1.05f);
        near(colour(doubled + "\"float mixMask\" [0.5]\n", "x:resultRGB"), 0.3f, 0.6f, 0.9f);
        // A connected input, as exporters write it: a texture (here a mix) tinted.
        near(colour("Pattern \"PxrMix\" \"grey\" \"float mix\" [0.5]\n"
                    "Pattern \"PxrColorCorrect\" \"x\" \"reference color inputRGB\" [\"grey:resultRGB\"] "
                    "\"color rgbGain\" [1 0.5 0.25]\n",
                    "x:resultRGB"),
             0.5f, 0.25f, 0.125f);
    }
    SECTION("PxrGamma raises each channel to the gamma") {
        near(colour("Pattern \"PxrGamma\" \"x\" \"color inputRGB\" [0.25 0.5 1] \"float gamma\" [0.5]\n", "x:resultRGB"),
             0.5f, std::sqrt(0.5f), 1.0f);
        near(colour("Pattern \"PxrGamma\" \"x\" \"color inputRGB\" [0.25 0.5 1] \"float gamma\" [2.2]\n", "x:resultRGB"),
             std::pow(0.25f, 2.2f), std::pow(0.5f, 2.2f), 1.0f);
    }
    SECTION("PxrHSL turns the hue and scales saturation and lightness") {
        std::string const hsl = "Pattern \"PxrHSL\" \"x\" \"color inputRGB\" ";
        near(colour(hsl + "[0.2 0.5 0.7]\n", "x:resultRGB"), 0.2f, 0.5f, 0.7f);  // to HSL and back
        near(colour(hsl + "[1 0 0] \"float hue\" [0.333333333]\n", "x:resultRGB"), 0.0f, 1.0f, 0.0f);
        near(colour(hsl + "[1 0 0] \"float hue\" [-0.333333333]\n", "x:resultRGB"), 0.0f, 0.0f, 1.0f);
        near(colour(hsl + "[1 0 0] \"float saturation\" [0]\n", "x:resultRGB"), 0.5f, 0.5f, 0.5f);
        near(colour(hsl + "[1 0 0] \"float luminance\" [0.5]\n", "x:resultRGB"), 0.5f, 0.0f, 0.0f);
    }
    SECTION("PxrInvert inverts the chosen channels of RGB, HSL or HSV") {
        std::string const inv = "Pattern \"PxrInvert\" \"x\" \"color inputRGB\" [0.2 0.4 0.9] ";
        near(colour(inv + "\n", "x:resultRGB"), 0.8f, 0.6f, 0.1f);
        near(colour(inv + "\"int invertChannel1\" [0]\n", "x:resultRGB"), 0.8f, 0.4f, 0.1f);
        // HSL, lightness only: 0.55 becomes 0.45, hue and saturation stay.
        near(colour(inv + "\"int colorModel\" [1] \"int invertChannel0\" [0] \"int invertChannel1\" [0]\n",
                    "x:resultRGB"),
             0.1f, 0.3f, 0.8f);
        near(colour("Pattern \"PxrInvert\" \"x\" \"color inputRGB\" [1 0 0] \"int colorModel\" [2] "
                    "\"int invertChannel1\" [0] \"int invertChannel2\" [0]\n",
                    "x:resultRGB"),
             0.0f, 1.0f, 1.0f);  // the hue turns to the complement
        near(colour("Pattern \"PxrInvert\" \"x\" \"color inputRGB\" [1.5 -0.5 0.5]\n", "x:resultRGB"), 0.0f, 1.0f,
             0.5f);  // kept within black and white
        warns("Pattern \"PxrInvert\" \"x\" \"int colorModel\" [5]\n",
              "PxrInvert: colorModel 5 is not one of 0 (RGB), 1 (HSL), 2 (HSV); RGB is used");
    }
    SECTION("PxrClamp keeps channels in range, or wraps them with modulus") {
        near(colour("Pattern \"PxrClamp\" \"x\" \"color inputRGB\" [-0.5 0.5 1.5]\n", "x:resultRGB"), 0.0f, 0.5f, 1.0f);
        near(colour("Pattern \"PxrClamp\" \"x\" \"color inputRGB\" [-0.5 0.5 1.5] \"color min\" [0.2 0.6 0] "
                    "\"color max\" [1 1 1.2]\n",
                    "x:resultRGB"),
             0.2f, 0.6f, 1.2f);
        near(colour("Pattern \"PxrClamp\" \"x\" \"color inputRGB\" [1.25 -0.25 0.5] \"int modulus\" [1]\n",
                    "x:resultRGB"),
             0.25f, 0.75f, 0.5f);
    }
    SECTION("PxrToFloat hands on one channel") {
        std::string const toColour = "Pattern \"PxrToFloat3\" \"grey\" \"reference float input\" [\"f:resultF\"]\n";
        near(colour("Pattern \"PxrToFloat\" \"f\" \"color input\" [0.2 0.5 0.9]\n" + toColour, "grey:resultRGB"), 0.2f,
             0.2f, 0.2f);
        near(colour("Pattern \"PxrToFloat\" \"f\" \"color input\" [0.2 0.5 0.9] \"int mode\" [2]\n" + toColour,
                    "grey:resultRGB"),
             0.9f, 0.9f, 0.9f);
        warns("Pattern \"PxrToFloat\" \"f\" \"int mode\" [7]\n"
              "Pattern \"PxrToFloat3\" \"x\" \"reference float input\" [\"f:resultF\"]\n",
              "PxrToFloat: mode 7 is not one of 0 (red), 1 (green), 2 (blue); red is used");
    }
}

TEST_CASE("PxrWorley and PxrVoronoise lay cells on the surface as documented", "[patterns]") {
    // Both feed a PxrToFloat3 of resultF, emitted: each pixel shows the pattern's value there.
    auto cells = [](std::string const& pattern, int spp = 4) {
        RenderSettings settings;
        settings.spp = spp;
        return test::renderRib(kHead + pattern +
                                   "\nPattern \"PxrToFloat3\" \"grey\" \"reference float input\" [\"w:resultF\"]\n"
                                   "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"grey:resultRGB\"]\n" +
                                   kSquare,
                               settings);
    };
    auto spreadOf = [](test::RenderOutcome const& r) {
        double sum = 0, squares = 0;
        int const n = r.width * r.height;
        for (int y = 0; y < r.height; ++y)
            for (int x = 0; x < r.width; ++x) {
                sum += r.channel(x, y, 0);
                squares += r.channel(x, y, 0) * r.channel(x, y, 0);
            }
        return std::sqrt(std::max(0.0, squares / n - (sum / n) * (sum / n)));
    };
    SECTION("PxrWorley without jitter: F1 is the distance to the middle of the pixel's square of (s, t)") {
        // frequency 2: squares of half a unit, middles at 0.25 and 0.75 (in units of the squares: at k + 0.5).
        std::string const grid = "Pattern \"PxrWorley\" \"w\" \"float frequency\" [2] \"float jitter\" [0] ";
        auto euclidean = cells(grid + "\"float c1\" [1] \"float c2\" [0]", 64);
        auto chebyshev = cells(grid + "\"float c1\" [1] \"float c2\" [0] \"int distancemetric\" [2]", 64);
        auto manhattan = cells(grid + "\"float c1\" [1] \"float c2\" [0] \"int distancemetric\" [1]", 64);
        for (int x : {1, 3, 9, 12})
            for (int y : {2, 5, 13}) {
                float const dx = std::fabs(2.0f * pixelU(x) - std::floor(2.0f * pixelU(x)) - 0.5f);
                float const dy = std::fabs(2.0f * pixelV(y) - std::floor(2.0f * pixelV(y)) - 0.5f);
                CHECK(euclidean.channel(x, y, 0) == Approx(std::sqrt(dx * dx + dy * dy)).margin(0.03));
                CHECK(chebyshev.channel(x, y, 0) == Approx(std::max(dx, dy)).margin(0.03));
                CHECK(manhattan.channel(x, y, 0) == Approx(dx + dy).margin(0.03));
            }
        // F2 at a square's middle is the next middle's distance, one square away; c1 F1 + c2 F2 is clamped.
        auto second = cells(grid + "\"float c1\" [0] \"float c2\" [0.5]", 64);
        // (u, v) = (0.28, 0.72) is (0.56, 1.44) in squares: 1/16 from the middle (0.5, 1.5), 0.94 from the next two.
        CHECK(second.channel(4, 4, 0) == Approx(0.5f * std::hypot(0.9375f, 0.0625f)).margin(0.03));
        auto defaults = cells(grid);  // 0.8 F1 - 0.2 F2 < 0 near a middle: clamped to 0
        CHECK(defaults.channel(4, 4, 0) == 0.0f);
        auto inverted = cells(grid + "\"int invert\" [1]");
        for (int x = 0; x < 16; ++x) CHECK(inverted.channel(x, 7, 0) == Approx(1.0f - defaults.channel(x, 7, 0)));
    }
    SECTION("PxrWorley with jitter: irregular cells in 0 to 1; what is not modelled is said") {
        auto r = cells("Pattern \"PxrWorley\" \"w\" \"int shape\" [2] \"int distancemetric\" [7] \"float randomScale\" [1]");
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                CHECK(r.channel(x, y, 0) >= 0.0f);
                CHECK(r.channel(x, y, 0) <= 1.0f);
            }
        CHECK(spreadOf(r) > 0.05);
        CHECK(r.anyMessageContains("PxrWorley: shape 2 is not modelled"));
        CHECK(r.anyMessageContains("PxrWorley: distancemetric 7 is not one of 0 (Euclidean), 1 (Manhattan), "
                                   "2 (Chebyshev), 3 (Minkowski); Euclidean is used"));
        CHECK(r.anyMessageContains("PxrWorley: randomScale is not modelled"));
    }
    SECTION("PxrVoronoise: flat cells without smoothness, a smooth noise with it, in 0 to 1") {
        std::string const one = "Pattern \"PxrVoronoise\" \"w\" \"float frequency\" [2] \"int octaves\" [1] ";
        auto flat = cells(one + "\"float jitter\" [1] \"float smoothness\" [0]");
        auto smooth = cells(one + "\"float jitter\" [1] \"float smoothness\" [1]");
        for (auto const* r : {&flat, &smooth})
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 16; ++x) {
                    CHECK(r->channel(x, y, 0) >= 0.0f);
                    CHECK(r->channel(x, y, 0) <= 1.0f);
                }
        // Averaging its neighbours' values narrows the spread of the smooth one; the flat one takes
        // each cell's own value, so neighbouring pixels (most of them in one cell) mostly agree.
        CHECK(spreadOf(smooth) < 0.7 * spreadOf(flat));
        auto agreeing = [](test::RenderOutcome const& r) {
            int same = 0;
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x + 1 < 16; ++x) same += std::fabs(r.channel(x, y, 0) - r.channel(x + 1, y, 0)) < 0.01f;
            return same;
        };
        CHECK(agreeing(flat) > 16 * 15 / 2);
        CHECK(agreeing(flat) > agreeing(smooth));
        auto turbulent = cells(one + "\"float jitter\" [1] \"float smoothness\" [1] \"int turbulent\" [1]");
        CHECK_FALSE(turbulent.rgba == smooth.rgba);
    }
}

TEST_CASE("PxrFlakes tilts the normal inside its flakes and marks them in resultA", "[patterns]") {
    // One flake per unit cell of a connected manifold's (s, t); without jitter it is centred, and of size 1 it
    // fills the circle inscribed in the cell: here the whole square is one cell.
    auto shown = [](std::string const& parameters, std::string const& output) {
        return test::renderRib(kHead + "Pattern \"PxrManifold2D\" \"m\"\n"
                                       "Pattern \"PxrFlakes\" \"f\" \"float flakeFreq\" [1] \"float jitter\" [0] "
                                       "\"reference struct manifold\" [\"m:result\"] " +
                                   parameters + "\n" + output + kSquare,
                               fewSamples());
    };
    std::string const mask = "Pattern \"PxrToFloat3\" \"a\" \"reference float input\" [\"f:resultA\"]\n"
                             "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"a:resultRGB\"]\n";
    std::string const normal = "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"f:resultN\"]\n";
    std::string const surface = "Pattern \"PxrVariable\" \"n\" \"string variable\" [\"Nn\"]\n"
                                "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"n:resultRGB\"]\n";
    auto flaked = shown("", mask);
    CHECK(flaked.channel(7, 8, 0) == 1.0f);
    CHECK(flaked.channel(8, 7, 0) == 1.0f);
    for (int corner : {0, 15}) {
        CHECK(flaked.channel(corner, 0, 0) == 0.0f);
        CHECK(flaked.channel(corner, 15, 0) == 0.0f);
    }
    CHECK(shown("\"float density\" [0]", mask).channel(8, 8, 0) == 0.0f);  // no cell has a flake
    auto tilted = shown("", normal);
    auto plain = shown("", surface);
    auto at = [](test::RenderOutcome const& r, int x, int y) {
        return RtVector3(r.channel(x, y, 0), r.channel(x, y, 1), r.channel(x, y, 2));
    };
    RtVector3 const inside = at(tilted, 8, 8), outside = at(tilted, 0, 0), own = at(plain, 8, 8);
    CHECK(inside.Length() == Approx(1.0f).margin(1e-3));
    CHECK((inside - own).Length() > 0.05f);  // tilted in the flake
    CHECK((outside - at(plain, 0, 0)).Length() < 1e-5f);  // the surface's own normal elsewhere
    CHECK((at(shown("\"float flakeAmount\" [0]", normal), 8, 8) - own).Length() < 1e-5f);  // no tilt asked for
    // In object space (no manifold), at a fine frequency: some points in flakes, some not.
    auto fine = test::renderRib(kHead + "Pattern \"PxrFlakes\" \"f\" \"float flakeFreq\" [8] \"float size\" [1.5]\n" +
                                    mask + kSquare,
                                fewSamples());
    double const covered = test::meanChannel(fine, 0, [](int, int) { return true; });
    CHECK(covered > 0.05);
    CHECK(covered < 0.95);
}

TEST_CASE("PxrFractal is a noise in 0 to 1 that varies across the surface and with its variation",
          "[patterns]") {
    auto noise = [](std::string const& parameters) {
        return test::renderRib(kHead + "Pattern \"PxrFractal\" \"f\" \"float frequency\" [4] " + parameters +
                                   "\nPattern \"PxrToFloat3\" \"grey\" \"reference float input\" [\"f:resultF\"]\n"
                                   "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"grey:resultRGB\"]\n" +
                                   kSquare,
                               fewSamples());
    };
    auto stats = [](test::RenderOutcome const& r) {
        double sum = 0, squares = 0, lowest = 1, highest = 0;
        int const n = r.width * r.height;
        for (int y = 0; y < r.height; ++y)
            for (int x = 0; x < r.width; ++x) {
                double const v = r.channel(x, y, 0);
                sum += v;
                squares += v * v;
                lowest = std::min(lowest, v);
                highest = std::max(highest, v);
            }
        double const mean = sum / n;
        return std::array<double, 4>{mean, std::sqrt(std::max(0.0, squares / n - mean * mean)), lowest, highest};
    };
    auto const plain = noise("");
    auto const [mean, spread, lowest, highest] = stats(plain);
    CHECK(lowest >= 0.0);
    CHECK(highest <= 1.0);
    CHECK(mean == Approx(0.5).margin(0.15));
    CHECK(spread > 0.03);  // it varies: not a constant
    // Another variation is another pattern; the same one, the same pattern.
    auto const varied = noise("\"float variation\" [1]");
    double largest = 0;
    for (size_t i = 0; i < plain.rgba.size(); ++i) largest = std::max(largest, double(std::fabs(plain.rgba[i] - varied.rgba[i])));
    CHECK(largest > 0.05);
    CHECK(noise("").rgba == plain.rgba);
    // Turbulent: absolute values, so darker on average, never below 0.
    auto const [turbulentMean, turbulentSpread, turbulentLowest, turbulentHighest] = stats(noise("\"int turbulent\" [1]"));
    CHECK(turbulentMean < mean);
    CHECK(turbulentLowest >= 0.0);
    CHECK(turbulentSpread > 0.01);
    (void)turbulentHighest;
    CHECK(noise("\"float erosion\" [0.5]").anyMessageContains("PxrFractal: erosion is not modelled"));
}

TEST_CASE("a polygon without texture coordinates has a (u v) per face as in RenderMan: a quad runs 0 to 1 across",
          "[patterns][primvars]") {
    // The square as a Polygon, corners written from the top left: (u, v) = (0, 0) there, (1, 0) at the
    // top right, (1, 1) at the bottom right. A T ramp through t = v then lies in straight rows (split
    // into triangles, each with its own barycentric (u, v), it would bend at the diagonal).
    auto r = test::renderRib(kHead + "Pattern \"PxrVariable\" \"st\" \"string variable\" [\"t\"]\n"
                                     "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"st:resultRGB\"]\n"
                                     "Polygon \"P\" [-1 1 0  1 1 0  1 -1 0  -1 -1 0]\n",
                             fewSamples());
    for (int x : {1, 6, 9, 14})
        for (int y : {1, 7, 12}) CHECK(r.channel(x, y, 0) == Approx(1.0f - pixelV(y)).margin(0.02));
    auto u = test::renderRib(kHead + "Pattern \"PxrVariable\" \"u\" \"string variable\" [\"u\"]\n"
                                     "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"u:resultRGB\"]\n"
                                     "PointsPolygons [4] [0 1 2 3] \"P\" [-1 1 0  1 1 0  1 -1 0  -1 -1 0]\n",
                             fewSamples());
    for (int x : {1, 6, 9, 14})
        for (int y : {1, 7, 12}) CHECK(u.channel(x, y, 0) == Approx(pixelU(x)).margin(0.02));
    // A triangle keeps its barycentric coordinates: u along its first edge, v along its last.
    auto tri = test::renderRib(kHead + "Pattern \"PxrVariable\" \"v\" \"string variable\" [\"v\"]\n"
                                       "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"v:resultRGB\"]\n"
                                       "Polygon \"P\" [-1 -1 0  1 -1 0  -1 1 0]\n",
                               fewSamples());
    CHECK(tri.channel(2, 4, 0) == Approx(pixelV(4)).margin(0.02));
}

TEST_CASE("patterns run only for the parameters asked for, each once per batch", "[patterns]") {
    SECTION("no connections: no pattern runs, no texture is read, unreached patterns are not even loaded") {
        auto r = test::renderRib(kHead + "Pattern \"PxrTexture\" \"t\" \"string filename\" [\"none.tx\"]\n"
                                         "Bxdf \"PxrConstant\" \"c\" \"color emitColor\" [0.5 0.5 0.5]\n" +
                                     kSquare,
                                 fewSamples());
        CHECK(r.stats.patternEvaluations == 0u);
        CHECK(r.stats.textureLookups == 0u);
        for (auto const& plugin : r.stats.plugins) CHECK(plugin.find("PxrTexture") == std::string::npos);
        CHECK_FALSE(r.anyMessageContains("none.tx"));
    }
    SECTION("two inputs of a mix connected to one node: that node still runs once per batch") {
        auto r = test::renderRib(kHead + "Pattern \"PxrVariable\" \"u\" \"string variable\" [\"u\"]\n"
                                         "Pattern \"PxrMix\" \"m\" \"reference color color1\" [\"u:resultRGB\"] "
                                         "\"reference color color2\" [\"u:resultRGB\"]\n"
                                         "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"m:resultRGB\"]\n" +
                                     kSquare,
                                 fewSamples());
        REQUIRE(r.stats.batches > 0u);
        CHECK(r.stats.patternEvaluations == 2 * r.stats.batches);  // the mix and the variable, once each
        CHECK(r.stats.patternPoints == 2 * r.stats.shadePoints);
        CHECK(r.channel(3, 3, 0) == Approx(pixelU(3)).margin(0.01));
    }
}

TEST_CASE("PxrTexture reads what OpenImageIO's texture system reads, a missing file is magenta and a warning",
          "[patterns][textures]") {
    // A 64 x 64 image: red grows with x, green with y (top row 0), blue constant.
    int const size = 64;
    std::vector<float> pixels(static_cast<size_t>(size * size * 3));
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            float* p = &pixels[static_cast<size_t>(3 * (y * size + x))];
            p[0] = static_cast<float>(x) / (size - 1);
            p[1] = static_cast<float>(y) / (size - 1);
            p[2] = 0.25f;
        }
    std::string const file = test::outputDir() + "/ramp.exr";
    writeImage(file, pixels, size, size, 3);

    SECTION("lookups match the texture system at the same coordinates") {
        auto r = test::renderRib(kHead + "Pattern \"PxrTexture\" \"t\" \"string filename\" [\"" + file +
                                     "\"] \"int invertT\" [0]\n"
                                     "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"t:resultRGB\"]\n" +
                                     kSquare,
                                 fewSamples());
        CHECK(r.stats.textureLookups > 0u);
        OIIO::TextureSystem* system = OIIO::TextureSystem::create(/*shared=*/true);  // never destroyed: see OiioTextures
        OIIO::TextureOpt options;
        for (int x : {1, 6, 9, 14})
            for (int y : {2, 12}) {
                // With invertT off, t is v: the image's top row sits at v = 0.
                float expected[3];
                REQUIRE(system->texture(OIIO::ustring(file), options, pixelU(x), pixelV(y), 0, 0, 0, 0, 3, expected));
                CHECK(r.channel(x, y, 0) == Approx(expected[0]).margin(0.02));
                CHECK(r.channel(x, y, 1) == Approx(expected[1]).margin(0.02));
                CHECK(r.channel(x, y, 2) == Approx(0.25f).margin(1e-3));
            }
    }
    SECTION("invertT (RenderMan's default) flips t: the image's bottom row is t = 0") {
        auto r = test::renderRib(kHead + "Pattern \"PxrTexture\" \"t\" \"string filename\" [\"" + file + "\"]\n"
                                     "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"t:resultRGB\"]\n" +
                                     kSquare,
                                 fewSamples());
        CHECK(r.channel(8, 1, 1) < 0.15f);   // the top of the square (v near 1) shows the image's top row
        CHECK(r.channel(8, 14, 1) > 0.85f);
    }
    SECTION("blur widens the filter; lerp, filter and atlasStyle 0 are read as RenderMan writes them") {
        std::string const texture =
            "Pattern \"PxrTexture\" \"t\" \"string filename\" [\"" + file +
            "\"] \"int invertT\" [0] \"int lerp\" [1] \"int filter\" [1] \"int atlasStyle\" [0]";
        std::string const shaded =
            "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"t:resultRGB\"]\n" + kSquare;
        auto sharp = test::renderRib(kHead + texture + "\n" + shaded, fewSamples());
        auto blurred = test::renderRib(kHead + texture + " \"float blur\" [0.5]\n" + shaded, fewSamples());
        CHECK_FALSE(sharp.anyMessageContains("has no parameter"));
        // Blurred over half the image, the ramp's ends move towards its mean (0.5); its middle stays.
        for (int x : {0, 15})
            CHECK(std::fabs(blurred.channel(x, 8, 0) - 0.5f) <
                  std::fabs(sharp.channel(x, 8, 0) - 0.5f) - 0.2f);
        CHECK(blurred.channel(8, 8, 0) == Approx(sharp.channel(8, 8, 0)).margin(0.02));
        CHECK(blurred.channel(8, 8, 2) == Approx(0.25f).margin(1e-3));
    }
    SECTION("a grey image is grey; resultA is an image's alpha, 1 where it has none") {
        std::vector<float> grey(static_cast<size_t>(size * size), 0.4f), rgba(static_cast<size_t>(size * size * 4));
        for (size_t i = 0; i < rgba.size(); i += 4) {
            rgba[i] = 0.9f;
            rgba[i + 1] = 0.6f;
            rgba[i + 2] = 0.3f;
            rgba[i + 3] = 0.25f;
        }
        std::string const greyFile = test::outputDir() + "/grey.exr", rgbaFile = test::outputDir() + "/decal.exr";
        writeImage(greyFile, grey, size, size, 1);
        writeImage(rgbaFile, rgba, size, size, 4);
        auto shown = [](std::string const& image, std::string const& output) {
            auto r = test::renderRib(kHead + "Pattern \"PxrTexture\" \"t\" \"string filename\" [\"" + image + "\"]\n"
                                             "Pattern \"PxrMix\" \"alpha\" \"color color1\" [0 0 0] "
                                             "\"reference float mix\" [\"t:resultA\"]\n"
                                             "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"" + output + "\"]\n" +
                                         kSquare,
                                     fewSamples());
            return RtColorRGB(r.channel(8, 8, 0), r.channel(8, 8, 1), r.channel(8, 8, 2));
        };
        RtColorRGB const greyColour = shown(greyFile, "t:resultRGB");
        CHECK(greyColour.r == Approx(0.4f).margin(1e-3));
        CHECK(greyColour.g == Approx(0.4f).margin(1e-3));
        CHECK(greyColour.b == Approx(0.4f).margin(1e-3));
        CHECK(shown(greyFile, "alpha:resultRGB").r == Approx(1.0f).margin(1e-3));
        CHECK(shown(file, "alpha:resultRGB").r == Approx(1.0f).margin(1e-3));
        CHECK(shown(rgbaFile, "alpha:resultRGB").r == Approx(0.25f).margin(1e-3));
        CHECK(shown(rgbaFile, "t:resultRGB").g == Approx(0.6f).margin(1e-3));
        // A decal laid over a base colour by its alpha, as exporters write it.
        auto decal = test::renderRib(kHead + "Pattern \"PxrTexture\" \"t\" \"string filename\" [\"" + rgbaFile + "\"]\n"
                                             "Pattern \"PxrBlend\" \"b\" \"reference color topRGB\" [\"t:resultRGB\"] "
                                             "\"reference float topA\" [\"t:resultA\"] \"color bottomRGB\" [0.1 0.1 0.1]\n"
                                             "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"b:resultRGB\"]\n" +
                                         kSquare,
                                     fewSamples());
        CHECK(decal.channel(8, 8, 0) == Approx(0.75f * 0.1f + 0.25f * 0.9f).margin(1e-3));
    }
    SECTION("a file that does not exist") {
        auto r = test::renderRib(kHead + "Pattern \"PxrTexture\" \"t\" \"string filename\" [\"no/such/maple.tx\"] "
                                         "\"color missingColor\" [1 0 1]\n"
                                         "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"t:resultRGB\"]\n" +
                                     kSquare,
                                 fewSamples());
        CHECK(r.anyMessageContains("texture \"no/such/maple.tx\" does not exist (looked for from the current folder"));
        CHECK(r.channel(8, 8, 0) == Approx(1.0f));
        CHECK(r.channel(8, 8, 1) == Approx(0.0f));
    }
}

TEST_CASE("classic paintedplastic multiplies Cs by its texture map at (s, t), and MakeTexture's texture is its picture",
          "[patterns][textures][classic]") {
    // A 64 x 64 image whose green grows from its top row (0) to its bottom row (1).
    int const size = 64;
    std::vector<float> pixels(static_cast<size_t>(size * size * 3), 0.0f);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) pixels[static_cast<size_t>(3 * (y * size + x) + 1)] = static_cast<float>(y) / (size - 1);
    std::string const picture = test::outputDir() + "/classic-ramp.exr";
    writeImage(picture, pixels, size, size, 3);
    // Ambient light only (Kd and Ks 0): each pixel is Cs * texture * Ka * ambient. The
    // patch's first two points are its top edge, where the classic t is 0.
    std::string const head = "Format 16 16 1\nProjection \"orthographic\"\nScreenWindow -1 1 -1 1\n";
    std::string const world = "WorldBegin\nTranslate 0 0 5\nLightSource \"ambientlight\" 1 \"intensity\" [1]\n"
                              "Color [0.5 1 1]\n";
    std::string const surface = "Surface \"paintedplastic\" \"Ka\" [1] \"Kd\" [0] \"Ks\" [0] \"texturename\" [\"ramp.tex\"]\n"
                                "Patch \"bilinear\" \"P\" [-1 1 0  1 1 0  -1 -1 0  1 -1 0]\nWorldEnd\n";

    SECTION("MakeTexture made ramp.tex from the picture: the image's top row is at t = 0, the patch's top") {
        auto r = test::renderRib("MakeTexture \"" + picture + "\" \"./ramp.tex\" \"periodic\" \"periodic\" \"gaussian\" 2 2\n" +
                                     head + world + surface,
                                 fewSamples());
        CHECK(r.messages.empty());
        CHECK(r.stats.textureLookups > 0u);
        for (int y : {2, 5, 10, 13}) CHECK(r.channel(8, y, 1) == Approx(1.0f - pixelV(y)).margin(0.03));
        CHECK(r.channel(8, 8, 0) == Approx(0.0f).margin(1e-6));  // Cs's red times the image's
    }
    SECTION("MakeLatLongEnvironment makes a texture the same way") {
        auto r = test::renderRib("MakeLatLongEnvironment \"" + picture + "\" \"ramp.tex\" \"gaussian\" 2 2\n" + head +
                                     world + surface,
                                 fewSamples());
        CHECK(r.messages.empty());
        CHECK(r.channel(8, 13, 1) == Approx(1.0f - pixelV(13)).margin(0.03));
    }
    SECTION("the texture file a file of Make requests alone writes holds the picture and its wrap modes") {
        MadeTexture made;
        made.picture = picture;
        made.wrapS = "clamp";
        made.wrapT = "black";
        std::string const texture = test::outputDir() + "/ramp-made.tex";  // RenderMan's name; TIFF inside
        std::filesystem::remove(texture);
        imageFiles().makeTexture(texture, made);
        ImagePixels const written = imageFiles().read(texture, "made texture");
        REQUIRE(written.width == size);
        REQUIRE(written.channels == 3);
        CHECK(written.pixels == pixels);
        auto input = OIIO::ImageInput::open(texture);
        REQUIRE(input);
        CHECK(input->spec().get_string_attribute("wrapmodes") == "clamp,black");
        CHECK(input->spec().tile_width > 0);          // tiled, as a texture is
        CHECK(input->seek_subimage(0, 1));            // and mip-mapped
        // A scene that names the written file, without making it, renders as one that makes it.
        std::string const named =
            "Surface \"paintedplastic\" \"Ka\" [1] \"Kd\" [0] \"Ks\" [0] \"texturename\" [\"" + texture +
            "\"]\nPatch \"bilinear\" \"P\" [-1 1 0  1 1 0  -1 -1 0  1 -1 0]\nWorldEnd\n";
        auto r = test::renderRib(head + world + named, fewSamples());
        CHECK(r.messages.empty());
        for (int y : {2, 5, 10, 13}) CHECK(r.channel(8, y, 1) == Approx(1.0f - pixelV(y)).margin(0.03));
        // An environment map is written as one.
        input.reset();
        made.environment = true;
        imageFiles().makeTexture(texture, made);
        input = OIIO::ImageInput::open(texture);
        REQUIRE(input);
        CHECK(input->spec().get_string_attribute("textureformat") == "LatLong Environment");
    }
    SECTION("a file that only makes textures is no scene to render: loading it as one says so") {
        std::string const path = test::outputDir() + "/make-only.rib";
        std::ofstream(path) << "MakeTexture \"" << picture << "\" \"ramp.tex\" \"periodic\" \"periodic\" \"box\" 1 1\n";
        Diagnostics diagnostics(false);
        CHECK_THROWS_WITH(loadScene(path, diagnostics), Catch::Contains("there is no WorldBegin") &&
                                                            Catch::Contains("(it only makes textures)"));
        // A wrap mode txmake does not have is said, and the texture wraps around.
        Scene scene = test::parseRib("MakeTexture \"" + picture + "\" \"ramp.tex\" \"repeat\" \"clamp\" \"box\" 1 1\n"
                                     "WorldBegin\n", diagnostics);
        CHECK(test::warningsContaining(diagnostics, "wrap mode \"repeat\" is not periodic, clamp or black") == 1);
        CHECK(scene.madeTextures.at("ramp.tex").wrapS == "periodic");
        CHECK(scene.madeTextures.at("ramp.tex").wrapT == "clamp");
    }
    SECTION("a dome light's image made by MakeLatLongEnvironment is its picture") {
        Diagnostics diagnostics(false);
        Scene scene = test::parseRib("MakeLatLongEnvironment \"" + picture + "\" \"sky.tex\" \"gaussian\" 2 2\nWorldBegin\n"
                                     "Light \"PxrDomeLight\" \"sky\" \"string lightColorMap\" [\"sky.tex\"]\n",
                                     diagnostics);
        CHECK(test::warningTexts(diagnostics).empty());
        test::parseRib("WorldBegin\nLight \"PxrDomeLight\" \"sky\" \"string lightColorMap\" [\"sky.tex\"]\n", diagnostics);
        CHECK(test::warningsContaining(diagnostics, "\"sky.tex\" does not exist") == 1);
    }
    SECTION("a shader of the scene's own that names a texture maps its colour with it, as paintedplastic does") {
        std::string const own = "Surface \"textura\" \"Ka\" [1] \"Kd\" [0] \"texturename\" [\"ramp.tex\"]\n"
                                "Patch \"bilinear\" \"P\" [-1 1 0  1 1 0  -1 -1 0  1 -1 0]\nWorldEnd\n";
        auto r = test::renderRib("MakeTexture \"" + picture + "\" \"./ramp.tex\" \"periodic\" \"periodic\" \"gaussian\" 2 2\n" +
                                     head + world + own,
                                 fewSamples());
        REQUIRE(r.messages.size() == 1u);
        CHECK(r.messages[0].text.find("rendered as \"matte\"") != std::string::npos);
        CHECK(r.messages[0].text.find("its texturename maps its colour") != std::string::npos);
        for (int y : {2, 5, 10, 13}) CHECK(r.channel(8, y, 1) == Approx(1.0f - pixelV(y)).margin(0.03));
        // A metal's texturename is its environment: not a colour map.
        auto metal = test::renderRib("MakeTexture \"" + picture + "\" \"./ramp.tex\" \"periodic\" \"periodic\" \"gaussian\" 2 2\n" +
                                         head + world + "Surface \"mymetal\" \"texturename\" [\"ramp.tex\"]\n" +
                                         "Patch \"bilinear\" \"P\" [-1 1 0  1 1 0  -1 -1 0  1 -1 0]\nWorldEnd\n",
                                     fewSamples());
        CHECK(metal.stats.textureLookups == 0u);
    }
    SECTION("a texture that is not there: one located warning, and the surface keeps Cs") {
        auto r = test::renderRib(head + world + surface, fewSamples());
        REQUIRE(r.messages.size() == 1u);
        INFO(r.messages[0].text);
        CHECK(r.messages[0].text.find("test.rib:8:53: Surface \"paintedplastic\": texture \"ramp.tex\" does not exist") !=
              std::string::npos);
        CHECK(r.channel(8, 8, 0) == Approx(0.5f).margin(1e-4));
        CHECK(r.channel(8, 8, 1) == Approx(1.0f).margin(1e-4));
    }
}

TEST_CASE("bad networks: located errors for wrong handles, outputs and types, warnings for what is missing",
          "[patterns][errors]") {
    auto fails = [](std::string const& body, std::string const& text) {
        CHECK_THROWS_WITH(test::renderRib(kHead + body + kSquare), Catch::Matchers::Contains(text));
    };
    SECTION("a handle not declared before: a located warning, and the parameter keeps the plugin's default") {
        // As RenderMan does, the render goes on without the connection (a public student scene
        // connects a PxrBump to a pattern it never declares).
        auto r = test::renderRib(kHead + "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"later:resultRGB\"]\n" +
                                     kSquare,
                                 fewSamples());
        CHECK(r.anyMessageContains("test.rib:7:24: Bxdf \"c\" parameter \"emitColor\" refers to pattern \"later\", "
                                   "which is not declared before it"));
        CHECK(r.anyMessageContains("left unconnected, at the plugin's default"));
        CHECK(r.channel(8, 8, 0) == Approx(1.0f).margin(1e-5));  // PxrConstant's default emitColor: white
        // A node naming itself (how a cycle would have to be written) is the same case: no cycle forms.
        auto cycle = test::renderRib(kHead + "Pattern \"PxrMix\" \"m\" \"reference color color1\" [\"m:resultRGB\"]\n"
                                             "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"m:resultRGB\"]\n" +
                                         kSquare,
                                     fewSamples());
        CHECK(cycle.anyMessageContains("Pattern \"m\" parameter \"color1\" refers to pattern \"m\", which is not declared before it"));
        CHECK(cycle.channel(8, 8, 0) == Approx(0.5f).margin(1e-5));  // PxrMix's defaults: black and white, mixed half and half
    }
    SECTION("an output the pattern does not have") {
        fails("Pattern \"PxrMix\" \"m\"\nBxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"m:resultColour\"]\n",
              "has no output \"resultColour\" (its outputs: resultRGB, resultR, resultG, resultB)");
        fails("Pattern \"PxrMix\" \"m\"\nBxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"m:resultRBG\"]\n",
              "has no output \"resultRBG\" (did you mean \"resultRGB\"? its outputs: resultRGB, resultR, resultG, "
              "resultB)");
    }
    SECTION("a float output into a colour") {
        fails("Pattern \"PxrTexture\" \"t\"\nBxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"t:resultR\"]\n",
              "is a color, but \"t:resultR\" is a float output");
    }
    SECTION("a reference without an output") {
        fails("Pattern \"PxrMix\" \"m\"\nBxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"m\"]\n",
              "a reference is \"handle:output\"");
    }
    SECTION("a pattern plugin that is not there: a warning, and the parameter keeps the plugin's default") {
        auto r = test::renderRib(kHead + "Pattern \"PxrOSL\" \"osl\"\n"
                                         "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"osl:Cout\"]\n" +
                                     kSquare,
                                 fewSamples());
        CHECK(r.anyMessageContains("Pattern \"osl\" cannot be used"));
        // Named as RenderMan's, and the RIB line is said once, at the start of the warning.
        CHECK(r.anyMessageContains("(\"PxrOSL\" is one of RenderMan's patterns, which this renderer does not "
                                   "have: Pattern plugin \"PxrOSL\" not found"));
        CHECK(r.channel(8, 8, 0) == Approx(1.0f));  // PxrConstant's default emitColor is white
    }
    SECTION("a pattern that is an OSL shader on the shader search path: said to be OSL, not a missing .so") {
        std::string const folder = test::outputDir() + "/osl-shaders";
        std::filesystem::create_directories(folder);
        std::ofstream(folder + "/dimples.oso") << "OpenShadingLanguage 1.00\nshader dimples\n";
        auto r = test::renderRib("Option \"searchpath\" \"string shader\" [\"" + folder + "\"]\n" + kHead +
                                     "Pattern \"dimples\" \"d\"\n"
                                     "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"d:Cout\"]\n" +
                                     kSquare,
                                 fewSamples());
        CHECK(r.anyMessageContains("Pattern \"d\" cannot be used (\"dimples\" is the OSL shader " + folder +
                                   "/dimples.oso, and this renderer runs only patterns written in C++"));
        CHECK_FALSE(r.anyMessageContains("searchpath"));  // the shader search path is read, not skipped
        CHECK(r.channel(8, 8, 0) == Approx(1.0f));
    }
    SECTION("a missing pattern plugin used by three Patterns: said once in full, the others counted") {
        std::string threeUses;
        for (char const* handle : {"a", "b", "c"})
            threeUses += std::string("Pattern \"PxrOSL\" \"") + handle + "\"\nBxdf \"PxrConstant\" \"c" + handle +
                         "\" \"reference color emitColor\" [\"" + handle + ":Cout\"]\n" + kSquare;
        auto r = test::renderRib(kHead + threeUses, fewSamples());
        int full = 0;
        for (auto const& m : r.messages) full += m.text.find("not found") != std::string::npos ? 1 : 0;
        CHECK(full == 1);
        CHECK(r.anyMessageContains("2 more Patterns of the missing plugin \"PxrOSL\" cannot be used either"));
    }
}

TEST_CASE("a primvar named like a parameter gives that parameter per-point values", "[patterns][primvars]") {
    auto r = test::renderRib(kHead + "Bxdf \"PxrConstant\" \"c\" \"color emitColor\" [0.5 0.5 0.5]\n"
                                     "Polygon \"P\" [-1 -1 0  0 -1 0  0 1 0  -1 1 0] "
                                     "\"varying color emitColor\" [0 1 0  1 1 0  1 1 0  0 1 0]\n"
                                     "Polygon \"P\" [0 -1 0  1 -1 0  1 1 0  0 1 0]\n",
                             fewSamples());
    // The left square ramps red from 0 to 1 across it; the right one keeps the Bxdf's own grey.
    CHECK(r.channel(1, 8, 0) == Approx(2.0f * pixelU(1)).margin(0.02));
    CHECK(r.channel(6, 8, 0) == Approx(2.0f * pixelU(6)).margin(0.02));
    CHECK(r.channel(6, 8, 1) == Approx(1.0f));
    CHECK(r.channel(12, 8, 0) == Approx(0.5f));
}

TEST_CASE("GetParamInfo tells a plugin which inputs are given, connected or left to their default",
          "[patterns][api]") {
    // The paraminfo test Bxdf emits (given's info / 2, connected's info / 2,
    // triple's array length / 4), asked of the parameter list and of the
    // shading context, or magenta where the two disagree.
    auto emitted = [](std::string const& params) {
        auto r = test::renderRib(
            kHead +
                "Pattern \"PxrMix\" \"tex\" \"color color1\" [0.2 0.4 0.8] \"float mix\" [0]\n"
                "Bxdf \"paraminfo\" \"p\" " +
                params + "\n" + kSquare,
            fewSamples());
        return Vec3(r.channel(8, 8, 0), r.channel(8, 8, 1), r.channel(8, 8, 2));
    };
    SECTION("nothing given: every input at its default, the array at its declared length") {
        CHECK(emitted("") == Vec3(0.0f, 0.0f, 0.75f));
    }
    SECTION("a value, a connection and an array of two") {
        Vec3 const c = emitted(
            "\"float given\" [1] \"reference color connected\" [\"tex:resultRGB\"] \"float[2] triple\" [4 "
            "5]");
        CHECK(c.x == Approx(0.5f * k_RixSCParameterListValue));
        CHECK(c.y == Approx(0.5f * k_RixSCNetworkValue));
        CHECK(c.z == Approx(0.25f * 2));
    }
}

TEST_CASE("a pattern written for RenderMan 22 (OutputSpec, baking methods) asks its own inputs' GetParamInfo",
          "[patterns][api]") {
    // connectioninfo outputs a grey of 0, 0.5 or 1 for its input left alone,
    // given a value, or connected.
    auto grey = [](std::string const& input) {
        auto r = test::renderRib(kHead + "Pattern \"PxrMix\" \"tex\" \"color color1\" [0.2 0.4 0.8] \"float mix\" [0]\n"
                                         "Pattern \"connectioninfo\" \"info\" " +
                                     input +
                                     "\n"
                                     "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"info:resultRGB\"]\n" +
                                     kSquare,
                                 fewSamples());
        return r.channel(8, 8, 1);
    };
    CHECK(grey("") == Approx(0.0f).margin(1e-6));
    CHECK(grey("\"color input\" [1 1 1]") == Approx(0.5f));
    CHECK(grey("\"reference color input\" [\"tex:resultRGB\"]") == Approx(1.0f));
}

TEST_CASE("a pattern with RenderMan's manifold structs: struct output and input, outputs computed only when read",
          "[patterns][api]") {
    // manifold's result is (s, t, 0) * scale, or its connected manifold's Q * scale;
    // resultS and resultT are its x and y, computed only where GetParamInfo says
    // something reads them (the other is handed back as k_RixSCInvalidDetail).
    auto shown = [](std::string const& patterns, std::string const& output) {
        return test::renderRib(kHead + patterns + "Pattern \"PxrMix\" \"show\" \"color color1\" [0 0 0] "
                                                  "\"color color2\" [1 1 1] \"reference float mix\" [\"" + output +
                                   "\"]\nBxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"show:resultRGB\"]\n" +
                                   kSquare,
                               fewSamples());
    };
    std::string const half = "Pattern \"manifold\" \"m1\" \"float scale\" [0.5]\n";
    auto s = shown(half, "m1:resultS");
    auto t = shown(half, "m1:resultT");
    for (int k : {1, 8, 14}) {
        CHECK(s.channel(k, 8, 0) == Approx(0.5f * pixelU(k)).margin(0.01));
        CHECK(t.channel(8, k, 0) == Approx(0.5f * pixelV(k)).margin(0.01));
    }
    // "reference struct manifold" joins m1's result (its Q) to m2's manifold input.
    auto chained = shown(half + "Pattern \"manifold\" \"m2\" \"float scale\" [4] "
                                "\"reference struct manifold\" [\"m1:result\"]\n",
                         "m2:resultS");
    for (int k : {1, 8, 14}) CHECK(chained.channel(k, 8, 0) == Approx(std::min(1.0f, 2.0f * pixelU(k))).margin(0.01));
    // A member by its own name: result.Q is the struct's point.
    auto member = shown(half + "Pattern \"manifold\" \"m2\" \"reference point manifold.Q\" [\"m1:result.Q\"]\n",
                        "m2:resultT");
    CHECK(member.channel(8, 4, 0) == Approx(0.5f * pixelV(4)).margin(0.01));
    // Unconnected, as exporters write every default out: "struct manifold" [] leaves the plugin's own
    // manifold; a struct given values says it ignores them.
    auto unconnected = shown("Pattern \"manifold\" \"m2\" \"float scale\" [0.5] \"struct manifold\" []\n",
                             "m2:resultS");
    for (int k : {1, 8, 14}) CHECK(unconnected.channel(k, 8, 0) == Approx(0.5f * pixelU(k)).margin(0.01));
    CHECK_FALSE(unconnected.anyMessageContains("manifold"));
    auto valued = shown("Pattern \"manifold\" \"m2\" \"float scale\" [0.5] \"struct manifold\" [1 2 3]\n",
                        "m2:resultS");
    CHECK(valued.channel(8, 8, 0) == Approx(0.5f * pixelU(8)).margin(0.01));
    CHECK(valued.anyMessageContains("parameter \"manifold\": a struct or filter reference holds no values"));
}

TEST_CASE("Transform moves points to object space, to a named coordinate system, and leaves unknown spaces alone",
          "[patterns][api]") {
    // A square scaled by half and moved 0.25 right: world x = 0.25 + 0.5 * object x.
    auto shownX = [](std::string const& space, std::string const& before = "") {
        return test::renderRib(kHead + before + "Pattern \"manifold\" \"m\" \"string space\" [\"" + space +
                                   "\"]\nPattern \"PxrMix\" \"show\" \"color color1\" [0 0 0] \"color color2\" [1 1 1] "
                                   "\"reference float mix\" [\"m:resultS\"]\n"
                                   "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"show:resultRGB\"]\n"
                                   "TransformBegin\nTranslate 0.25 0 0\nScale 0.5 0.5 0.5\n" + kSquare + "TransformEnd\n",
                               fewSamples());
    };
    auto worldX = [](int px) { return -1.0f + 2.0f * (static_cast<float>(px) + 0.5f) / 16.0f; };
    auto object = shownX("object");
    for (int px : {11, 13}) CHECK(object.channel(px, 8, 0) == Approx((worldX(px) - 0.25f) / 0.5f).margin(0.01));
    auto named = shownX("shifted", "TransformBegin\nTranslate 0.5 0 0\nCoordinateSystem \"shifted\"\nTransformEnd\n");
    for (int px : {12, 13}) CHECK(named.channel(px, 8, 0) == Approx(worldX(px) - 0.5f).margin(0.01));
    auto unknown = shownX("NDC");  // not known here: P stays in world space
    for (int px : {11, 13}) CHECK(unknown.channel(px, 8, 0) == Approx(worldX(px)).margin(0.01));

    SECTION("vectors skip the translation, normals take the inverse transpose") {
        // Squeezed to half its width in x only: object space stretches x by 2 for
        // positions and directions, and normals, which must stay perpendicular, shrink by 2.
        auto transformedX = [&](int transformAs) {
            return test::renderRib(kHead + "Pattern \"manifold\" \"m\" \"string space\" [\"object\"] "
                                   "\"int transformAs\" [" + std::to_string(transformAs) + "]\n"
                                   "Pattern \"PxrMix\" \"show\" \"color color1\" [0 0 0] \"color color2\" [1 1 1] "
                                   "\"reference float mix\" [\"m:resultS\"]\n"
                                   "Bxdf \"PxrConstant\" \"c\" \"reference color emitColor\" [\"show:resultRGB\"]\n"
                                   "TransformBegin\nTranslate 0.25 0 0\nScale 0.5 1 1\n" + kSquare + "TransformEnd\n",
                                   fewSamples());
        };
        auto vectors = transformedX(1), normals = transformedX(2);
        for (int px : {9, 10}) {
            CHECK(vectors.channel(px, 8, 0) == Approx(2.0f * worldX(px)).margin(0.01));
            CHECK(normals.channel(px, 8, 0) == Approx(0.5f * worldX(px)).margin(0.01));
        }
    }
}
