// rixcheck: the autograder's plugin checks as Catch2 test cases.
//
//   RIXCHECK_PLUGIN=diffuse RIXCHECK_PLUGIN_DIR=my/build/plugins rixcheck [tags]
//
// Each test case checks one property of the plugin RIXCHECK_PLUGIN (loaded
// from RIXCHECK_PLUGIN_DIR) and compares it with the reference solution of
// the same name. Students run it (or `ctest` in their build) to check their
// work; rixgrade runs each case in its own process and turns it into points.
// Tags: [loads] [values] [chi2] [consistency] [reciprocity] [energy] [hardcases]
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>

#include "probe/BxdfProbe.h"
#include "probe/SamplingHistogram.h"
#include "shade/PluginSearchPath.h"

using namespace bxdflab;

namespace {

struct PluginFacts {
    const char* params;  ///< parameters used for every check (same for student and solution)
    const char* colorParams;  ///< a second, coloured set the values check also compares
    bool reciprocal;
    bool conservesEnergy;
    bool emitsOnly;
    bool singleLobeSampler;  ///< one 2-D draw maps to the direction (mixtures choose a lobe first)
};

// The parameters each exercise is checked with: white where energy matters.
const std::map<std::string, PluginFacts> kPlugins = {
    {"emissive", {"\"color emissiveColor\" [1 0.5 0.25]", "\"color emissiveColor\" [0.2 2 0.7]", false, false, true, false}},
    {"diffuse", {"\"color diffuseColor\" [1 1 1]", "\"color diffuseColor\" [0.7 0.4 0.1]", true, true, false, true}},
    {"buggydiffuse", {"\"color diffuseColor\" [1 1 1]", "\"color diffuseColor\" [0.7 0.4 0.1]", true, true, false, true}},
    {"specular", {"\"color specularColor\" [1 1 1] \"float gloss\" [30]",
                  "\"color specularColor\" [0.2 0.8 0.6] \"float gloss\" [80]", true, true, false, true}},
    {"plastic", {"\"color diffuseColor\" [0.6 0.6 0.6] \"color specularColor\" [0.4 0.4 0.4] \"float gloss\" [40]",
                 "\"color diffuseColor\" [0.5 0.1 0.1] \"color specularColor\" [0.2 0.3 0.4] \"float gloss\" [10]", true, true, false, false}},
    {"ward", {"\"color specularColor\" [1 1 1] \"float uRoughness\" [0.3] \"float vRoughness\" [0.1]",
              "\"color specularColor\" [0.9 0.5 0.2] \"float uRoughness\" [0.1] \"float vRoughness\" [0.4] \"color diffuseColor\" [0.1 0.2 0.3]", true, false, false, true}},
    {"finishedwood", {"\"vector fiberAxis\" [0.6 0.8 0] \"float beta\" [0.2]",
                      "\"vector fiberAxis\" [1 0 0] \"float beta\" [0.1] \"float eta\" [1.3] \"color diffuseColor\" [0.4 0.2 0.1]", false, false, false, true}},
};

std::string env(const char* name) {
    const char* value = std::getenv(name);
    return value ? value : "";
}

std::string pluginName() {
    std::string name = env("RIXCHECK_PLUGIN");
    if (name.empty()) FAIL("set RIXCHECK_PLUGIN to the plugin to check (e.g. diffuse)");
    if (!kPlugins.count(name)) FAIL("rixcheck has no checks for a plugin named \"" << name << "\"");
    return name;
}

PluginFacts const& facts() { return kPlugins.at(pluginName()); }

Diagnostics& quiet() {
    static Diagnostics diagnostics(false);
    return diagnostics;
}

/// The student's plugin with the given parameters: only the submission's
/// folder is searched, never the solutions.
BxdfProbe& student(std::string const& params) {
    static std::map<std::string, std::unique_ptr<BxdfProbe>> probes;
    auto& probe = probes[params];
    if (!probe) {
        std::string dir = env("RIXCHECK_PLUGIN_DIR");
        if (dir.empty()) FAIL("set RIXCHECK_PLUGIN_DIR to the folder holding your plugin");
        probe = std::make_unique<BxdfProbe>(pluginName(), params, std::vector<std::string>{dir}, quiet(),
                                            /*searchBuiltins=*/false);
    }
    return *probe;
}
BxdfProbe& student() { return student(facts().params); }

/// The reference solution (the oracle).
BxdfProbe& solution(std::string const& params) {
    static std::map<std::string, std::unique_ptr<BxdfProbe>> probes;
    auto& probe = probes[params];
    if (!probe) probe = std::make_unique<BxdfProbe>(pluginName(), params, builtinPluginFolders(), quiet(), false);
    return *probe;
}
BxdfProbe& solution() { return solution(facts().params); }

Vec3 direction(float thetaDegrees, float phiDegrees) {
    float t = glm::radians(thetaDegrees), p = glm::radians(phiDegrees);
    return Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

ProbePoint viewFrom(float thetaDegrees, float phiDegrees = 20.0f) {
    ProbePoint point;
    point.V = direction(thetaDegrees, phiDegrees);
    return point;
}

bool close(float a, float b, float relative) {
    return std::fabs(a - b) <= relative * std::fmax(std::fabs(a), std::fabs(b)) + 1e-6f;
}

/// Fails (with a message a student understands) when the plugin gives back
/// nothing at all: no light, no valid sample, no emission. Then every property
/// would hold trivially, so it would earn points for a skeleton.
void requireAttempted() {
    ProbePoint point = viewFrom(30.0f);
    auto evaluated = student().evaluate({point, point}, {direction(30.0f, 200.0f), direction(10.0f, 90.0f)});
    bool light = !evaluated[0].W.IsBlack() || !evaluated[1].W.IsBlack();
    for (auto const& g : student().generate(std::vector<ProbePoint>(16, point))) light = light || g.valid;
    for (auto const& e : student().emission({point})) light = light || !e.IsBlack();
    if (!light) FAIL("your plugin returns no light and no samples yet: are the TODO bodies still empty?");
}

}  // namespace

TEST_CASE("loads: the plugin loads, declares its parameters and lobes, and builds a Bxdf", "[loads]") {
    BxdfProbe& p = student();
    RixBXLobeTraits lobes = p.lobes();
    if (facts().emitsOnly)
        CHECK_FALSE(lobes.HasAny());
    else
        CHECK(lobes.HasAny());
}

TEST_CASE("values: W and the pdfs match the reference solution at fixed directions", "[values]") {
    // Views from above and, for two-sided surfaces, from below; white and coloured parameters.
    std::vector<ProbePoint> points;
    std::vector<Vec3> L;
    for (float thetaV : {0.0f, 30.0f, 60.0f, 85.0f, 120.0f, 160.0f})
        for (float thetaL : {5.0f, 35.0f, 65.0f, 88.0f, 115.0f, 150.0f})
            for (float phiL : {0.0f, 90.0f, 200.0f}) {
                points.push_back(viewFrom(thetaV));
                L.push_back(direction(thetaL, phiL));
            }
    for (std::string params : {facts().params, facts().colorParams}) {
        INFO("parameters " << params);
        auto mine = student(params).evaluate(points, L), theirs = solution(params).evaluate(points, L);
        auto emitMine = student(params).emission(points), emitTheirs = solution(params).emission(points);
        for (size_t i = 0; i < L.size(); ++i) {
            INFO("view " << points[i].V.x << " " << points[i].V.y << " " << points[i].V.z << ", light " << L[i].x << " "
                         << L[i].y << " " << L[i].z);
            for (int c = 0; c < 3; ++c) {
                INFO("channel " << c);
                REQUIRE(close(mine[i].W[c], theirs[i].W[c], 1e-3f));
                REQUIRE(close(emitMine[i][c], emitTheirs[i][c], 1e-3f));
            }
            REQUIRE(close(mine[i].FPdf, theirs[i].FPdf, 1e-3f));
            REQUIRE(close(mine[i].RPdf, theirs[i].RPdf, 1e-3f));
        }
    }
}

TEST_CASE("chi2: sampled directions follow the declared FPdf", "[chi2]") {
    requireAttempted();
    if (facts().emitsOnly) return;
    const std::vector<float> views = {0.0f, 45.0f, 80.0f};
    double alpha = sidak(0.01, static_cast<int>(views.size()));
    for (float view : views) {
        SamplingHistogram h = sampleHistogram(student(), viewFrom(view), 100000, 12, 24, 10, 11u);
        ChiSquaredResult chi = h.test();
        INFO("viewer at " << view << " degrees: chi-squared " << chi.statistic << " with " << chi.degreesOfFreedom
                          << " degrees of freedom, p = " << chi.pValue);
        REQUIRE(h.validSamples > 0);
        REQUIRE(h.nonFiniteSamples == 0);
        REQUIRE(chi.impossibleSamples == 0);
        REQUIRE(chi.pValue > alpha);
        // The shape matches; the scale must too: FPdf's mass over the hemisphere is
        // the fraction of samples that come back valid (1 when none are rejected).
        double validFraction = static_cast<double>(h.validSamples) / static_cast<double>(h.samples);
        INFO("FPdf integrates to " << h.pdfIntegral << " over the hemisphere, but " << validFraction
                                   << " of the samples are valid");
        REQUIRE(h.pdfIntegral == Approx(validFraction).margin(0.02));
    }
}

TEST_CASE("jacobian: FPdf is the density the sampling mapping really produces", "[jacobian]") {
    // Lajolla's check: at fixed random numbers xi, finite differences of the
    // mapping xi -> L give the solid angle one unit of xi covers, |dL/du x dL/dv|;
    // its inverse is the density of the sampled directions, which FPdf must equal.
    if (facts().emitsOnly || !facts().singleLobeSampler) return;
    requireAttempted();
    const float h = 1e-3f;
    int compared = 0;
    for (float view : {30.0f, 60.0f})
        for (float u : {0.15f, 0.35f, 0.55f, 0.75f})
            for (float v : {0.1f, 0.3f, 0.6f, 0.85f}) {
                ProbePoint point = viewFrom(view);
                ProbeResult at = student().generateAt(point, RtFloat2(u, v));
                ProbeResult du1 = student().generateAt(point, RtFloat2(u + h, v));
                ProbeResult du0 = student().generateAt(point, RtFloat2(u - h, v));
                ProbeResult dv1 = student().generateAt(point, RtFloat2(u, v + h));
                ProbeResult dv0 = student().generateAt(point, RtFloat2(u, v - h));
                if (!at.valid || !du1.valid || !du0.valid || !dv1.valid || !dv0.valid) continue;
                Vec3 dLdu = (glm::normalize(du1.L) - glm::normalize(du0.L)) / (2 * h);
                Vec3 dLdv = (glm::normalize(dv1.L) - glm::normalize(dv0.L)) / (2 * h);
                double area = glm::length(glm::cross(dLdu, dLdv));
                if (!(area > 0)) continue;
                ++compared;
                INFO("viewer at " << view << " degrees, xi = (" << u << ", " << v << "): FPdf " << at.FPdf
                                  << ", 1/|Jacobian| " << 1.0 / area);
                REQUIRE(std::fabs(1.0 / area - at.FPdf) <= 0.02 * at.FPdf);
            }
    REQUIRE(compared > 0);
}

TEST_CASE("consistency: EvaluateSample and EvaluateSamplesAtIndex agree with GenerateSample", "[consistency]") {
    requireAttempted();
    if (facts().emitsOnly) return;
    for (float view : {10.0f, 50.0f, 85.0f}) {
        std::vector<ProbePoint> points(512, viewFrom(view));
        auto generated = student().generate(points);
        std::vector<Vec3> L;
        for (auto const& g : generated) L.push_back(g.L);
        auto evaluated = student().evaluate(points, L);
        auto atIndex = student().evaluateAtIndex(points[0], L);
        int valid = 0;
        for (size_t i = 0; i < generated.size(); ++i) {
            if (!generated[i].valid) continue;
            ++valid;
            INFO("sample " << i << " with the viewer at " << view << " degrees");
            REQUIRE(generated[i].FPdf > 0.0f);
            REQUIRE(close(evaluated[i].FPdf, generated[i].FPdf, 1e-4f));
            REQUIRE(close(atIndex[i].FPdf, generated[i].FPdf, 1e-4f));
            for (int c = 0; c < 3; ++c) {
                REQUIRE(close(evaluated[i].W[c], generated[i].W[c], 1e-4f));
                REQUIRE(close(atIndex[i].W[c], generated[i].W[c], 1e-4f));
            }
        }
        REQUIRE(valid > 0);
    }
}

TEST_CASE("reciprocity: f(V, L) = f(L, V) and RPdf(V, L) = FPdf(L, V)", "[reciprocity]") {
    requireAttempted();
    if (!facts().reciprocal) return;
    for (float thetaV : {10.0f, 45.0f, 75.0f})
        for (float thetaL : {20.0f, 55.0f, 80.0f}) {
            Vec3 V = direction(thetaV, 20.0f), L = direction(thetaL, 150.0f);
            ProbePoint fromL;
            fromL.V = L;
            auto forward = student().evaluate({viewFrom(thetaV)}, {L})[0];
            auto backward = student().evaluate({fromL}, {V})[0];
            INFO("theta_V " << thetaV << ", theta_L " << thetaL);
            for (int c = 0; c < 3; ++c) REQUIRE(close(forward.W[c] / L.z, backward.W[c] / V.z, 1e-3f));
            REQUIRE(close(forward.RPdf, backward.FPdf, 1e-3f));
        }
}

TEST_CASE("energy: the directional albedo is at most 1 and matches the solution's", "[energy]") {
    requireAttempted();
    if (facts().emitsOnly) return;
    for (float view : {0.0f, 45.0f, 80.0f}) {
        auto albedo = [&](BxdfProbe& p) {
            std::vector<ProbePoint> points(32768, viewFrom(view));
            double sum = 0.0;
            for (auto const& g : p.generate(points))
                if (g.valid && g.FPdf > 0) sum += g.W.g / g.FPdf;
            return sum / static_cast<double>(points.size());
        };
        double mine = albedo(student()), theirs = albedo(solution());
        INFO("viewer at " << view << " degrees: albedo " << mine << ", the solution's " << theirs);
        if (facts().conservesEnergy) REQUIRE(mine <= 1.01);
        REQUIRE(mine == Approx(theirs).epsilon(0.01));
    }
}

TEST_CASE("hardcases: grazing and back-facing views, degenerate tangents, extreme random numbers", "[hardcases]") {
    requireAttempted();
    const float tiny = 1e-7f;
    std::vector<Vec3> views = {Vec3(0, 0, 1), glm::normalize(Vec3(1, 0, tiny)), Vec3(1, 0, 0),
                               glm::normalize(Vec3(1, 0, -tiny)), glm::normalize(Vec3(0.3f, 0.2f, -0.9f))};
    std::vector<Vec3> tangents = {Vec3(1, 0, 0), Vec3(0), Vec3(0, 0, 1), Vec3(0, 3, 0.5f)};
    std::vector<Vec3> lights = {Vec3(0, 0, 1), glm::normalize(Vec3(0, 1, tiny)), Vec3(0, 1, 0),
                                glm::normalize(Vec3(0, 1, -tiny))};
    for (Vec3 const& V : views)
        for (Vec3 const& T : tangents) {
            ProbePoint point;
            point.V = V;
            point.dPdu = T;
            INFO("V = (" << V.x << ", " << V.y << ", " << V.z << "), dPdu = (" << T.x << ", " << T.y << ", " << T.z << ")");
            for (float xi : {-1.0f, 0.0f, 1.0f - 0x1p-24f}) {
                INFO("random numbers: " << (xi < 0 ? std::string("a sequence") : std::to_string(xi)));
                for (auto const& g : student().generate(std::vector<ProbePoint>(xi < 0 ? 32 : 1, point), 0, 0, xi)) {
                    for (int c = 0; c < 3; ++c) REQUIRE(std::isfinite(g.W[c]));
                    REQUIRE(std::isfinite(g.FPdf));
                    REQUIRE(g.FPdf >= 0.0f);
                    if (g.valid) {
                        REQUIRE(g.FPdf > 0.0f);
                        REQUIRE(isFinite(g.L));
                    }
                }
            }
            for (auto const& e : student().evaluate(std::vector<ProbePoint>(lights.size(), point), lights)) {
                for (int c = 0; c < 3; ++c) REQUIRE(std::isfinite(e.W[c]));
                REQUIRE(std::isfinite(e.FPdf));
                REQUIRE(e.FPdf >= 0.0f);
            }
        }
}
