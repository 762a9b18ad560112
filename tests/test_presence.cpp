// Presence (cut-outs): a Bxdf that computes it (k_ComputesPresence and a
// RixOpacity, here the stock PxrDiffuse's and PxrConstant's "float presence")
// lets rays through where it says the surface is absent: camera rays, shadow
// rays and indirect rays alike, deterministically, and only in scenes that ask.
#include <catch2/catch.hpp>

#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {

// A red wall (a constant colour: no light needed) 10 units away, and, when
// `card` is given, a square card 5 units away in the middle of the view
// (pixels 8 to 15 lie wholly on it, pixels 7 and 16 partly).
std::string cardBeforeWall(std::string const& card) {
    return "Format 24 24 1\nProjection \"perspective\" \"fov\" [30]\nPixelSamples 8 8\n"
           "Integrator \"PxrDirectLighting\" \"d\"\nWorldBegin\n"
           "  AttributeBegin\n  Bxdf \"PxrConstant\" \"wall\" \"color emitColor\" [1 0 0]\n"
           "  Polygon \"P\" [-10 -10 10  10 -10 10  10 10 10  -10 10 10]\n  AttributeEnd\n" +
           (card.empty() ? "" : "  AttributeBegin\n  " + card +
                                    "\n  Patch \"bilinear\" \"P\" [-0.5 -0.5 5  0.5 -0.5 5  -0.5 0.5 5  0.5 0.5 5]\n"
                                    "  AttributeEnd\n") +
           "WorldEnd\n";
}

bool inCard(int x, int y) { return x >= 8 && x < 16 && y >= 8 && y < 16; }
bool clearOfCard(int x, int y) { return x < 6 || x > 17 || y < 6 || y > 17; }

// A floor lit by a distant light from straight above, seen from above, and,
// when `card` is given, a card between them that camera rays do not see.
std::string floorUnderCard(std::string const& card) {
    return "Format 24 24 1\nProjection \"perspective\" \"fov\" [30]\nPixelSamples 4 4\n"
           "Integrator \"PxrDirectLighting\" \"d\"\n"
           "Rotate -90 1 0 0\nTranslate 0 -10 0\n"  // looking straight down from 10 units up
           "WorldBegin\n"
           "  AttributeBegin\n  Rotate 90 1 0 0\n  Light \"PxrDistantLight\" \"sun\" \"float intensity\" [50000]\n"
           "  AttributeEnd\n"
           "  AttributeBegin\n  Bxdf \"PxrDiffuse\" \"floor\" \"color diffuseColor\" [1 1 1]\n"
           "  Polygon \"P\" [-10 0 -10  10 0 -10  10 0 10  -10 0 10]\n  AttributeEnd\n" +
           (card.empty() ? ""
                         : "  AttributeBegin\n  Attribute \"visibility\" \"int camera\" [0]\n  " + card +
                               "\n  Polygon \"P\" [-1 2 -1  1 2 -1  1 2 1  -1 2 1]\n  AttributeEnd\n") +
           "WorldEnd\n";
}

double meanRed(test::RenderOutcome const& r, bool card) {
    return test::meanChannel(r, 0, [&](int x, int y) { return card ? inCard(x, y) : clearOfCard(x, y); });
}

bool simulated(RenderStats const& stats, std::string const& effect) {
    for (auto const& name : stats.effects.simulated)
        if (name.find(effect) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE("camera rays pass a surface where its presence is 0 and stop where it is 1", "[presence]") {
    auto open = test::renderRib(cardBeforeWall(""));
    auto absent = test::renderRib(cardBeforeWall("Bxdf \"PxrDiffuse\" \"card\" \"float presence\" [0]"));
    auto present = test::renderRib(cardBeforeWall("Bxdf \"PxrDiffuse\" \"card\" \"float presence\" [1]"));
    // Absent: the wall shows through, exactly as with no card at all.
    CHECK(meanRed(absent, true) == Approx(meanRed(open, true)).epsilon(1e-6));
    CHECK(meanRed(open, true) == Approx(1.0));
    CHECK(absent.stats.presencePoints > 0u);
    CHECK(simulated(absent.stats, "presence"));
    // Present (the default, written out): an unlit card, black.
    CHECK(meanRed(present, true) < 1e-6);
    CHECK(present.stats.presencePoints == 0u);  // presence 1 asks for nothing
    // The pixels around the card see the wall either way.
    CHECK(meanRed(present, false) == Approx(meanRed(open, false)).epsilon(1e-6));
}

TEST_CASE("a fractional presence stops that fraction of the rays", "[presence]") {
    auto quarter = test::renderRib(cardBeforeWall("Bxdf \"PxrDiffuse\" \"card\" \"float presence\" [0.25]"));
    // 64 pixels x 64 samples: 4096 draws; three standard deviations of the mean are 0.02.
    CHECK(meanRed(quarter, true) == Approx(0.75).margin(0.02));
    // The same scene with one thread and with two gives the same image.
    RenderSettings one, two;
    one.threads = 1;
    two.threads = 2;
    auto single = test::renderRib(cardBeforeWall("Bxdf \"PxrDiffuse\" \"card\" \"float presence\" [0.25]"), one);
    auto dual = test::renderRib(cardBeforeWall("Bxdf \"PxrDiffuse\" \"card\" \"float presence\" [0.25]"), two);
    CHECK(single.rgba == dual.rgba);
}

TEST_CASE("presence can come from a pattern: a card fading out along u", "[presence]") {
    auto faded = test::renderRib(cardBeforeWall("Pattern \"PxrVariable\" \"u\" \"string variable\" [\"u\"]\n"
                                                "  Bxdf \"PxrConstant\" \"card\" \"color emitColor\" [0 0 1]"
                                                " \"reference float presence\" [\"u:resultF\"]"));
    // Presence u runs from 0 at one side of the card to 1 at the other: the
    // card's blue and the wall's red trade places across it, and together make 1.
    auto column = [&](int c, int x) { return test::meanChannel(faded, c, [&](int px, int y) { return px == x && inCard(px, y); }); };
    double const redLeft = column(0, 8), redRight = column(0, 15);
    CHECK(std::fabs(redLeft - redRight) > 0.5);
    CHECK(column(0, 8) + column(2, 8) == Approx(1.0).margin(1e-5));
    CHECK(column(0, 15) + column(2, 15) == Approx(1.0).margin(1e-5));
    CHECK(faded.stats.presencePoints > 0u);
}

TEST_CASE("shadow rays pass a cut-out: the floor under an absent card is lit", "[presence]") {
    auto open = test::renderRib(floorUnderCard(""));
    auto absent = test::renderRib(floorUnderCard("Bxdf \"PxrDiffuse\" \"card\" \"float presence\" [0]"));
    auto solid = test::renderRib(floorUnderCard("Bxdf \"PxrDiffuse\" \"card\""));
    auto half = test::renderRib(floorUnderCard("Bxdf \"PxrDiffuse\" \"card\" \"float presence\" [0.5]"));
    auto shade = [](test::RenderOutcome const& r) {
        return test::meanChannel(r, 0, [](int x, int y) { return x >= 10 && x < 14 && y >= 10 && y < 14; });
    };
    REQUIRE(shade(open) > 0.1);
    CHECK(shade(solid) < 1e-6);  // the card's shadow
    CHECK(shade(absent) == Approx(shade(open)).epsilon(1e-6));
    CHECK(shade(half) == Approx(0.5 * shade(open)).epsilon(0.1));
}

TEST_CASE("indirect rays pass a cut-out too", "[presence]") {
    // The floor lit only by a glowing ceiling; a card between them, unseen by the camera.
    auto scene = [](std::string const& card) {
        std::string rib = floorUnderCard(card);
        size_t const sun = rib.find("  AttributeBegin\n  Rotate 90"), end = rib.find("AttributeEnd\n", sun);
        rib.replace(sun, end + 13 - sun,
                    "  AttributeBegin\n  Attribute \"visibility\" \"int camera\" [0]\n"
                    "  Bxdf \"PxrConstant\" \"sky\" \"color emitColor\" [1 1 1]\n"
                    "  Polygon \"P\" [-100 8 -100  -100 8 100  100 8 100  100 8 -100]\n  AttributeEnd\n");
        return test::withIntegrator(rib, "Integrator \"PxrPathTracer\" \"p\"");
    };
    auto middle = [](test::RenderOutcome const& r) {
        return test::meanChannel(r, 0, [](int x, int y) { return x >= 10 && x < 14 && y >= 10 && y < 14; });
    };
    auto open = test::renderRib(scene(""));
    auto absent = test::renderRib(scene("Bxdf \"PxrDiffuse\" \"card\" \"float presence\" [0]"));
    auto solid = test::renderRib(scene("Bxdf \"PxrDiffuse\" \"card\""));
    REQUIRE(middle(open) > 0.1);
    CHECK(middle(solid) < 0.9 * middle(open));  // the card hides part of the ceiling
    CHECK(middle(absent) == Approx(middle(open)).epsilon(1e-6));
}

TEST_CASE("a classic Opacity below 1 shows what lies behind, and lets that share of the light through",
          "[presence][rib]") {
    // Surface "constant" shows Cs Os; a quarter present with Cs Os / 0.25 where it is, it composites as
    // 0.25 of green over 0.75 of the red wall.
    auto quarter = test::renderRib(cardBeforeWall("Color [0 1 0]\n  Opacity [0.25 0.25 0.25]\n  Surface \"constant\""));
    CHECK(meanRed(quarter, true) == Approx(0.75).margin(0.02));
    CHECK(test::meanChannel(quarter, 1, inCard) == Approx(0.25).margin(0.02));
    CHECK_FALSE(quarter.anyMessageContains("Opacity"));  // a grey opacity is rendered as it is meant
    // A shader this renderer does not have stands in as PxrDiffuse, and shows through as the shader would.
    auto unknown = test::renderRib(cardBeforeWall("Opacity [0.5 0.5 0.5]\n  Surface \"glassy\""));
    CHECK(meanRed(unknown, true) == Approx(0.5).margin(0.02));
    // Shadows: half the light passes a card of Opacity 0.5.
    auto open = test::renderRib(floorUnderCard(""));
    auto half = test::renderRib(floorUnderCard("Opacity [0.5 0.5 0.5]\n  Surface \"matte\""));
    auto solid = test::renderRib(floorUnderCard("Surface \"matte\""));
    auto underCard = [](int x, int y) { return x >= 10 && x < 14 && y >= 10 && y < 14; };
    double const lit = test::meanChannel(open, 0, underCard);
    REQUIRE(lit > 0.1);
    CHECK(test::meanChannel(solid, 0, underCard) < 0.01 * lit);
    CHECK(test::meanChannel(half, 0, underCard) == Approx(0.5 * lit).margin(0.05 * lit));
    // A coloured Opacity shows through by its mean, and says so.
    auto tinted = test::renderRib(cardBeforeWall("Opacity [0 0.5 1]\n  Surface \"constant\""));
    CHECK(meanRed(tinted, true) == Approx(0.5).margin(0.02));
    CHECK(tinted.anyMessageContains("test.rib:11:3: Opacity with unequal colours is rendered as their mean"));
}
