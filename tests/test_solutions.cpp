// The reference plugins, driven through the probe harness: values against
// hand-computed numbers, sampling against the declared pdf (chi-squared),
// generate/evaluate consistency, pdf normalisation, reciprocity, energy, and
// the hard cases of models.md (one table: adding a case is one line).
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iterator>

#include "checks/Check.h"
#include "checks/CheckSupport.h"
#include "measure/ProbeMeasurer.h"
#include "probe/BxdfProbe.h"

using namespace bxdflab;
using checks::direction;
using checks::viewFrom;

namespace {

std::unique_ptr<BxdfProbe> probe(std::string const& plugin, std::string const& params) {
    static Diagnostics diagnostics(false);
    return std::make_unique<BxdfProbe>(plugin, params, std::vector<std::string>{}, diagnostics);
}

RtColorRGB weightAt(BxdfProbe& p, ProbePoint const& point, Vec3 const& L) { return p.evaluate({point}, {L})[0].W; }

// A parameter set the tests below use beyond the manifests' own. What each
// model is (reciprocal, energy-conserving, ...) is the manifest's to say.
struct Model {
    const char* plugin;
    const char* params;
    bool mayReject;  ///< GenerateSample can return invalid samples (pdf integrates to < 1)
};

// Every solution, in the configurations the tests below exercise.
const std::vector<Model> kModels = {
    {"diffuse", "\"color diffuseColor\" [1 1 1]", false},
    {"buggydiffuse", "\"color diffuseColor\" [1 1 1]", false},
    {"diffuse", "\"color diffuseColor\" [1 1 1] \"int samplingMode\" [1]", false},
    {"specular", "\"float gloss\" [30]", false},
    {"specular", "\"float gloss\" [30] \"int samplingMode\" [1]", true},
    {"plastic", "\"color diffuseColor\" [0.6 0.6 0.6] \"color specularColor\" [0.4 0.4 0.4] \"float gloss\" [40]", true},
    {"ward", "\"float uRoughness\" [0.3] \"float vRoughness\" [0.1]", true},
    {"ward", "\"float uRoughness\" [0.3] \"float vRoughness\" [0.1] \"int samplingMode\" [0]", false},
    {"ward", "\"float uRoughness\" [0.2] \"float vRoughness\" [0.2] \"color diffuseColor\" [0.4 0.4 0.4]", true},
    {"ggx", "\"float uRoughness\" [0.3] \"float vRoughness\" [0.1]", true},
    {"ggx", "\"float uRoughness\" [0.3] \"float vRoughness\" [0.1] \"int samplingMode\" [1]", true},
    {"ggx", "\"float uRoughness\" [0.3] \"float vRoughness\" [0.1] \"int samplingMode\" [0]", false},
    {"ggx", "\"float uRoughness\" [0.02] \"float vRoughness\" [0.02]", true},
    {"finishedwood", "", false},
    {"finishedwood", "\"vector fiberAxis\" [0.6 0.64 0.48] \"float beta\" [0.3] \"float eta\" [1.3]", false},
};

/// Runs one of the autograder's checks with the plugin as both the student's
/// plugin and the oracle.
void requireCheckPasses(Exercise const& e, std::string const& check, std::string const& pluginDir) {
    static Diagnostics quiet(false);
    ProbeMeasurer plugin(e.plugin, {pluginDir}, quiet);
    CheckContext context{e, plugin, plugin, 1u};
#ifdef BXDFLAB_SANITIZE
    // Under the sanitizers the same code runs on an eighth of the draws: a correct
    // plugin still passes with the same probability, the test only loses power.
    context.chiSquaredSamples /= 8;
#endif
    CheckOutcome outcome = runCheck(check, context);
    CAPTURE(outcome.summary, outcome.details);
    CHECK(outcome.passed());
}

std::string readWholeFile(std::string const& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string describe(Model const& m) { return std::string(m.plugin) + " " + m.params; }

/// Sum of FPdf sin(theta) dtheta dphi over the upper hemisphere (midpoint rule).
double integratePdf(BxdfProbe& p, ProbePoint const& point, int thetaSteps, int phiSteps) {
    std::vector<ProbePoint> points(static_cast<size_t>(thetaSteps * phiSteps), point);
    std::vector<Vec3> L;
    std::vector<float> solidAngle;
    float dTheta = 0.5f * kPi / thetaSteps, dPhi = 2.0f * kPi / phiSteps;
    for (int i = 0; i < thetaSteps; ++i)
        for (int j = 0; j < phiSteps; ++j) {
            float theta = (i + 0.5f) * dTheta, phi = (j + 0.5f) * dPhi;
            L.emplace_back(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
            solidAngle.push_back(std::sin(theta) * dTheta * dPhi);
        }
    auto results = p.evaluate(points, L);
    double total = 0.0;
    for (size_t k = 0; k < results.size(); ++k) total += static_cast<double>(results[k].FPdf) * solidAngle[k];
    return total;
}

}  // namespace

TEST_CASE("solutions: values at fixed directions match hand-computed numbers", "[solutions]") {
    const float pi = F_PI;
    SECTION("diffuse: W = rho cos / pi, FPdf = cos / pi, RPdf = cos_V / pi") {
        auto p = probe("diffuse", "\"color diffuseColor\" [0.8 0.4 0.2]");
        auto r = p->evaluate({viewFrom(0)}, {direction(60, 10)})[0];
        CHECK(r.W.r == Approx(0.8 * 0.5 / pi).epsilon(1e-5));
        CHECK(r.W.b == Approx(0.2 * 0.5 / pi).epsilon(1e-5));
        CHECK(r.FPdf == Approx(0.5 / pi).epsilon(1e-5));
        CHECK(r.RPdf == Approx(1.0 / pi).epsilon(1e-5));
        CHECK(p->evaluate({viewFrom(0)}, {direction(100, 0)})[0].W.r == 0.0f);  // below the surface
    }
    SECTION("specular: normalised Phong around the mirror direction") {
        auto p = probe("specular", "\"color specularColor\" [1 1 1] \"float gloss\" [10]");
        // V at 30 degrees (phi 0): the mirror direction is at 30 degrees, phi 180.
        CHECK(weightAt(*p, viewFrom(30), direction(30, 180)).g == Approx(12.0 / (2 * pi) * std::cos(pi / 6)).epsilon(1e-4));
        // 10 degrees off the mirror direction: cos(10 deg)^10.
        double expected = 12.0 / (2 * pi) * std::pow(std::cos(pi / 18), 10.0) * std::cos(40 * pi / 180);
        CHECK(weightAt(*p, viewFrom(30), direction(40, 180)).g == Approx(expected).epsilon(1e-4));
        auto raw = probe("specular", "\"float gloss\" [10] \"int normalize\" [0]");
        CHECK(weightAt(*raw, viewFrom(30), direction(30, 180)).g == Approx(std::cos(pi / 6)).epsilon(1e-4));
    }
    SECTION("plastic: the sum of both lobes, and the albedo-weighted mixture pdf") {
        auto p = probe("plastic", "\"color diffuseColor\" [0.5 0.5 0.5] \"color specularColor\" [0.25 0.25 0.25] "
                                  "\"float gloss\" [10]");
        auto r = p->evaluate({viewFrom(30)}, {direction(40, 180)})[0];
        double cosL = std::cos(40 * pi / 180), lobe = std::pow(std::cos(pi / 18), 10.0);
        CHECK(r.W.r == Approx(0.5 * cosL / pi + 0.25 * 12.0 / (2 * pi) * lobe * cosL).epsilon(1e-4));
        double pSpecular = 0.25 / 0.75;
        CHECK(r.FPdf == Approx((1 - pSpecular) * cosL / pi + pSpecular * 11.0 / (2 * pi) * lobe).epsilon(1e-4));
    }
    SECTION("ward: peak value and an anisotropic fall-off") {
        auto p = probe("ward", "\"color specularColor\" [1 1 1] \"float uRoughness\" [0.2] \"float vRoughness\" [0.4]");
        CHECK(weightAt(*p, viewFrom(0), Vec3(0, 0, 1)).r == Approx(1.0 / (4 * pi * 0.2 * 0.4)).epsilon(1e-4));
        // V = N, L tilted by 20 degrees toward u (dPdu = +x): H = L + V.
        double t = 20 * pi / 180;
        double alongU = std::exp(-std::pow(std::sin(t) / 0.2, 2) / std::pow(1 + std::cos(t), 2)) * std::sqrt(std::cos(t)) /
                        (4 * pi * 0.08);
        double alongV = std::exp(-std::pow(std::sin(t) / 0.4, 2) / std::pow(1 + std::cos(t), 2)) * std::sqrt(std::cos(t)) /
                        (4 * pi * 0.08);
        CHECK(weightAt(*p, viewFrom(0), direction(20, 0)).r == Approx(alongU).epsilon(1e-4));
        CHECK(weightAt(*p, viewFrom(0), direction(20, 90)).r == Approx(alongV).epsilon(1e-4));
    }
    SECTION("ggx: peak value, an anisotropic fall-off with Smith masking, Schlick's Fresnel and both pdfs") {
        auto p = probe("ggx", "\"color specularColor\" [1 1 1] \"float uRoughness\" [0.2] \"float vRoughness\" [0.4]");
        // V = L = N: H = N, D = 1 / (pi au av), no masking, F = 1, W = D / 4.
        CHECK(weightAt(*p, viewFrom(0), Vec3(0, 0, 1)).r == Approx(1.0 / (4 * pi * 0.2 * 0.4)).epsilon(1e-4));
        // V = N, L tilted by 20 degrees toward u: H is tilted by 10 degrees the same way.
        double h = 10 * pi / 180, l = 20 * pi / 180;
        auto ggxD = [&](double alpha) {  // with H in the plane of N and one tangent
            double s = std::pow(std::sin(h) / alpha, 2) + std::pow(std::cos(h), 2);
            return 1.0 / (pi * 0.2 * 0.4 * s * s);
        };
        auto lambda = [](double alpha, double theta) {
            return (std::sqrt(1 + std::pow(alpha * std::tan(theta), 2)) - 1) / 2;
        };
        CHECK(weightAt(*p, viewFrom(0), direction(20, 0)).r ==
              Approx(ggxD(0.2) / (1 + lambda(0.2, l)) / 4).epsilon(1e-4));
        CHECK(weightAt(*p, viewFrom(0), direction(20, 90)).r ==
              Approx(ggxD(0.4) / (1 + lambda(0.4, l)) / 4).epsilon(1e-4));

        // V and L mirrored at 60 degrees: H = N, V.H = 1/2, F = F0 + (1 - F0) / 32.
        std::string const plastic = "\"color specularColor\" [0.04 0.04 0.04] \"float uRoughness\" [0.3] "
                                    "\"float vRoughness\" [0.3]";
        double t = 60 * pi / 180, D = 1 / (pi * 0.09), F = 0.04 + 0.96 / 32, G1 = 1 / (1 + lambda(0.3, t));
        double G2 = 1 / (1 + 2 * lambda(0.3, t));
        for (int mode : {1, 2}) {
            auto q = probe("ggx", plastic + " \"int samplingMode\" [" + std::to_string(mode) + "]");
            auto r = q->evaluate({viewFrom(60)}, {direction(60, 180)})[0];
            CAPTURE(mode);
            CHECK(r.W.g == Approx(F * D * G2 / (4 * std::cos(t))).epsilon(1e-4));
            // distribution of normals: D (N.H) / (4 V.H); visible normals: G1(V) D / (4 cos theta_V)
            CHECK(r.FPdf == Approx(mode == 1 ? D / (4 * 0.5) : G1 * D / (4 * std::cos(t))).epsilon(1e-4));
        }
    }
    SECTION("finishedwood with eta = 1: no coat, diffuse and fiber lobes through a clear boundary") {
        auto p = probe("finishedwood", "\"float eta\" [1] \"color diffuseColor\" [0.5 0.5 0.5] "
                                       "\"color fiberColor\" [1 1 1] \"float beta\" [0.1] \"vector fiberAxis\" [1 0 0]");
        // L in the plane across the fiber (yz): psi_i = psi_r = 0, g(0) = 1 / (beta sqrt(2 pi)).
        double cosL = std::cos(pi / 6);
        double expected = 0.5 / pi * cosL + 1.0 / (0.1 * std::sqrt(2 * pi)) * cosL;
        CHECK(weightAt(*p, viewFrom(0), direction(30, 90)).r == Approx(expected).epsilon(1e-4));
        // Along the fiber the highlight is gone: psi_h = 30 degrees is 5 beta away.
        CHECK(weightAt(*p, viewFrom(0), direction(30, 0)).r == Approx(0.5 / pi * cosL).epsilon(1e-3));
        // Seen at 40 degrees along the fiber, the highlight is a cone: light must
        // travel in along the fiber as far as it travels out toward the viewer, so
        // L lies opposite V (psi_h = 0), not beside it (psi_h = 80 degrees). A lobe
        // built on the refracted view direction as it comes (it points into the
        // wood) swaps the two. At the peak psi_d = 80 degrees: f = g(0) / cos^2(40).
        double cos40 = std::cos(40 * pi / 180);
        CHECK(weightAt(*p, viewFrom(40), direction(40, 180)).r ==
              Approx(0.5 / pi * cos40 + 1.0 / (0.1 * std::sqrt(2 * pi)) / cos40).epsilon(1e-4));
        CHECK(weightAt(*p, viewFrom(40), direction(40, 0)).r == Approx(0.5 / pi * cos40).epsilon(1e-3));
    }
    SECTION("emissive: no lobes, only emission") {
        auto p = probe("emissive", "\"color emissiveColor\" [3 2 1]");
        CHECK_FALSE(p->lobes().HasAny());
        CHECK(p->emission({viewFrom(0)})[0].g == 2.0f);
        CHECK_FALSE(p->generate({viewFrom(0)}, stratifiedSamples(1, 0))[0].valid);
    }
}

TEST_CASE("solutions: every reference solution passes every check of its exercise", "[solutions][checks]") {
    // The autograder's own checks (labkit/checks), with the solution as both the
    // plugin and the oracle: its sampling, consistency, reciprocity, energy and
    // hard cases hold for every sampling mode and parameter set of the manifest.
    static std::vector<Exercise> const exercises = loadExercises(BXDFLAB_SOURCE_DIR);
    auto const& e = GENERATE(from_range(exercises));
    auto const check = GENERATE(from_range(checkNames()));
    if (Exercise::isRenderCheck(check) || !e.gradedWith(check)) return;
    CAPTURE(e.plugin, check);
    requireCheckPasses(e, check, SOLUTION_PLUGIN_DIR);
}

TEST_CASE("solutions: starter files the manifest calls identical to the solution's are", "[solutions][starter]") {
    // What a student is given unchanged (factories, headers) must not drift from
    // the solution it is graded against.
    for (Exercise const& e : loadExercises(BXDFLAB_SOURCE_DIR)) {
        for (std::string const& file : e.identicalToSolution) {
            CAPTURE(e.plugin, file);
            std::string starter = readWholeFile(std::string(BXDFLAB_SOURCE_DIR) + "/" + e.folder + "/" + file);
            std::string solution = readWholeFile(std::string(BXDFLAB_SOURCE_DIR) + "/" + e.solutionFolder + "/" + file);
            REQUIRE_FALSE(starter.empty());
            CHECK(starter == solution);
        }
    }
}

TEST_CASE("stock models (PxrDisney) pass every check of their model manifest", "[stock][checks]") {
    // The same checks as the solutions', on the stock plugins that have a model.json.
    static std::vector<Exercise> const models = {
        loadExercise(BXDFLAB_SOURCE_DIR, std::string(BXDFLAB_SOURCE_DIR) + "/renderer/plugins/stock/disney/model.json")};
    auto const& e = GENERATE(from_range(models));
    auto const check = GENERATE(from_range(checkNames()));
    if (!e.gradedWith(check)) return;
    CAPTURE(e.plugin, check);
    requireCheckPasses(e, check, STOCK_PLUGIN_DIR);
}

TEST_CASE("PxrDisney's subsurfaceColor colours its flattened diffuse term and is black by default", "[stock]") {
    // RenderMan's parameter mixes its colour into the diffuse response by subsurface:
    // f_diffuse = mix(baseColor F_d, subsurfaceColor F_ss, subsurface) / pi. The
    // specular term is the same in every case, so differences isolate the diffuse one.
    std::string const grey = "\"color baseColor\" [0.8 0.8 0.8] \"float roughness\" [0.5] ";
    ProbePoint const point = viewFrom(20.0f, 0.0f);
    Vec3 const L = direction(40.0f, 120.0f);
    auto weight = [&](std::string const& extra) { return weightAt(*probe("PxrDisney", grey + extra), point, L); };
    RtColorRGB const burley = weight("");
    RtColorRGB const specularOnly = weight("\"float subsurface\" [1]");  // black subsurfaceColor: no diffuse
    RtColorRGB const red = weight("\"float subsurface\" [1] \"color subsurfaceColor\" [1 0 0]");
    RtColorRGB const half = weight("\"float subsurface\" [0.5] \"color subsurfaceColor\" [1 0 0]");
    RtColorRGB const burleyDiffuse = burley - specularOnly, redDiffuse = red - specularOnly;
    CHECK(burleyDiffuse.g > 0.01f);
    CHECK(redDiffuse.r > 0.01f);
    CHECK(redDiffuse.g == Approx(0.0f).margin(1e-6));
    CHECK(half.g == Approx(specularOnly.g + 0.5f * burleyDiffuse.g).epsilon(1e-4));
    CHECK(half.r == Approx(specularOnly.r + 0.5f * (burleyDiffuse.r + redDiffuse.r)).epsilon(1e-4));
}

TEST_CASE("solutions: FPdf integrates to 1 over the hemisphere, or to the valid fraction", "[solutions][pdf]") {
    auto model = GENERATE(from_range(kModels));
    auto viewTheta = GENERATE(0.0f, 60.0f);
    CAPTURE(describe(model), viewTheta);
    auto p = probe(model.plugin, model.params);
    ProbePoint point = viewFrom(viewTheta, 25.0f);
    double integral = integratePdf(*p, point, 512, 1024);
    CHECK(integral <= 1.002);
    if (!model.mayReject) CHECK(integral == Approx(1.0).epsilon(0.003));
    // Rejected samples carry exactly the missing probability.
    std::vector<ProbePoint> points(20000, point);
    int valid = 0;
    for (auto const& g : p->generate(points, stratifiedSamples(points.size(), 0))) valid += g.valid;
    CHECK(valid / 20000.0 == Approx(integral).margin(0.01));
}

TEST_CASE("chapter 9: sampling visible normals bounds every sample's weight by 1, sampling D does not", "[solutions][ch09]") {
    // With F0 = 1 the weight a visible-normal sample carries is W / FPdf = G2(V, L) / G1(V) <= 1 at every
    // view and roughness, grazing included; sampling D(m) cos(theta_m) lets it grow at grazing views.
    auto const alpha = GENERATE(0.01, 0.3, 1.0);
    auto const viewTheta = GENERATE(0.0, 60.0, 85.0, 89.5);
    CAPTURE(alpha, viewTheta);
    std::string const roughness = "\"float uRoughness\" [" + std::to_string(alpha) + "] \"float vRoughness\" [" +
                                  std::to_string(alpha) + "]";
    auto largestWeight = [&](int mode) {
        auto p = probe("ggx", roughness + " \"int samplingMode\" [" + std::to_string(mode) + "]");
        std::vector<ProbePoint> points(4096, viewFrom(viewTheta, 30.0));
        double largest = 0.0;
        for (auto const& g : p->generate(points, stratifiedSamples(points.size(), 3)))
            if (g.valid) largest = std::max(largest, static_cast<double>(g.W.g / g.FPdf));
        return largest;
    };
    double visible = largestWeight(2);
    CHECK(visible <= 1.0 + 1e-4);
    CHECK(visible > 0.0);
    if (viewTheta >= 85.0 && alpha >= 0.3) CHECK(largestWeight(1) > 1.5);
}

TEST_CASE("chapter 10: glass by hand, and a lossless smooth boundary", "[solutions][ch10]") {
    SECTION("smooth, normal incidence: F = ((1.5 - 1) / (1.5 + 1))^2 = 0.04; radiance / eta^2 crosses unchanged") {
        auto p = probe("glass", "\"float ior\" [1.5] \"float roughness\" [0]");
        for (double theta : {0.0, 180.0}) {
            CAPTURE(theta);
            double const etaV = theta > 90 ? 1.5 : 1.0, etaL = theta > 90 ? 1.0 : 1.5;
            std::vector<ProbePoint> points(4000, viewFrom(theta));
            int reflected = 0, refracted = 0;
            for (auto const& g : p->generate(points, stratifiedSamples(points.size(), 7))) {
                REQUIRE(g.valid);
                REQUIRE(g.discrete);
                bool reflects = (g.L.z > 0) == (theta < 90);
                CHECK(g.FPdf == Approx(reflects ? 0.04 : 0.96).epsilon(1e-4));
                CHECK(g.W.g / g.FPdf == Approx(reflects ? 1.0 : (etaV * etaV) / (etaL * etaL)).epsilon(1e-4));
                (reflects ? reflected : refracted) += 1;
            }
            CHECK(reflected / 4000.0 == Approx(0.04).margin(0.005));
            CHECK(refracted + reflected == 4000);
        }
    }
    SECTION("rough, straight through at normal incidence: H = N, (eta_V V.H + eta_L L.H)^2 = 0.25") {
        double const alpha = 0.3, D = 1.0 / (kPi * alpha * alpha), F = 0.04;
        auto p = probe("glass", "\"float ior\" [1.5] \"float roughness\" [0.3]");
        auto r = p->evaluate({viewFrom(0)}, {Vec3(0, 0, -1)})[0];
        // W = |V.H| |L.H| eta_V^2 (1 - F) D G2 / (cos(theta_V) 0.25), G2 = 1 along the normal
        CHECK(r.W.g == Approx((1 - F) * D / 0.25).epsilon(1e-4));
        // FPdf = (1 - F) G1(V) D(H) (V.H / cos(theta_V)) eta_L^2 |L.H| / 0.25
        CHECK(r.FPdf == Approx((1 - F) * D * 2.25 / 0.25).epsilon(1e-4));
        // From inside: the mirror image of the same pair, with the indices swapped.
        auto back = p->evaluate({viewFrom(180)}, {Vec3(0, 0, 1)})[0];
        CHECK(back.W.g == Approx((1 - F) * D * 2.25 / 0.25).epsilon(1e-4));
        CHECK(back.FPdf == Approx((1 - F) * D * 1.0 / 0.25).epsilon(1e-4));
    }
    SECTION("rough: the scattered radiance / eta^2 is at most 1, and nearly 1 for a nearly smooth boundary") {
        // A single-scattering microfacet model loses the light that would scatter
        // again among the microfacets (a refraction through a tilted microfacet that
        // leaves on the wrong side): more for rough glass, more from inside.
        auto const alpha = GENERATE(0.02, 0.3);
        auto const viewTheta = GENERATE(0.0, 60.0, 85.0, 150.0, 120.0);
        CAPTURE(alpha, viewTheta);
        auto p = probe("glass", "\"float ior\" [1.5] \"float roughness\" [" + std::to_string(alpha) + "]");
        std::vector<ProbePoint> points(100000, viewFrom(viewTheta, 10.0));
        double etaV = viewTheta > 90 ? 1.5 : 1.0, sum = 0.0;
        for (auto const& g : p->generate(points, stratifiedSamples(points.size(), 11))) {
            if (!g.valid) continue;
            double etaL = g.L.z < 0 ? 1.5 : 1.0;
            sum += g.W.g / g.FPdf * (etaL * etaL) / (etaV * etaV);
        }
        double albedo = sum / static_cast<double>(points.size());
        CHECK(albedo <= 1.0);
        CHECK(albedo >= (alpha < 0.1 ? 0.97 : 0.75));
    }
}

TEST_CASE("chapter 7: the buggydiffuse starter's GenerateSample and EvaluateSample disagree, the solution's agree",
          "[solutions][ch07]") {
    Diagnostics diagnostics(false);
    BxdfProbe buggy("buggydiffuse", "", {std::string(STARTER_PLUGIN_DIR)}, diagnostics);
    BxdfProbe fixed("buggydiffuse", "", {}, diagnostics);
    std::vector<ProbePoint> points(256, viewFrom(50.0f));
    auto mismatches = [&](BxdfProbe& p) {
        auto generated = p.generate(points, stratifiedSamples(points.size(), 0));
        std::vector<Vec3> L;
        for (auto const& g : generated) L.push_back(g.L);
        auto evaluated = p.evaluate(points, L);
        int count = 0;
        for (size_t i = 0; i < generated.size(); ++i)
            if (generated[i].valid && (std::fabs(evaluated[i].FPdf - generated[i].FPdf) > 1e-4f * generated[i].FPdf ||
                                       std::fabs(evaluated[i].W.g - generated[i].W.g) > 1e-4f * generated[i].W.g))
                ++count;
        return count;
    };
    CHECK(mismatches(buggy) > 200);
    CHECK(mismatches(fixed) == 0);
}

TEST_CASE("varying parameters follow a point moved one place later in its batch", "[solutions][checks]") {
    // The marks that ask for parameters varying per point, or for two threads
    // at once, survive the trip (they cross to the sandboxed measurer as text)
    // and nothing else is taken for them.
    std::string const params = "\"float gloss\" [40]";
    for (int firstShare : {-1, 0, 7}) {
        std::string marked = varyingParams(params, firstShare);
        std::optional<VaryingMark> const mark = takeVaryingMark(marked);
        REQUIRE(mark.has_value());
        CHECK(mark->firstShare == firstShare);
        CHECK_FALSE(mark->coloursOnly);
        CHECK(marked == params);
    }
    std::string colours = varyingColours(params);
    std::optional<VaryingMark> const coloursMark = takeVaryingMark(colours);
    REQUIRE(coloursMark.has_value());
    CHECK(coloursMark->coloursOnly);
    CHECK(colours == params);
    std::string other = "# each value varies from point to point, starting at share x\n" + params;
    CHECK_FALSE(takeVaryingMark(other).has_value());
    CHECK(other.size() > params.size());
    std::string together = askedTogether(params, 200);
    CHECK_FALSE(takeVaryingMark(together).has_value());
    REQUIRE(takeTogetherMark(together) == 200);
    CHECK(together == params);

    // Point i takes share i + firstShare: moved one place later with
    // firstShare - 1, a point keeps its gloss, and the plastic solution its
    // answer; moved without it, the point's gloss (and answer) changes.
    static Diagnostics quiet(false);
    ProbeMeasurer plastic("plastic", {SOLUTION_PLUGIN_DIR}, quiet);
    std::vector<ProbePoint> points = {viewFrom(10, 0), viewFrom(30, 90), viewFrom(50, 200)};
    std::vector<Vec3> L = {direction(12, 180), direction(30, 270), direction(50, 20)};  // near each mirror direction
    std::vector<ProbePoint> moved = {viewFrom(70, 45), points[0], points[1]};
    std::vector<Vec3> movedL = {direction(70, 225), L[0], L[1]};
    std::string const full = "\"color specularColor\" [1 1 1] \"color diffuseColor\" [0 0 0] " + params;
    auto before = plastic.evaluate(varyingParams(full, 0), points, L);
    auto kept = plastic.evaluate(varyingParams(full, -1), moved, movedL);
    auto shifted = plastic.evaluate(varyingParams(full, 0), moved, movedL);
    for (size_t j = 0; j < 2; ++j) {
        CAPTURE(j);
        CHECK(kept[j + 1].W[0] == before[j].W[0]);
        CHECK(std::fabs(shifted[j + 1].W[0] - before[j].W[0]) > 1e-3f * before[j].W[0]);
    }
}
