// consistency: at every direction GenerateSample returns, EvaluateSample and
// EvaluateSamplesAtIndex give the same W, FPdf and RPdf (0.01%), and a valid
// sample has FPdf > 0 -- what PxrValidateBxdf shows as a picture. And each
// point's answers depend on that point alone: not on its place in the batch,
// nor on another thread shading at the same time; a point that wants no lobe
// gets none.
#include <cmath>

#include "checks/CheckSupport.h"

namespace bxdflab {

using namespace checks;

namespace {

double const kTolerance = 1e-4;

/// Points that differ in normal, tangent and view, each in a frame of its own
/// turned about the checks' axis, viewed from the exercise's sides.
struct MixedBatch {
    std::vector<Frame> frames;
    std::vector<ProbePoint> points;
    std::vector<Vec3> localViews;

    MixedBatch(Exercise const& e, size_t count, double phiStep) {
        std::vector<double> viewThetas = {10.0, 50.0, 85.0};
        if (e.transmits) viewThetas.insert(viewThetas.end(), {120.0, 160.0});
        for (float degrees : {40.0f, 130.0f, 220.0f, 310.0f}) frames.emplace_back(degrees);
        for (size_t j = 0; j < count; ++j) {
            localViews.push_back(direction(viewThetas[j % viewThetas.size()], 20.0 + phiStep * static_cast<double>(j)));
            points.push_back(frameOf(j).point(localViews.back()));
        }
    }
    Frame const& frameOf(size_t j) const { return frames[j % frames.size()]; }
    /// Where to evaluate point j: where its sample went (where the lobes are),
    /// else a fixed direction.
    std::vector<Vec3> directions(std::vector<ProbeResult> const& generated) const {
        std::vector<Vec3> L;
        for (size_t j = 0; j < points.size(); ++j)
            L.push_back(generated[j].valid ? generated[j].L
                                           : frameOf(j).toWorld(direction(40, 110.0 + 31.0 * static_cast<double>(j))));
        return L;
    }
    /// "L theta .., W (..), FPdf .., RPdf .." of point j's answer.
    std::string told(size_t j, ProbeResult const& r) const {
        if (!r.valid) return "nothing (no valid lobe)";
        return "L " + describeDirection(frameOf(j).toLocal(r.L)) + ", W " + describe(r.W) + ", FPdf " + number(r.FPdf) +
               ", RPdf " + number(r.RPdf);
    }
};

/// The same W, FPdf and RPdf, to kTolerance.
bool sameWeightAndPdfs(ProbeResult const& a, ProbeResult const& b) {
    bool equal = close(a.FPdf, b.FPdf, kTolerance, 1e-9) && close(a.RPdf, b.RPdf, kTolerance, 1e-9);
    for (int k = 0; k < 3; ++k) equal = equal && close(a.W[k], b.W[k], kTolerance, 1e-9);
    return equal;
}

/// The same answer: both invalid, or both valid with the same W and pdfs (and
/// the same direction when compareL).
bool sameAnswer(ProbeResult const& a, ProbeResult const& b, bool compareL) {
    if (a.valid != b.valid) return false;
    if (!a.valid) return true;
    bool equal = sameWeightAndPdfs(a, b);
    for (int k = 0; k < 3 && compareL; ++k) equal = equal && std::fabs(a.L[k] - b.L[k]) < 1e-5f;
    return equal;
}

/// A batch of points that differ in normal, tangent, view, parameters (as a
/// texture makes them) and random numbers is asked, then asked again moved one
/// place later behind a new first point (which wants no lobe, and must get
/// nothing): every point keeps all it had, so its answers must not change. A
/// Bxdf that reads index 0 (gloss[0], m_Nn[0], lobesWanted[0]) or a
/// neighbour's entry where it should read [i] answers differently. Returns the
/// failure, or nothing.
std::string answersDependOnPlaceInBatch(CheckContext& c, std::string const& params, std::string const& modeName) {
    size_t const n = 64;
    MixedBatch const batch(c.exercise, n, 47.0);
    std::vector<SampleSpec> samples = stratifiedSamples(n, c.seed + 11u);

    Frame const newcomerFrame(175.0f);
    std::vector<ProbePoint> moved = {newcomerFrame.point(direction(35, 250))};
    moved[0].wantsLobes = false;
    moved.insert(moved.end(), batch.points.begin(), batch.points.end() - 1);
    std::vector<SampleSpec> movedSamples = stratifiedSamples(1, c.seed + 13u);
    movedSamples.insert(movedSamples.end(), samples.begin(), samples.end() - 1);
    std::string const asked = varyingParams(params, 0), askedMoved = varyingParams(params, -1);

    auto differs = [&](char const* call, size_t j, ProbeResult const& before, ProbeResult const& after) {
        return std::string(call) + " answered differently for one point when only the other points of its batch " +
               "changed (sampling mode \"" + modeName + "\", " + withParams(params) +
               ", varying from point to point): the point at index " + std::to_string(j) + ", the viewer at " +
               describeDirection(batch.localViews[j]) + ", moved to index " + std::to_string(j + 1) +
               " with the same normal, view, parameters and random numbers, and its answer went from " +
               batch.told(j, before) + " to " + batch.told(j, after) +
               ". Each point's answer may depend on that point alone: does a loop read index 0 (gloss[0], "
               "m_Nn[0], lobesWanted[0]) or a neighbour's entry where it should read [i], or draw random numbers "
               "anywhere but from the RixRNG it is given?";
    };

    auto wantedNothing = [&](char const* call, char const* answered) {
        return std::string(call) + " " + answered + " for a point whose lobesWanted asks for no lobe (sampling mode \"" +
               modeName + "\", " + withParams(params) + ", the first point of a batch): an integrator that wants no " +
               "lobe of this Bxdf at a point (past its diffuse depth, say) must get nothing there. Test lobesWanted[i] " +
               "against the lobes each point would sample or evaluate, and leave the point alone when it wants none";
    };
    auto generated = c.plugin.generate(asked, batch.points, samples);
    auto generatedMoved = c.plugin.generate(askedMoved, moved, movedSamples);
    if (generatedMoved[0].valid) return wantedNothing("GenerateSample", "returned a valid sample");
    for (size_t j = 0; j + 1 < n; ++j)
        if (!sameAnswer(generated[j], generatedMoved[j + 1], true))
            return differs("GenerateSample", j, generated[j], generatedMoved[j + 1]);

    std::vector<Vec3> L = batch.directions(generated);
    std::vector<Vec3> movedL = {newcomerFrame.toWorld(direction(25, 80))};
    movedL.insert(movedL.end(), L.begin(), L.end() - 1);
    auto evaluated = c.plugin.evaluate(asked, batch.points, L);
    auto evaluatedMoved = c.plugin.evaluate(askedMoved, moved, movedL);
    if (evaluatedMoved[0].valid) return wantedNothing("EvaluateSample", "evaluated a lobe");
    for (size_t j = 0; j + 1 < n; ++j)
        if (!sameAnswer(evaluated[j], evaluatedMoved[j + 1], false))
            return differs("EvaluateSample", j, evaluated[j], evaluatedMoved[j + 1]);
    return {};
}

/// A renderer shades on several threads at once, each with its own batch. Two
/// instances of the plugin ask for the two halves of a batch on two threads at
/// once, round after round; every answer must be the one a single thread
/// gets. A Bxdf that keeps per-call data in a static or global variable (a
/// scratch array, the last pdf) mixes the two threads' data. Returns the
/// failure, or nothing.
std::string answersDependOnOtherThreads(CheckContext& c, std::string const& params, std::string const& modeName) {
    // Long runs of rounds: on a busy or single core the two threads overlap
    // only where one is interrupted in the middle of a call.
    size_t const n = 1024;
    int const rounds = 200;
    MixedBatch const batch(c.exercise, n, 29.0);
    std::vector<SampleSpec> samples = stratifiedSamples(n, c.seed + 17u);
    std::string const together = askedTogether(params, rounds);

    auto differs = [&](char const* call, size_t j, ProbeResult const& alone, ProbeResult const& shared) {
        return std::string(call) + " answered differently when two threads asked at once (sampling mode \"" +
               modeName + "\", " + withParams(params) + "): at the viewer " + describeDirection(batch.localViews[j]) +
               " one thread gets " + batch.told(j, alone) + ", but with another thread shading other points at the "
               "same time " + batch.told(j, shared) + ". A renderer shades on many threads: does the plugin keep "
               "data of one call in a static or global variable? Take scratch memory from the shading context "
               "(RixAlloca, or the Allocator) and keep per-point values in local variables.";
    };

    auto generated = c.plugin.generate(params, batch.points, samples);
    auto generatedTogether = c.plugin.generate(together, batch.points, samples);
    for (size_t j = 0; j < n; ++j)
        if (!sameAnswer(generated[j], generatedTogether[j], true))
            return differs("GenerateSample", j, generated[j], generatedTogether[j]);

    std::vector<Vec3> L = batch.directions(generated);
    auto evaluated = c.plugin.evaluate(params, batch.points, L);
    auto evaluatedTogether = c.plugin.evaluate(together, batch.points, L);
    for (size_t j = 0; j < n; ++j)
        if (!sameAnswer(evaluated[j], evaluatedTogether[j], false))
            return differs("EvaluateSample", j, evaluated[j], evaluatedTogether[j]);
    return {};
}

}  // namespace

CheckOutcome checkConsistency(CheckContext& c) {
    Exercise const& e = c.exercise;
    if (std::string why = notAttempted(c); !why.empty()) return CheckOutcome::fail(why);
    Frame const& f = frame();
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
                    if (!sameWeightAndPdfs(*other, g))
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
    for (SamplingMode const& mode : e.samplingModes) {
        std::string const params = e.withMode(e.params, mode);
        if (std::string why = answersDependOnPlaceInBatch(c, params, mode.name); !why.empty())
            return CheckOutcome::fail(why);
        if (std::string why = answersDependOnOtherThreads(c, params, mode.name); !why.empty())
            return CheckOutcome::fail(why);
    }
    return CheckOutcome::pass("GenerateSample, EvaluateSample and EvaluateSamplesAtIndex agree at " +
                              std::to_string(compared / 2) +
                              " sampled directions, and each point's answers stay the same wherever it sits in "
                              "its batch and with two threads asking at once");
}

}  // namespace bxdflab
