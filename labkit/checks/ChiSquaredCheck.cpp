// chi2: the directions GenerateSample returns follow the FPdf that
// EvaluateSample declares, for every sampling mode and at views that differ
// for the sampler (more azimuths for anisotropic models), and at one view
// with the exercise's coloured parameter set, whose weights change the
// probabilities of a mixture's lobes. Pearson's test on
// equal-area cells (16 x 32) of about a million independent draws per view;
// expected counts integrate FPdf adaptively over each cell; the draws that
// come back invalid are one more category. Sidak's correction over every
// test keeps a correct plugin's chance of failing below context.alpha.
#include <cmath>

#include "checks/CheckSupport.h"
#include "stats/DirectionTest.h"

namespace bxdflab {

using namespace checks;

namespace {

struct View {
    double theta, phi;
    bool bentNormal = false;  ///< the geometric normal bent away from the shading normal
};

std::vector<View> viewsFor(Exercise const& e) {
    // The bent view: samples must gather about the shading normal, not the geometric one.
    std::vector<View> views = {{0, 20}, {45, 20}, {80, 20}, {45, 20, true}};
    if (e.anisotropic) views.insert(views.end(), {{45, 110}, {80, 65}});
    if (e.transmits) views.insert(views.end(), {{130, 20}, {165, 20}});  // from inside: one beyond the critical angle
    return views;
}

}  // namespace

CheckOutcome checkChiSquared(CheckContext& c) {
    Exercise const& e = c.exercise;
    if (std::string why = notAttempted(c); !why.empty()) return CheckOutcome::fail(why);
    Frame const& f = frame();
    // Every view with the exercise's parameters, and one with its coloured set, whose
    // other weights move the mixture's lobe probabilities (Ward's diffuse part, say).
    std::vector<std::pair<std::string, View>> probes;
    for (View const& view : viewsFor(e)) probes.push_back({e.params, view});
    if (e.colorParams != e.params) probes.push_back({e.colorParams, View{45, 20}});
    int const tests = static_cast<int>(probes.size() * e.samplingModes.size());
    double const alphaEach = sidak(c.alpha, tests);
    long const samples = c.chiSquaredSamples;
    DirectionCells cells;
    cells.fullSphere = e.transmits;
    std::string details;
    int testIndex = 0;
    for (SamplingMode const& mode : e.samplingModes) {
        for (auto const& [base, view] : probes) {
            std::string const params = e.withMode(base, mode);
            ++testIndex;
            Vec3 localV = direction(view.theta, view.phi);
            ProbePoint point = view.bentNormal ? f.bentPoint(localV) : f.point(localV);
            DirectionCounts counts(cells);
            long const batch = 1 << 17;
            for (long first = 0; first < samples; first += batch) {
                size_t n = static_cast<size_t>(std::min(batch, samples - first));
                auto drawn = c.plugin.generate(params, std::vector<ProbePoint>(n, point),
                                               independentSamples(n, c.seed * 7919u + static_cast<uint32_t>(testIndex),
                                                                  static_cast<uint32_t>(first)));
                for (auto const& g : drawn) counts.add(g.valid, f.toLocal(g.L), g.FPdf);
            }
            BatchPdf pdf = [&](std::vector<Vec3> const& local) {
                std::vector<Vec3> world;
                world.reserve(local.size());
                for (auto const& l : local) world.push_back(f.toWorld(l));
                std::vector<double> out;
                out.reserve(local.size());
                for (auto const& r : c.plugin.evaluate(params, std::vector<ProbePoint>(local.size(), point), world))
                    out.push_back(r.FPdf);
                return out;
            };
            auto mass = integrateCells(cells, pdf, toleranceForSamples(static_cast<double>(samples)));
            integrateEmptyCellsFinely(cells, counts.observed, pdf, mass, 64, &counts.example);
            DirectionTestResult t = testDirections(counts, mass);

            std::string where = "with the viewer at " + describeDirection(localV) +
                                (view.bentNormal ? ", the shading normal bent 20 deg from the geometric normal," : "") +
                                " and sampling mode \"" + mode.name + "\"" +
                                (base == e.params ? "" : ", " + withParams(base));
            char line[1024];
            std::snprintf(line, sizeof line,
                          "%s: %ld draws, %ld invalid; FPdf integrates to %.4f; chi-squared %.1f with %d degrees of "
                          "freedom, p = %.3g (needed above %.2g)\n",
                          where.c_str(), counts.total, counts.invalid, t.pdfMass, t.chi.statistic,
                          t.chi.degreesOfFreedom, t.chi.pValue, alphaEach);
            details += line;
            if (counts.total == counts.invalid)
                return CheckOutcome::fail(where + ": none of " + std::to_string(counts.total) +
                                              " samples was valid (lobeSampled[i].SetValid(true) never happened)",
                                          details);
            if (counts.nonFinite > 0)
                return CheckOutcome::fail(where + ": " + std::to_string(counts.nonFinite) +
                                              " valid samples had a NaN, infinite or zero direction or pdf",
                                          details);
            if (counts.outside > 0)
                return CheckOutcome::fail(where + ": " + std::to_string(counts.outside) +
                                              " valid samples point below the surface, where this model reflects "
                                              "nothing; mark such samples invalid",
                                          details);
            if (t.impossible > 0)
                return CheckOutcome::fail(where + ": " + std::to_string(t.impossible) +
                                              " valid samples fell where your FPdf is zero",
                                          details);
            if (t.pdfMass > 1.0 + 1e-3)
                return CheckOutcome::fail(where + ": your FPdf integrates to " + number(t.pdfMass) +
                                              (e.transmits ? " over the sphere" : " over the hemisphere") +
                                              ", but a probability density integrates to at most 1",
                                          details);
            if (!(t.chi.pValue > alphaEach))
                return CheckOutcome::fail(where + ": your samples do not follow your FPdf (chi-squared " +
                                              number(t.chi.statistic) + " with " +
                                              std::to_string(t.chi.degreesOfFreedom) + " degrees of freedom, p = " +
                                              number(t.chi.pValue) + "); " + t.worstCell + ".",
                                          details);
        }
    }
    return CheckOutcome::pass("samples follow FPdf in all " + std::to_string(tests) + " tests", details);
}

}  // namespace bxdflab
