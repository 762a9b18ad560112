// The same scene, seed and spp give the same image bit for bit, whatever the
// thread count; another seed gives another (equally valid) image.
#include <catch2/catch.hpp>

#include "support/RenderHelpers.h"

using namespace bxdflab;

TEST_CASE("renders are bit-identical for 1 and 2 threads, and across runs", "[determinism]") {
    std::string rib = test::readScene("ch06/diffuse.rib");
    REQUIRE_FALSE(rib.empty());
    RenderSettings settings;
    settings.spp = 4;
    settings.threads = 1;
    auto one = test::renderRib(rib, settings);
    settings.threads = 2;
    auto two = test::renderRib(rib, settings);
    auto again = test::renderRib(rib, settings);
    REQUIRE(one.rgba.size() == two.rgba.size());
    CHECK(one.rgba == two.rgba);
    CHECK(one.variance == two.variance);
    CHECK(two.rgba == again.rgba);
    CHECK(one.stats.shadowRays == two.stats.shadowRays);

    settings.seed = 7;
    auto reseeded = test::renderRib(rib, settings);
    CHECK(reseeded.rgba != two.rgba);
    // ...but it is the same picture: the means agree closely.
    auto all = [](int, int) { return true; };
    CHECK(test::meanChannel(reseeded, 0, all) == Approx(test::meanChannel(two, 0, all)).epsilon(0.01));
}

TEST_CASE("path tracing is bit-identical for 1 and 2 threads", "[determinism][integrators]") {
    std::string rib = test::withIntegrator(test::readScene("ch06/diffuse.rib"),
                                           "Integrator \"PxrPathTracer\" \"p\" \"int maxPathLength\" [5]");
    rib.replace(rib.find("Format 800 700 1"), 16, "Format 120 100 1");
    RenderSettings settings;
    settings.spp = 4;
    settings.threads = 1;
    auto one = test::renderRib(rib, settings);
    settings.threads = 2;
    auto two = test::renderRib(rib, settings);
    CHECK(one.rgba == two.rgba);
}
