// values: W, FPdf, RPdf and emission equal the reference's at fixed
// directions, for every parameter set and sampling mode, to 0.1%.
#include <cmath>

#include "checks/CheckSupport.h"

namespace bxdflab {

using namespace checks;

CheckOutcome checkValues(CheckContext& c) {
    Exercise const& e = c.exercise;
    Frame const& f = frame();
    const double tolerance = 1e-3;
    std::vector<double> viewThetas = {0, 30, 60, 85, 120, 160};
    std::vector<Vec3> localL;
    for (double thetaL : {5.0, 35.0, 65.0, 88.0, 115.0, 150.0})
        for (double phiL : {0.0, 90.0, 200.0}) localL.push_back(direction(thetaL, phiL));

    std::vector<ProbePoint> points;
    std::vector<Vec3> L;
    std::vector<Vec3> localV;
    for (double thetaV : viewThetas) {
        Vec3 V = direction(thetaV, 20);
        for (Vec3 const& l : localL) {
            points.push_back(f.point(V));
            L.push_back(f.toWorld(l));
            localV.push_back(V);
        }
    }
    size_t const perView = localL.size();

    int compared = 0, differing = 0, oneSidedViews = 0;
    std::string first;
    auto report = [&](std::string const& what, size_t i, std::string const& params, std::string const& mine,
                      std::string const& theirs) {
        ++differing;
        if (!first.empty()) return;
        first = "your " + what + " at V = " + describeDirection(localV[i]) + " and L = " +
                describeDirection(localL[i % perView]) + ", " + withParams(params) + ", is " + mine +
                "; the reference's is " + theirs + ".";
        if (localV[i].z < 0) first += " This view is below the surface.";
        if (localL[i % perView].z < 0) first += " This light direction is below the surface.";
    };

    for (std::string const& base : {e.params, e.colorParams}) {
        bool firstMode = true;
        for (SamplingMode const& mode : e.samplingModes) {
            std::string const params = e.withMode(base, mode);
            auto mine = c.plugin.evaluate(params, points, L), theirs = c.reference.evaluate(params, points, L);
            if (firstMode) {
                auto emitMine = c.plugin.emission(params, points), emitTheirs = c.reference.emission(params, points);
                for (size_t i = 0; i < points.size(); i += perView) {
                    ++compared;
                    bool same = true;
                    for (int k = 0; k < 3; ++k) same = same && close(emitMine[i][k], emitTheirs[i][k], tolerance);
                    if (!same) report("emission (EmitLocal)", i, params, describe(emitMine[i]), describe(emitTheirs[i]));
                }
            }
            firstMode = false;
            for (size_t view = 0; view < viewThetas.size(); ++view) {
                size_t begin = view * perView;
                bool below = localV[begin].z < 0;
                if (below && e.sides == Sidedness::Either) {
                    // A one-sided model is black from below: accepted, like the reference's two-sided answer.
                    bool black = true;
                    for (size_t i = begin; i < begin + perView; ++i)
                        black = black && mine[i].W.IsBlack() && mine[i].FPdf == 0.0f;
                    if (black) {
                        ++oneSidedViews;
                        continue;
                    }
                }
                for (size_t i = begin; i < begin + perView; ++i) {
                    compared += 3;
                    bool sameW = true;
                    for (int k = 0; k < 3; ++k) sameW = sameW && close(mine[i].W[k], theirs[i].W[k], tolerance);
                    if (!sameW) report("W = f cos(theta_L)", i, params, describe(mine[i].W), describe(theirs[i].W));
                    if (!close(mine[i].FPdf, theirs[i].FPdf, tolerance))
                        report("FPdf (sampling mode " + mode.name + ")", i, params, number(mine[i].FPdf),
                               number(theirs[i].FPdf));
                    if (!close(mine[i].RPdf, theirs[i].RPdf, tolerance))
                        report("RPdf (sampling mode " + mode.name + ")", i, params, number(mine[i].RPdf),
                               number(theirs[i].RPdf));
                }
            }
        }
    }
    std::string details = std::to_string(compared) + " values compared at " + std::to_string(viewThetas.size()) +
                          " views and " + std::to_string(perView) + " light directions, to " + number(100 * tolerance) +
                          "%.";
    if (oneSidedViews)
        details += " Your model is black seen from below (one-sided); the exercise accepts that.";
    if (differing)
        return CheckOutcome::fail(std::to_string(differing) + " of " + std::to_string(compared) +
                                      " values differ from the reference's by more than " + number(100 * tolerance) +
                                      "%. The first: " + first,
                                  details);
    return CheckOutcome::pass("all " + std::to_string(compared) + " values match the reference's", details);
}

}  // namespace bxdflab
