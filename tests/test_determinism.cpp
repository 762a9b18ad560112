// The same scene, seed and spp give the same image bit for bit, whatever the
// thread count; another seed gives another (equally valid) image.
#include <catch2/catch.hpp>

#include "render/Renderer.h"
#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {
/// `rib` at 4 spp with `threads` worker threads and `seed`.
test::RenderOutcome render(std::string const& rib, int threads, uint32_t seed = 0) {
    RenderSettings settings;
    settings.spp = 4;
    settings.threads = threads;
    settings.seed = seed;
    return test::renderRib(rib, settings);
}
}  // namespace

TEST_CASE("renders are bit-identical for 1 and 2 threads, and across runs", "[determinism][heavy]") {
    std::string rib = test::readScene("ch06/diffuse.rib");
    REQUIRE_FALSE(rib.empty());
    auto one = render(rib, 1), two = render(rib, 2), again = render(rib, 2);
    REQUIRE(one.rgba.size() == two.rgba.size());
    CHECK(one.rgba == two.rgba);
    CHECK(one.variance == two.variance);
    CHECK(two.rgba == again.rgba);
    CHECK(one.stats.shadowRays == two.stats.shadowRays);

    auto reseeded = render(rib, 2, 7);
    CHECK(reseeded.rgba != two.rgba);
    // ...but it is the same picture: the means agree closely.
    auto all = [](int, int) { return true; };
    CHECK(test::meanChannel(reseeded, 0, all) == Approx(test::meanChannel(two, 0, all)).epsilon(0.01));
}

TEST_CASE("path tracing is bit-identical for 1 and 2 threads", "[determinism][integrators]") {
    std::string rib = test::withIntegrator(test::readScene("ch06/diffuse.rib"),
                                           "Integrator \"PxrPathTracer\" \"p\" \"int maxPathLength\" [5]");
    rib.replace(rib.find("Format 800 700 1"), 16, "Format 120 100 1");
    CHECK(render(rib, 1).rgba == render(rib, 2).rgba);
}

TEST_CASE("bidirectional path tracing is bit-identical for 1 and 2 threads", "[determinism][integrators][vcm]") {
    std::string rib = test::readScene("ch04/caustic.rib");
    rib.replace(rib.find("Format 320 240 1"), 16, "Format 64 48 1");
    CHECK(render(rib, 1).rgba == render(rib, 2).rgba);
}

TEST_CASE("a renderer that renders twice gives the same image and reports each render's own counts", "[determinism]") {
    Diagnostics diagnostics(false);
    Scene scene = test::parseRib(test::readScene("ch06/diffuse.rib"), diagnostics);
    RenderSettings settings;
    settings.spp = 2;
    settings.pluginPath = TEST_PLUGIN_DIR;
    Renderer renderer(scene, settings, diagnostics);
    std::vector<float> const first = renderer.render().rgba();
    RenderStats const once = renderer.stats();
    std::vector<float> const second = renderer.render().rgba();
    RenderStats const twice = renderer.stats();
    CHECK(first == second);
    REQUIRE(once.cameraRays == static_cast<uint64_t>(scene.xres) * static_cast<uint64_t>(scene.yres) * 2u);
    CHECK(twice.cameraRays == once.cameraRays);
    CHECK(twice.shadowRays == once.shadowRays);
    CHECK(twice.shadePoints == once.shadePoints);
    CHECK(twice.batches == once.batches);
    CHECK(twice.surfacePoints == once.surfacePoints);
}
