// The autograder's statistics, against closed forms: the adaptive cell
// integration, the chi-squared test's pooling, and the render comparison.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "exercise/Exercise.h"
#include "image/RenderComparison.h"
#include "stats/DirectionTest.h"

using namespace bxdflab;

TEST_CASE("cell integration matches closed forms for the cosine and Phong densities", "[checks][stats]") {
    DirectionCells cells;
    SECTION("cosine: the integral over z0..z1, phi0..phi1 is (z1^2 - z0^2) (phi1 - phi0) / (2 pi)") {
        auto mass = integrateCells(cells, [](std::vector<Vec3> const& w) {
            std::vector<double> p;
            for (auto const& d : w) p.push_back(d.z > 0 ? d.z / M_PI : 0.0);
            return p;
        }, toleranceForSamples(1e6));
        double total = 0.0;
        for (int c = 0; c < cells.count(); ++c) {
            double z0, z1, p0, p1;
            cells.bounds(c, z0, z1, p0, p1);
            double exact = (z1 * z1 - z0 * z0) * (p1 - p0) / (2 * M_PI);
            CHECK(mass[static_cast<size_t>(c)] == Approx(exact).epsilon(1e-6));
            total += mass[static_cast<size_t>(c)];
        }
        CHECK(total == Approx(1.0).epsilon(1e-6));
    }
    SECTION("a sharp Phong lobe about the normal (n = 300): (z1^(n+1) - z0^(n+1)) (phi1 - phi0) / (2 pi)") {
        double const n = 300;
        auto mass = integrateCells(cells, [&](std::vector<Vec3> const& w) {
            std::vector<double> p;
            for (auto const& d : w) p.push_back(d.z > 0 ? (n + 1) / (2 * M_PI) * std::pow(double(d.z), n) : 0.0);
            return p;
        }, toleranceForSamples(1e6));
        for (int c = 0; c < cells.count(); ++c) {
            double z0, z1, p0, p1;
            cells.bounds(c, z0, z1, p0, p1);
            double exact = (std::pow(z1, n + 1) - std::pow(z0, n + 1)) * (p1 - p0) / (2 * M_PI);
            // Accurate to far better than the noise of a million samples (sqrt(mass / 1e6)).
            CHECK(std::fabs(mass[static_cast<size_t>(c)] - exact) <= 0.06 * std::sqrt(std::max(exact, 1e-6) / 1e6));
        }
    }
}

TEST_CASE("a cell whose samples the adaptive rule cannot explain is integrated finely, an empty one is left alone",
          "[checks][stats]") {
    // A density that lives in a thin band of phi inside one cell (like the edge of the
    // directions a refraction can reach), missed by every node of the first passes.
    DirectionCells cells;
    cells.fullSphere = true;
    int const target = 37;
    double z0, z1, phi0, phi1;
    cells.bounds(target, z0, z1, phi0, phi1);
    double const band0 = phi0 + 0.375 * (phi1 - phi0), band1 = phi0 + 0.625 * (phi1 - phi0);  // on grid lines
    double const density = 50.0;
    BatchPdf pdf = [&](std::vector<Vec3> const& w) {
        std::vector<double> p;
        for (auto const& d : w) {
            double phi = std::atan2(d.y, d.x);
            if (phi < 0) phi += 2 * M_PI;
            p.push_back(d.z > z0 && d.z < z1 && phi > band0 && phi < band1 ? density : 0.0);
        }
        return p;
    };
    std::vector<double> mass(static_cast<size_t>(cells.count()), 0.0), observed(mass.size(), 0.0);
    observed[target] = 3.0;
    integrateEmptyCellsFinely(cells, observed, pdf, mass);
    double const exact = density * (z1 - z0) * (band1 - band0);
    CHECK(mass[target] == Approx(exact).epsilon(1e-3));
    observed[target] = 0.0;
    std::vector<double> untouched(mass.size(), 0.0);
    integrateEmptyCellsFinely(cells, observed, pdf, untouched);
    CHECK(untouched[target] == 0.0);  // no sample fell there: nothing to explain
}

TEST_CASE("a sliver thinner than the fine grid is judged by the pdf at the draw that fell in it", "[checks][stats]") {
    // A horizon tilted across a cell can leave the pdf non-zero in a corner
    // that no node of the 64 x 64 grid reaches: a draw there is legitimate
    // exactly when the pdf at the draw itself is non-zero.
    DirectionCells cells;
    int const target = 100;
    double z0, z1, phi0, phi1;
    cells.bounds(target, z0, z1, phi0, phi1);
    double const edge = phi0 + 1e-4 * (phi1 - phi0);  // far thinner than a grid column
    BatchPdf pdf = [&](std::vector<Vec3> const& w) {
        std::vector<double> p;
        for (auto const& d : w) {
            double phi = std::atan2(d.y, d.x);
            if (phi < 0) phi += 2 * M_PI;
            p.push_back(phi < edge && d.z > z0 && d.z < z1 ? 2.0 : 0.0);
        }
        return p;
    };
    std::vector<double> observed(static_cast<size_t>(cells.count()), 0.0);
    observed[target] = 1.0;
    std::vector<Vec3> examples(observed.size(), Vec3(0.0f));
    double const zMid = 0.5 * (z0 + z1);
    auto directionAtPhi = [&](double phi) { return directionAt(zMid, phi); };

    std::vector<double> mass(observed.size(), 0.0);
    integrateEmptyCellsFinely(cells, observed, pdf, mass);
    CHECK(mass[target] == 0.0);  // without the draw the grid sees nothing

    examples[static_cast<size_t>(target)] = directionAtPhi(phi0 + 0.5e-4 * (phi1 - phi0));  // inside the sliver
    integrateEmptyCellsFinely(cells, observed, pdf, mass, 64, &examples);
    CHECK(mass[target] > 0.0);
    CHECK(mass[target] < 1e-5);  // a grid node's share: too little to weigh in the test

    examples[static_cast<size_t>(target)] = directionAtPhi(0.5 * (phi0 + phi1));  // where the pdf is zero
    std::vector<double> impossible(observed.size(), 0.0);
    integrateEmptyCellsFinely(cells, observed, pdf, impossible, 64, &examples);
    CHECK(impossible[target] == 0.0);
}

TEST_CASE("a transmitting exercise reads its refractive index from its own parameters", "[checks][exercise]") {
    Exercise e;
    e.transmits = true;
    e.iorParam = "ior";
    CHECK(e.ior("\"float ior\" [1.33] \"float roughness\" [0.1]") == Approx(1.33));
    CHECK(e.ior("\"float ior\" [1.5] \"float ior\" [2.4]") == Approx(2.4));  // the last one wins, as in RIB
    CHECK_THROWS_WITH(e.ior("\"float roughness\" [0]"), Catch::Contains("do not set \"float ior\""));
    e.transmits = false;
    CHECK(e.ior("") == 1.0);
}

TEST_CASE("chi-squared: uniform draws pass, a 3% tilt of a million fails, rare cells do not decide", "[checks][stats]") {
    DirectionCells cells;
    std::mt19937 random(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    auto draw = [&](double tilt) {
        DirectionCounts counts(cells);
        for (int i = 0; i < 1000000; ++i) {
            // z from the density proportional to 1 + tilt (2z - 1) on [0, 1], phi uniform.
            float z;
            do z = u(random);
            while (u(random) * (1 + std::fabs(tilt)) > 1 + tilt * (2 * z - 1));
            counts.add(true, directionAt(z, 2 * M_PI * u(random)), 1.0f);
        }
        return counts;
    };
    auto uniformMass = integrateCells(cells, [](std::vector<Vec3> const& w) {
        return std::vector<double>(w.size(), 1.0 / (2 * M_PI));
    }, toleranceForSamples(1e6));
    CHECK(testDirections(draw(0.0), uniformMass).chi.pValue > 1e-4);
    CHECK(testDirections(draw(0.03), uniformMass).chi.pValue < 1e-6);
    // One draw in a cell that expects 1e-3 must not fail a test on its own.
    std::vector<double> observed(100, 50.0), expected(100, 50.0);
    observed.push_back(1.0);
    expected.push_back(1e-3);
    CHECK(chiSquaredTest(observed, expected).pValue > 0.01);
}

TEST_CASE("render comparison: noise passes, a thin bias fails on the mean, a claimed huge variance gains nothing",
          "[checks][render]") {
    int const w = 64, h = 64;
    std::mt19937 random(3);
    std::normal_distribution<float> noise(0.0f, 1.0f);
    auto render = [&](float level, float sigma) {
        RenderImage image;
        image.width = w;
        image.height = h;
        for (int i = 0; i < 3 * w * h; ++i) {
            image.rgb.push_back(level + sigma * noise(random));
            image.variance.push_back(sigma * sigma);
        }
        return image;
    };
    RenderImage reference = render(0.5f, 0.02f);
    CHECK(compareRenders(render(0.5f, 0.02f), reference).passed());
    RenderVerdict biased = compareRenders(render(0.51f, 0.02f), reference);  // 2%: inside every pixel's noise
    CHECK(biased.pixelsAgree);
    CHECK_FALSE(biased.meansAgree);
    CHECK(biased.message.find("brighter") != std::string::npos);
    RenderImage wrong = render(0.8f, 0.02f);
    for (float& v : wrong.variance) v = 1e6f;  // "my noise is enormous, so anything agrees"
    CHECK_FALSE(compareRenders(wrong, reference).passed());
}

TEST_CASE("noise comparison: too noisy fails, too smooth fails only where the scene fixes the estimator",
          "[checks][render]") {
    auto withVariance = [](float variance) {
        RenderImage image;
        image.width = image.height = 32;
        image.rgb.assign(3 * 32 * 32, 0.5f);
        image.variance.assign(3 * 32 * 32, variance);
        return image;
    };
    RenderImage const reference = withVariance(1e-4f);
    CHECK(compareNoise(withVariance(1.2e-4f), reference, 1.5).passed);
    CHECK_FALSE(compareNoise(withVariance(2e-4f), reference, 1.5).passed);
    // Smoother is better where the estimator is the student's choice...
    CHECK(compareNoise(withVariance(1e-5f), reference, 1.5).passed);
    // ...but where the scene's parameters fix it, a smoother image took samples it was not asked for.
    NoiseVerdict smooth = compareNoise(withVariance(1e-5f), reference, 1.5, true);
    CHECK_FALSE(smooth.passed);
    CHECK(smooth.message.find("sample counts") != std::string::npos);
    CHECK(compareNoise(withVariance(0.8e-4f), reference, 1.5, true).passed);
    CHECK_FALSE(compareNoise(withVariance(2e-4f), reference, 1.5, true).passed);
}

TEST_CASE("render comparison: a pixel whose few samples all missed a rare light is noisy, not exact", "[checks][render]") {
    // A penumbra at 8 spp: each sample sees the light with probability 1/16 and then adds 1/8.
    // Many pixels get no hit at all and report a variance of exactly 0; their neighbours show the noise.
    int const w = 64, h = 64, spp = 8;
    auto render = [&](unsigned seed, float hitProbability) {
        std::mt19937 random(seed);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        RenderImage image;
        image.width = w;
        image.height = h;
        for (int p = 0; p < w * h; ++p) {
            int hits = 0;
            for (int s = 0; s < spp; ++s) hits += u(random) < hitProbability;
            float mean = static_cast<float>(hits) / spp, q = static_cast<float>(hits) / spp;
            float varianceOfMean = q * (1 - q) / (spp - 1);  // of samples that are 0 or 1, scaled to the mean
            for (int c = 0; c < 3; ++c) {
                image.rgb.push_back(mean);
                image.variance.push_back(varianceOfMean);
            }
        }
        return image;
    };
    RenderImage reference = render(1, 1.0f / 16);
    int reportedExact = 0;
    for (size_t i = 0; i < reference.variance.size(); i += 3) reportedExact += reference.variance[i] == 0.0f;
    REQUIRE(reportedExact > 1000);  // the situation this test is about
    for (unsigned seed : {2u, 3u, 4u}) CHECK(compareRenders(render(seed, 1.0f / 16), reference).passed());
    // Where the whole neighbourhood is noise-free, any difference still fails.
    RenderImage dark = render(5, 0.0f), lit = render(6, 0.0f);
    for (int y = 24; y < 40; ++y)
        for (int x = 24; x < 40; ++x) lit.rgb[3 * (static_cast<size_t>(y) * w + x)] = 0.01f;
    CHECK(compareRenders(dark, dark).passed());
    CHECK_FALSE(compareRenders(lit, dark).pixelsAgree);
}
