// PixelFilter: samples are drawn from the filter and a pixel is their mean
// (under negative lobes, the positive lobes' mean less the negative lobes'),
// so a pixel next to a sharp edge sees the filter's share of the bright side
// (negative where the filter is), each pixel stays an estimate of its own,
// and a filter that cannot be applied says so.
#include <catch2/catch.hpp>
#include <cmath>

#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {

/// A 16 x 4 image of a white half-plane whose edge runs between pixels 7 and 8, under `filter`.
std::string edgeScene(std::string const& filter) {
    return "Format 16 4 1\nProjection \"orthographic\"\nScreenWindow -1 1 -0.25 0.25\n" + filter +
           "WorldBegin\nTranslate 0 0 5\nBxdf \"PxrConstant\" \"c\" \"color emitColor\" [1 1 1]\n"
           "Polygon \"P\" [0 -1 0  4 -1 0  4 1 0  0 1 0]\n";
}

test::RenderOutcome render(std::string const& rib, int spp, int threads = 0) {
    RenderSettings settings = test::withSpp(spp);
    if (threads > 0) settings.threads = threads;
    return test::renderRib(rib, settings);
}

/// The share of a 1-D kernel's integral over [-h, h] that lies beyond `from` (midpoint rule).
template <class Kernel>
double shareBeyond(Kernel kernel, double h, double from) {
    double all = 0, beyond = 0;
    int const steps = 100000;
    for (int i = 0; i < steps; ++i) {
        double const x = -h + 2 * h * (i + 0.5) / steps;
        all += kernel(x);
        if (x > from) beyond += kernel(x);
    }
    return beyond / all;
}

}  // namespace

TEST_CASE("a pixel filter is what a pixel beside an edge sees of it", "[film][filter]") {
    // Pixel 7's centre is half a pixel from the edge: it sees the part of the filter beyond +0.5.
    SECTION("gaussian 2 2: exp(-2 x^2) over [-1, 1]") {
        auto r = render(edgeScene("PixelFilter \"gaussian\" 2 2\n"), 16384);
        double const expected = shareBeyond([](double x) { return std::exp(-2 * x * x); }, 1.0, 0.5);
        CHECK(r.channel(7, 1, 0) == Approx(expected).margin(0.01));
        CHECK(r.channel(8, 1, 0) == Approx(1 - expected).margin(0.01));
        CHECK(r.channel(6, 1, 0) == 0.0f);  // the filter does not reach
        CHECK(r.channel(9, 1, 0) == Approx(1.0f));
    }
    SECTION("triangle 2 2: an eighth") {
        auto r = render(edgeScene("PixelFilter \"triangle\" 2 2\n"), 16384);
        CHECK(r.channel(7, 1, 0) == Approx(0.125).margin(0.01));
    }
    SECTION(
        "catmull-rom 4 4: its negative lobe darkens the dark side below 0 and lifts the bright side above "
        "1") {
        auto r = render(edgeScene("PixelFilter \"catmull-rom\" 4 4\n"), 16384);
        // The cubic's integral from 1.5 to 2 is -1/76.8; the whole kernel integrates to 1.
        CHECK(r.channel(6, 1, 0) == Approx(-0.0130).margin(0.004));
        CHECK(r.channel(9, 1, 0) == Approx(1.0130).margin(0.004));
        // Each lobe's samples are averaged apart, so where the image is flat the lobe's
        // samples, counted below 0, add no noise even at a few samples.
        auto few = render(edgeScene("PixelFilter \"catmull-rom\" 4 4\n"), 16);
        for (int x : {12, 15}) CHECK(few.channel(x, 1, 0) == Approx(1.0f).epsilon(1e-6));
    }
    SECTION("catmull-rom 3 3 at 1 to 4 samples: no pixel goes black where the image is flat, and none beyond "
            "what the lobes can give") {
        // The lobes' shares of the filter: 1.118 positive, 0.118 negative. A mean of signed weights
        // left a pixel whose samples split evenly between the lobes black (a sixth of them at 2
        // samples), and let one negative sample on the dark side raise the rest by half.
        for (int spp : {1, 2, 3, 4}) {
            INFO(spp << " samples");
            auto r = render(edgeScene("PixelFilter \"catmull-rom\" 3 3\n"), spp);
            for (int y = 0; y < 4; ++y) {
                for (int x = 11; x < 16; ++x) CHECK(r.channel(x, y, 0) == Approx(1.0f).epsilon(1e-6));
                for (int x = 0; x < 5; ++x) CHECK(r.channel(x, y, 0) == 0.0f);
                for (int x = 5; x < 11; ++x) {
                    CHECK(r.channel(x, y, 0) >= -0.119f);
                    CHECK(r.channel(x, y, 0) <= 1.119f);
                }
            }
        }
    }
    SECTION("box 1 1, written out, is the image of a scene that names no filter, bit for bit") {
        CHECK(render(edgeScene("PixelFilter \"box\" 1 1\n"), 16).rgba == render(edgeScene(""), 16).rgba);
        CHECK(render(edgeScene(""), 16).channel(7, 1, 0) == 0.0f);
    }
}

TEST_CASE("a filtered image is the same with any thread count", "[film][filter][determinism]") {
    std::string const rib = edgeScene("PixelFilter \"mitchell\" 3 3\n");
    CHECK(render(rib, 8, 1).rgba == render(rib, 8, 2).rgba);
}

TEST_CASE("a pixel filter is read from PixelFilter or Option \"Ri\", and checked", "[film][filter][rib]") {
    SECTION("RenderMan 21 and later write it as Option \"Ri\"") {
        auto r = render(edgeScene("Option \"Ri\" \"string PixelFilterName\" [\"triangle\"] "
                                  "\"float[2] PixelFilterWidth\" [2 2]\n"),
                        16384);
        CHECK(r.channel(7, 1, 0) == Approx(0.125).margin(0.01));
        CHECK_FALSE(r.anyMessageContains("not used"));
    }
    SECTION("an unknown filter is named, with the ones there are, and the image keeps its box") {
        auto r = render(edgeScene("PixelFilter \"lanczoz\" 2 2\n"), 16);
        CHECK(r.anyMessageContains(
            "test.rib:4:1: PixelFilter \"lanczoz\" is not one this renderer has (box, "));
        CHECK(r.channel(7, 1, 0) == 0.0f);
    }
    SECTION("widths must be positive") {
        CHECK_THROWS_WITH(render(edgeScene("PixelFilter \"gaussian\" 0 2\n"), 1),
                          Catch::Matchers::Contains("test.rib:4:1") &&
                              Catch::Matchers::Contains("PixelFilter widths must be above 0"));
    }
    SECTION("light tracing adds to one pixel, so PxrVCM says the filter is not applied") {
        auto r = render(edgeScene("PixelFilter \"gaussian\" 2 2\nIntegrator \"PxrVCM\" \"v\"\n"), 16);
        CHECK(r.anyMessageContains("the pixel filter gaussian 2 x 2 is not applied"));
        CHECK(r.channel(7, 1, 0) == 0.0f);
    }
}
