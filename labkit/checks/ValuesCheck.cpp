// values: W and emission equal the reference's at fixed directions, for every
// parameter set and sampling mode, to 0.1%; again with the parameters varying
// from point to point, and where the shading normal is bent away from the
// geometric one. FPdf and RPdf are compared too, but pdfs of another valid
// sampling strategy are accepted (and said): whether the samples follow
// them is chi2's question, whether RPdf mirrors FPdf reciprocity's. A pdf
// that is negative or not finite, or zero where the reference samples and W
// is not black (no sample would ever find that light), is never accepted.
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

    int compared = 0, differing = 0, oneSidedViews = 0, pdfsOfTheirOwn = 0;
    std::string first, firstOwnPdf;
    // "your <what> at V = ... and L = ..., with <params>, is <mine>"
    auto yoursAt = [&](std::string const& what, Vec3 const& v, Vec3 const& l, std::string const& params,
                       std::string const& mine, std::string const& where) {
        return "your " + what + " at V = " + describeDirection(v) + " and L = " + describeDirection(l) +
               where + ", " + withParams(params) + ", is " + mine;
    };
    auto reportAt = [&](std::string const& what, Vec3 const& v, Vec3 const& l, std::string const& params,
                        std::string const& mine, std::string const& theirs, std::string const& where) {
        ++differing;
        if (!first.empty()) return;
        first = yoursAt(what, v, l, params, mine, where) + "; the reference's is " + theirs + ".";
        if (v.z < 0) first += " This view is below the surface.";
        if (l.z < 0) first += " This light direction is below the surface.";
    };
    auto report = [&](std::string const& what, size_t i, std::string const& params, std::string const& mine,
                      std::string const& theirs, std::string const& where) {
        reportAt(what, localV[i], localL[i % perView], params, mine, theirs, where);
    };
    // W and both pdfs of one answer against the reference's.
    auto compare = [&](ProbeResult const& m, ProbeResult const& t, Vec3 const& v, Vec3 const& l,
                       std::string const& params, std::string const& modeName, std::string const& where) {
        compared += 3;
        bool sameW = true;
        for (int k = 0; k < 3; ++k) sameW = sameW && close(m.W[k], t.W[k], tolerance);
        if (!sameW) reportAt("W = f cos(theta_L)", v, l, params, describe(m.W), describe(t.W), where);
        auto comparePdf = [&](char const* name, float mine, float theirs) {
            if (close(mine, theirs, tolerance)) return;
            std::string const what = std::string(name) + " (sampling mode " + modeName + ")";
            if (!std::isfinite(mine) || mine < 0.0f) {
                reportAt(what, v, l, params, number(mine), number(theirs), where);
                return;
            }
            if (theirs > 0.0f && mine == 0.0f && !t.W.IsBlack()) {
                reportAt(what, v, l, params, number(mine), number(theirs) + ", and W is not black there", where);
                return;
            }
            if (pdfsOfTheirOwn++ == 0)
                firstOwnPdf = yoursAt(what, v, l, params, number(mine), where) +
                              " where the reference's is " + number(theirs);
        };
        comparePdf("FPdf", m.FPdf, t.FPdf);
        comparePdf("RPdf", m.RPdf, t.RPdf);
    };

    // Each parameter set as given, then differing from point to point as a
    // texture makes it (where a Bxdf reads point 0's value for every point).
    std::string const varyingNote = " (the parameters varying from point to point, as a texture makes them)";
    for (bool varying : {false, true}) {
        for (std::string const& base : {e.params, e.colorParams}) {
            bool firstMode = true;
            for (SamplingMode const& mode : e.samplingModes) {
                std::string const params = e.withMode(base, mode);
                std::string const asked = varying ? varyingParams(params) : params;
                std::string const note = varying ? varyingNote : "";
                auto mine = c.plugin.evaluate(asked, points, L), theirs = c.reference.evaluate(asked, points, L);
                if (firstMode) {
                    auto emitMine = c.plugin.emission(asked, points), emitTheirs = c.reference.emission(asked, points);
                    for (size_t i = 0; i < points.size(); i += perView) {
                        ++compared;
                        bool same = true;
                        for (int k = 0; k < 3; ++k) same = same && close(emitMine[i][k], emitTheirs[i][k], tolerance);
                        if (!same)
                            report("emission (EmitLocal)", i, params, describe(emitMine[i]), describe(emitTheirs[i]),
                                   note);
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
                    for (size_t i = begin; i < begin + perView; ++i)
                        compare(mine[i], theirs[i], localV[i], localL[i % perView], params, mode.name, note);
                }
            }
        }
    }

    // Interpolated normals on a smooth-shaded mesh bend the shading normal N
    // away from the geometric normal Ng; the model's cosines and lobes follow N.
    // Compared only where V and L are clearly on the same side of both: what
    // to do between the two horizons is left to the writer.
    Vec3 const localNg = bentGeometricNormal();
    auto clearOfBoth = [&](Vec3 const& w) {
        float const n = w.z, g = glm::dot(w, localNg);
        return (n > 0.0f) == (g > 0.0f) && std::min(std::fabs(n), std::fabs(g)) > 0.1f;
    };
    std::vector<ProbePoint> bentPoints;
    std::vector<Vec3> bentL, bentLocalV, bentLocalL;
    for (double thetaV : {0.0, 30.0, 60.0}) {
        Vec3 const V = direction(thetaV, 20);
        if (!clearOfBoth(V)) continue;
        for (Vec3 const& l : localL) {
            if (!clearOfBoth(l)) continue;
            bentPoints.push_back(f.bentPoint(V));
            bentL.push_back(f.toWorld(l));
            bentLocalV.push_back(V);
            bentLocalL.push_back(l);
        }
    }
    std::string const bent = " (the shading normal bent 20 deg from the geometric normal)";
    for (std::string const& base : {e.params, e.colorParams})
        for (SamplingMode const& mode : e.samplingModes) {
            std::string const params = e.withMode(base, mode);
            auto mine = c.plugin.evaluate(params, bentPoints, bentL);
            auto theirs = c.reference.evaluate(params, bentPoints, bentL);
            for (size_t i = 0; i < bentPoints.size(); ++i)
                compare(mine[i], theirs[i], bentLocalV[i], bentLocalL[i], params, mode.name, bent);
        }
    std::string details = std::to_string(compared) + " values compared at " + std::to_string(viewThetas.size()) +
                          " views and " + std::to_string(perView) +
                          " light directions (each parameter set as given and varying from point to point), and at " +
                          std::to_string(bentPoints.size()) + " view and light pairs with a bent shading normal, to " +
                          number(100 * tolerance) + "%.";
    if (oneSidedViews)
        details += " Your model is black seen from below (one-sided); the exercise accepts that.";
    if (pdfsOfTheirOwn)
        details += " " + std::to_string(pdfsOfTheirOwn) +
                   " of your pdfs differ from the reference's: a sampling strategy of your own, accepted here; chi2 "
                   "checks that your samples follow your FPdf. The first: " + firstOwnPdf + ".";
    if (differing)
        return CheckOutcome::fail(std::to_string(differing) + " of " + std::to_string(compared) +
                                      " values differ from the reference's by more than " + number(100 * tolerance) +
                                      "%. The first: " + first,
                                  details);
    if (pdfsOfTheirOwn)
        return CheckOutcome::pass("W and emission match the reference's everywhere; " + std::to_string(pdfsOfTheirOwn) +
                                      " of your pdfs differ from its (another sampling strategy: chi2 checks it)",
                                  details);
    return CheckOutcome::pass("all " + std::to_string(compared) + " values match the reference's", details);
}

}  // namespace bxdflab
