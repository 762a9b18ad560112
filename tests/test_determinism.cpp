// The same scene, seed and spp give the same image bit for bit, whatever the
// thread count; another seed gives another (equally valid) image.
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {
std::string chapter6Scene() {
    std::ifstream in(std::string(SCENES_DIR) + "/ch06/diffuse.rib");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}
}  // namespace

TEST_CASE("renders are bit-identical for 1 and 2 threads, and across runs", "[determinism]") {
    std::string rib = chapter6Scene();
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
