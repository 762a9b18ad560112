// reciprocity: f(V, L) = f(L, V) (W divided by its own cosine) and
// RPdf(V, L) = FPdf(L, V), to 0.1%, for every sampling mode. The pdfs must
// mirror each other whatever f does: RPdf is the density of sampling V from
// L, so a model that is not reciprocal (finished wood) still has its pdfs
// compared, and only f is left alone. Across a
// refracting boundary radiance is not symmetric but radiance / eta^2 is, so a
// transmitting model must satisfy f(V, L) / eta_V^2 = f(L, V) / eta_L^2
// (Veach 1997, section 5.2), eta_V and eta_L the indices on V's and L's sides.
// Pairs that cross are compared to 1%: Fresnel's F computed from the denser
// side near the critical angle (a correct, common way) loses a few tenths of a
// percent to float rounding, while the bugs this catches are factors of eta^2.
#include <cmath>

#include "checks/CheckSupport.h"

namespace bxdflab {

using namespace checks;

CheckOutcome checkReciprocity(CheckContext& c) {
    Exercise const& e = c.exercise;
    if (e.emitsOnly) return CheckOutcome::notApplicable("not applicable: an emitter samples no directions");
    if (std::string why = notAttempted(c); !why.empty()) return CheckOutcome::fail(why);
    Frame const& f = frame();
    double const tolerance = 1e-3;
    double const ior = e.ior(e.params);
    std::vector<double> lightThetas = {20.0, 55.0, 80.0};
    if (e.transmits) lightThetas.insert(lightThetas.end(), {115.0, 150.0});  // through the boundary
    int compared = 0;
    for (SamplingMode const& mode : e.samplingModes) {
        std::string const params = e.withMode(e.params, mode);
        std::vector<ProbePoint> forwardPoints, backwardPoints;
        std::vector<Vec3> forwardL, backwardL, localVs, localLs;
        for (double thetaV : {10.0, 45.0, 75.0})
            for (double thetaL : lightThetas)
                for (double phiL : {150.0, 260.0}) {
                    Vec3 V = direction(thetaV, 20), L = direction(thetaL, phiL);
                    forwardPoints.push_back(f.point(V));
                    forwardL.push_back(f.toWorld(L));
                    backwardPoints.push_back(f.point(L));
                    backwardL.push_back(f.toWorld(V));
                    localVs.push_back(V);
                    localLs.push_back(L);
                }
        auto forward = c.plugin.evaluate(params, forwardPoints, forwardL);
        auto backward = c.plugin.evaluate(params, backwardPoints, backwardL);
        for (size_t i = 0; i < forward.size(); ++i) {
            ++compared;
            Vec3 V = localVs[i], L = localLs[i];
            std::string where = "with sampling mode \"" + mode.name + "\", V = " + describeDirection(V) + " and L = " +
                                describeDirection(L);
            double const etaV = indexOfSide(ior, V), etaL = indexOfSide(ior, L);
            double const scaleV = 1.0 / (etaV * etaV), scaleL = 1.0 / (etaL * etaL);
            double const allowed = etaV == etaL ? tolerance : 0.01;
            for (int k = 0; k < 3 && e.reciprocal; ++k) {
                double fVL = forward[i].W[k] / std::fabs(L.z), fLV = backward[i].W[k] / std::fabs(V.z);
                if (!close(fVL * scaleV, fLV * scaleL, allowed, 1e-7)) {
                    if (etaV == etaL)
                        return CheckOutcome::fail(where + ": f(V, L) = W / |cos(theta_L)| = " + number(fVL) +
                                                  " but f(L, V) = " + number(fLV) + " (channel " + std::to_string(k) + ")");
                    return CheckOutcome::fail(where + ": across the boundary f(V, L) / eta_V^2 = " +
                                              number(fVL * scaleV) + " but f(L, V) / eta_L^2 = " + number(fLV * scaleL) +
                                              " (eta_V " + number(etaV) + ", eta_L " + number(etaL) + ", channel " +
                                              std::to_string(k) + "); radiance crossing the boundary scales by "
                                              "(eta_V / eta_L)^2");
                }
            }
            if (!close(forward[i].RPdf, backward[i].FPdf, allowed, 1e-7))
                return CheckOutcome::fail(where + ": RPdf(V, L) = " + number(forward[i].RPdf) +
                                          " but the pdf of sampling V from L, FPdf(L, V), is " + number(backward[i].FPdf));
        }
    }
    if (!e.reciprocal)
        return CheckOutcome::pass("RPdf mirrors FPdf at " + std::to_string(compared) +
                                  " direction pairs (f itself is not compared: " +
                                  (e.notReciprocalBecause.empty() ? "this model is not reciprocal"
                                                                  : e.notReciprocalBecause) +
                                  ")");
    return CheckOutcome::pass("f and the pdfs are reciprocal at " + std::to_string(compared) + " direction pairs");
}

}  // namespace bxdflab
