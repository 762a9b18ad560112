// consistency: at every direction GenerateSample returns, EvaluateSample and
// EvaluateSamplesAtIndex give the same W, FPdf and RPdf (0.01%), and a valid
// sample has FPdf > 0 -- what PxrValidateBxdf shows as a picture. And each
// point's answers depend on that point alone, not on its place in the batch.
#include <cmath>

#include "checks/CheckSupport.h"

namespace bxdflab {

using namespace checks;

namespace {

/// A batch of points that differ in normal, tangent, view, parameters (as a
/// texture makes them) and random numbers is asked, then asked again moved one
/// place later behind a new first point (which wants no lobe): every point keeps
/// all it had, so its answers must not change. A Bxdf that reads index 0
/// (gloss[0], m_Nn[0], lobesWanted[0]) or a neighbour's entry where it should
/// read [i] answers differently. Returns
/// the failure, or nothing.
std::string answersDependOnPlaceInBatch(CheckContext& c, std::string const& params, std::string const& modeName) {
    Exercise const& e = c.exercise;
    std::vector<double> viewThetas = {10.0, 50.0, 85.0};
    if (e.transmits) viewThetas.insert(viewThetas.end(), {120.0, 160.0});
    size_t const n = 64;
    std::vector<Frame> frames;
    for (float degrees : {40.0f, 130.0f, 220.0f, 310.0f}) frames.emplace_back(degrees);
    auto frameOf = [&](size_t j) -> Frame const& { return frames[j % frames.size()]; };
    std::vector<ProbePoint> points;
    std::vector<Vec3> localViews;
    for (size_t j = 0; j < n; ++j) {
        localViews.push_back(direction(viewThetas[j % viewThetas.size()], 20.0 + 47.0 * static_cast<double>(j)));
        points.push_back(frameOf(j).point(localViews.back()));
    }
    std::vector<SampleSpec> samples = stratifiedSamples(n, c.seed + 11u);

    // The same points one place later, behind a point facing elsewhere that
    // wants no lobe at all.
    Frame const newcomerFrame(175.0f);
    std::vector<ProbePoint> moved = {newcomerFrame.point(direction(35, 250))};
    moved[0].wantsLobes = false;
    moved.insert(moved.end(), points.begin(), points.end() - 1);
    std::vector<SampleSpec> movedSamples = stratifiedSamples(1, c.seed + 13u);
    movedSamples.insert(movedSamples.end(), samples.begin(), samples.end() - 1);
    std::string const asked = varyingParams(params, 0), askedMoved = varyingParams(params, -1);

    double const tolerance = 1e-4;
    auto same = [&](ProbeResult const& a, ProbeResult const& b, bool compareL) {
        bool equal = a.valid == b.valid;
        if (!equal || !a.valid) return equal;
        equal = close(a.FPdf, b.FPdf, tolerance, 1e-9) && close(a.RPdf, b.RPdf, tolerance, 1e-9);
        for (int k = 0; k < 3; ++k) {
            equal = equal && close(a.W[k], b.W[k], tolerance, 1e-9);
            if (compareL) equal = equal && std::fabs(a.L[k] - b.L[k]) < 1e-5f;
        }
        return equal;
    };
    auto differs = [&](char const* call, size_t j, ProbeResult const& before, ProbeResult const& after) {
        Frame const& f = frameOf(j);
        auto told = [&](ProbeResult const& r) {
            if (!r.valid) return std::string("nothing (no valid lobe)");
            return "L " + describeDirection(f.toLocal(r.L)) + ", W " + describe(r.W) + ", FPdf " + number(r.FPdf) +
                   ", RPdf " + number(r.RPdf);
        };
        return std::string(call) + " answered differently for one point when only the other points of its batch " +
               "changed (sampling mode \"" + modeName + "\", " + withParams(params) +
               ", varying from point to point): the point at index " + std::to_string(j) + ", the viewer at " +
               describeDirection(localViews[j]) + ", moved to index " + std::to_string(j + 1) +
               " with the same normal, view, parameters and random numbers, and its answer went from " + told(before) +
               " to " + told(after) + ". Each point's answer may depend on that point alone: does a loop read " +
               "index 0 (gloss[0], m_Nn[0], lobesWanted[0]) or a neighbour's entry where it should read [i], or "
               "draw random " +
               "numbers anywhere but from the RixRNG it is given?";
    };

    auto generated = c.plugin.generate(asked, points, samples);
    auto generatedMoved = c.plugin.generate(askedMoved, moved, movedSamples);
    for (size_t j = 0; j + 1 < n; ++j)
        if (!same(generated[j], generatedMoved[j + 1], true))
            return differs("GenerateSample", j, generated[j], generatedMoved[j + 1]);

    // Evaluated where the samples went (where the lobes are), else at a fixed direction.
    std::vector<Vec3> L;
    for (size_t j = 0; j < n; ++j)
        L.push_back(generated[j].valid ? generated[j].L : frameOf(j).toWorld(direction(40, 110.0 + 31.0 * j)));
    std::vector<Vec3> movedL = {newcomerFrame.toWorld(direction(25, 80))};
    movedL.insert(movedL.end(), L.begin(), L.end() - 1);
    auto evaluated = c.plugin.evaluate(asked, points, L);
    auto evaluatedMoved = c.plugin.evaluate(askedMoved, moved, movedL);
    for (size_t j = 0; j + 1 < n; ++j)
        if (!same(evaluated[j], evaluatedMoved[j + 1], false))
            return differs("EvaluateSample", j, evaluated[j], evaluatedMoved[j + 1]);
    return {};
}

}  // namespace

CheckOutcome checkConsistency(CheckContext& c) {
    Exercise const& e = c.exercise;
    if (std::string why = notAttempted(c); !why.empty()) return CheckOutcome::fail(why);
    Frame const& f = frame();
    double const tolerance = 1e-4;
    int compared = 0;
    for (SamplingMode const& mode : e.samplingModes) {
        std::string const params = e.withMode(e.params, mode);
        std::vector<double> views = {10.0, 50.0, 85.0};
        if (e.transmits) views.insert(views.end(), {120.0, 160.0});  // from inside
        for (double view : views) {
            Vec3 localV = direction(view, 20);
            ProbePoint point = f.point(localV);
            size_t const n = 512;
            std::vector<ProbePoint> points(n, point);
            auto generated = c.plugin.generate(params, points, stratifiedSamples(n, c.seed + 3u));
            std::vector<Vec3> L;
            for (auto const& g : generated) L.push_back(g.L);
            auto evaluated = c.plugin.evaluate(params, points, L);
            auto atIndex = c.plugin.evaluateAtIndex(params, point, L);
            int valid = 0;
            std::string where = "with sampling mode \"" + mode.name + "\" and the viewer at " + describeDirection(localV);
            for (size_t i = 0; i < n; ++i) {
                ProbeResult const& g = generated[i];
                if (!g.valid) continue;
                ++valid;
                std::string sample = " (the sample toward " + describeDirection(f.toLocal(g.L)) + ")";
                if (!(g.FPdf > 0.0f))
                    return CheckOutcome::fail(where + ": GenerateSample marked a sample valid with FPdf " +
                                              number(g.FPdf) + sample + "; a valid sample needs FPdf > 0");
                for (auto const& [name, other] : {std::pair<char const*, ProbeResult const*>{"EvaluateSample", &evaluated[i]},
                                                  {"EvaluateSamplesAtIndex", &atIndex[i]}}) {
                    ++compared;
                    bool same = close(other->FPdf, g.FPdf, tolerance, 1e-9) && close(other->RPdf, g.RPdf, tolerance, 1e-9);
                    for (int k = 0; k < 3; ++k) same = same && close(other->W[k], g.W[k], tolerance, 1e-9);
                    if (!same)
                        return CheckOutcome::fail(
                            where + ": GenerateSample gave W " + describe(g.W) + ", FPdf " + number(g.FPdf) + ", RPdf " +
                            number(g.RPdf) + sample + ", but " + name + " gives W " + describe(other->W) + ", FPdf " +
                            number(other->FPdf) + ", RPdf " + number(other->RPdf) + " for the same direction" +
                            (other == &atIndex[i] ? " (asked for index 1 of a batch of two points: does it read "
                                                    "index 0 where it should read [index]?)"
                                                  : ""));
                }
            }
            if (valid == 0)
                return CheckOutcome::fail(where + ": none of " + std::to_string(n) +
                                          " samples was valid (lobeSampled[i].SetValid(true) never happened)");
        }
    }
    for (SamplingMode const& mode : e.samplingModes)
        if (std::string why = answersDependOnPlaceInBatch(c, e.withMode(e.params, mode), mode.name); !why.empty())
            return CheckOutcome::fail(why);
    return CheckOutcome::pass("GenerateSample, EvaluateSample and EvaluateSamplesAtIndex agree at " +
                              std::to_string(compared / 2) +
                              " sampled directions, and each point's answers stay the same wherever it sits in "
                              "its batch");
}

}  // namespace bxdflab
