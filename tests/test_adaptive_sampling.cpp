// Adaptive sampling: PixelVariance and the Hider's sample counts are read as
// RenderMan writes them, each pixel stops once its relative variance is as low
// as PixelVariance asks (or at maxsamples), and the image stays the same with
// any thread count and close to one rendered with every sample.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "render/SampleSchedule.h"
#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {

/// A lit sphere that fills the middle of the view; the corners see nothing.
std::string litSphere(std::string const& options) {
    return "Format 32 32 1\nProjection \"perspective\" \"fov\" [30]\n" + options +
           "Integrator \"PxrDirectLighting\" \"d\"\n"
           "WorldBegin\n"
           "  AttributeBegin\n  Translate 0 3 5\n  Rotate 90 1 0 0\n"
           "  Light \"PxrDiskLight\" \"key\" \"float intensity\" [20]\n  AttributeEnd\n"
           "  Translate 0 0 5\n  Bxdf \"PxrDiffuse\" \"d\"\n  Sphere 1 -1 1 360\n"
           "WorldEnd\n";
}

float largestVariance(test::RenderOutcome const& r, size_t pixel) {
    return std::max({r.variance[3 * pixel], r.variance[3 * pixel + 1], r.variance[3 * pixel + 2]});
}

/// The variance of the mean PixelVariance allows a pixel: PixelVariance times its value squared, its
/// value being its brightest channel and at least RenderMan's default dark falloff, 0.025.
double allowedVariance(test::RenderOutcome const& r, size_t pixel, double pixelVariance) {
    double const value = std::max({r.rgba[4 * pixel], r.rgba[4 * pixel + 1], r.rgba[4 * pixel + 2], 0.025f});
    return pixelVariance * value * value;
}

/// The sampling options a scene was read with.
void checkSampling(Scene const& scene, float pixelVariance, int spp, int minSamples, int minExtraSamples,
                   float darkFalloff) {
    CHECK(scene.pixelVariance == Approx(pixelVariance));
    CHECK(scene.spp == spp);
    CHECK(scene.minSamples == minSamples);
    CHECK(scene.minExtraSamples == minExtraSamples);
    CHECK(scene.darkFalloff == Approx(darkFalloff));
}

}  // namespace

TEST_CASE("PixelVariance and the Hider's sample counts are read as RenderMan writes them", "[rib][sampling]") {
    Diagnostics diagnostics(false);
    Scene hider = test::parseRib("PixelVariance 0.02\nHider \"raytrace\" \"int maxsamples\" [256] "
                                 "\"int minsamples\" [8] \"int minextrasamples\" [4] \"float darkfalloff\" [0.1] "
                                 "\"int incremental\" [1]\nWorldBegin\nWorldEnd\n",
                                 diagnostics);
    checkSampling(hider, 0.02f, 256, 8, 4, 0.1f);
    // RenderMan 21 and later: Option "Ri" and Option "hider", with the sampler's other controls read quietly.
    Scene later = test::parseRib("Option \"Ri\" \"float PixelVariance\" [0.015]\n"
                                 "Option \"hider\" \"int maxsamples\" [64] \"int minsamples\" [4] "
                                 "\"string adaptivemetric\" [\"variance\"] \"float darkfalloff\" [0.025]\n"
                                 "WorldBegin\nWorldEnd\n",
                                 diagnostics);
    checkSampling(later, 0.015f, 64, 4, -1, 0.025f);
    CHECK(test::warningsContaining(diagnostics, "") == 0);
    // Without them every pixel takes every sample.
    Scene plain = test::parseRib("WorldBegin\nWorldEnd\n", diagnostics);
    checkSampling(plain, 0.0f, 16, -1, -1, 0.025f);
    CHECK_THROWS_WITH(test::parseRib("Format 8 8 1\nPixelVariance -0.1\nWorldBegin\nWorldEnd\n", diagnostics),
                      Catch::Contains("test.rib:2:1") && Catch::Contains("PixelVariance must be 0"));
    CHECK_THROWS_WITH(test::parseRib("Hider \"raytrace\" \"int minsamples\" [-3]\nWorldBegin\nWorldEnd\n", diagnostics),
                      Catch::Contains("minsamples must be between -1"));
    CHECK_THROWS_WITH(test::parseRib("Hider \"raytrace\" \"float darkfalloff\" [2]\nWorldBegin\nWorldEnd\n", diagnostics),
                      Catch::Contains("darkfalloff must be between 0 and 1"));
}

TEST_CASE("The sample schedule follows RenderMan's rules for minsamples and minextrasamples", "[sampling]") {
    SampleSchedule const automatic = sampleSchedule(1024, 0.01f, -1, -1, 0.025f);
    CHECK(automatic.adaptive());
    CHECK(automatic.first == 32);  // the square root of maxsamples
    CHECK(automatic.step == 32);   // minextrasamples: minsamples
    CHECK(sampleSchedule(1024, 0.01f, 0, 0, 0.025f).first == 32);
    CHECK(sampleSchedule(1024, 0.01f, 1, -1, 0.025f).first == 2);  // one sample has no variance to test
    CHECK(sampleSchedule(100, 0.01f, 8, 3, 0.025f).step == 3);
    // No PixelVariance, or minsamples at maxsamples: every pixel takes every sample at once.
    CHECK_FALSE(sampleSchedule(1024, 0.0f, 16, -1, 0.025f).adaptive());
    CHECK(sampleSchedule(1024, 0.0f, 16, -1, 0.025f).first == 1024);
    CHECK_FALSE(sampleSchedule(64, 0.01f, 100, -1, 0.025f).adaptive());
    CHECK_FALSE(sampleSchedule(1, 0.01f, -1, -1, 0.025f).adaptive());
    // Settled: the variance of the mean at most PixelVariance times the value squared, dark values
    // counting as the dark falloff.
    CHECK(automatic.settled(0.0099 * 0.25, 0.5));
    CHECK_FALSE(automatic.settled(0.0101 * 0.25, 0.5));
    CHECK(automatic.settled(0.0099 * 0.025 * 0.025, 0.0));
    CHECK_FALSE(automatic.settled(0.011 * 0.025 * 0.025, 0.001));
    CHECK(automatic.settled(0.0, 0.0));  // a pixel whose samples all agree
}

TEST_CASE("Adaptive sampling stops each pixel once its relative variance is at most PixelVariance",
          "[render][sampling]") {
    double const pixelVariance = 0.001;
    std::string const rib = litSphere("PixelVariance 0.001\nHider \"raytrace\" \"int maxsamples\" [1024] "
                                      "\"int minsamples\" [16]\n");
    RenderSettings oneThread, twoThreads;
    oneThread.threads = 1;
    twoThreads.threads = 2;
    test::RenderOutcome const adaptive = test::renderRib(rib, oneThread);
    REQUIRE(adaptive.samples.size() == 32u * 32u);
    int stoppedEarly = 0, tookAll = 0;
    long long total = 0;
    for (size_t i = 0; i < adaptive.samples.size(); ++i) {
        int const n = adaptive.samples[i];
        total += n;
        // Tests come every minsamples samples, from minsamples to maxsamples.
        CHECK(n >= 16);
        CHECK(n <= 1024);
        CHECK((n % 16 == 0 || n == 1024));
        if (n < 1024) {
            ++stoppedEarly;
            CHECK(largestVariance(adaptive, i) <= allowedVariance(adaptive, i, pixelVariance) * (1 + 1e-5));
        } else {
            ++tookAll;
        }
    }
    // The empty corners (no variance at all) stop at the first test, the sphere's lit side takes more,
    // and its rim, half sky and half sphere, takes them all.
    CHECK(adaptive.samples[0] == 16);
    CHECK(adaptive.stats.samplesTaken.least == 16);
    CHECK(adaptive.stats.samplesTaken.most == 1024);
    CHECK(stoppedEarly > 0);
    CHECK(tookAll > 0);
    CHECK(adaptive.stats.cameraRays == static_cast<uint64_t>(total));
    CHECK(adaptive.stats.samplesTaken.mean == Approx(static_cast<double>(total) / (32 * 32)));
    CHECK(adaptive.stats.samplesTaken.mean < 200.0);
    CHECK(std::any_of(adaptive.stats.effects.simulated.begin(), adaptive.stats.effects.simulated.end(),
                      [](std::string const& effect) { return effect.find("adaptive sampling") == 0; }));

    // Which pixel stops when depends on its own samples alone: the same image with two threads.
    test::RenderOutcome const again = test::renderRib(rib, twoThreads);
    CHECK(again.rgba == adaptive.rgba);
    CHECK(again.samples == adaptive.samples);

    // Each pixel agrees with the same pixel rendered with every sample, within what PixelVariance
    // allows it (a pixel whose first samples all missed the sphere's rim stops with a variance of 0,
    // a little from its value; one pixel in a thousand may stray that far by chance).
    RenderSettings everySample = oneThread;
    everySample.pixelVariance = 0.0f;
    test::RenderOutcome const full = test::renderRib(rib, everySample);
    CHECK(full.stats.cameraRays == 32u * 32u * 1024u);
    CHECK(full.stats.samplesTaken.least == 1024);
    int strays = 0;
    for (size_t i = 0; i < full.samples.size(); ++i) {
        double const allowed =
            std::max<double>(largestVariance(adaptive, i), allowedVariance(adaptive, i, pixelVariance));
        double const spread = std::sqrt(allowed + largestVariance(full, i));
        if (std::abs(adaptive.rgba[4 * i] - full.rgba[4 * i]) > 4.0 * spread) ++strays;
    }
    CHECK(strays <= 2);
}

TEST_CASE("Without PixelVariance every pixel takes every sample, and the report says why", "[render][sampling]") {
    test::RenderOutcome const plain = test::renderRib(litSphere("PixelSamples 4 4\n"));
    CHECK(plain.stats.cameraRays == 32u * 32u * 16u);
    CHECK(plain.stats.samplesTaken.least == 16);
    CHECK(plain.stats.samplesTaken.most == 16);
    bool said = false;
    for (auto const& [effect, reason] : plain.stats.effects.skipped)
        said |= effect == "adaptive sampling" && reason.find("no PixelVariance") != std::string::npos;
    CHECK(said);
    // PxrVCM adds light subpaths to whichever pixel they land in, so it keeps every sample, with a warning.
    std::string vcm = test::withIntegrator(litSphere("PixelVariance 0.01\nPixelSamples 4 4\n"),
                                           "Integrator \"PxrVCM\" \"v\"");
    test::RenderOutcome const joined = test::renderRib(vcm);
    CHECK(joined.stats.samplesTaken.least == 16);
    CHECK(joined.anyMessageContains("PixelVariance is not applied"));
}
