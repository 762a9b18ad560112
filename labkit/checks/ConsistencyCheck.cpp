// consistency: at every direction GenerateSample returns, EvaluateSample and
// EvaluateSamplesAtIndex give the same W, FPdf and RPdf (0.01%), and a valid
// sample has FPdf > 0 -- what PxrValidateBxdf shows as a picture.
#include <cmath>

#include "checks/CheckSupport.h"

namespace bxdflab {

using namespace checks;

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
                            number(other->FPdf) + ", RPdf " + number(other->RPdf) + " for the same direction");
                }
            }
            if (valid == 0)
                return CheckOutcome::fail(where + ": none of " + std::to_string(n) +
                                          " samples was valid (lobeSampled[i].SetValid(true) never happened)");
        }
    }
    return CheckOutcome::pass("GenerateSample, EvaluateSample and EvaluateSamplesAtIndex agree at " +
                              std::to_string(compared / 2) + " sampled directions");
}

}  // namespace bxdflab
