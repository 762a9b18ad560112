// energy: the directional albedo, the integral of W = f cos over the
// hemisphere, is at most 1 where the model conserves energy and equals the
// reference's within 1%. It is estimated from the plugin's W alone -- never
// from its own sampler, so a sampling bug is blamed on sampling (chi2,
// jacobian), not here: directions come from two strategies the checker
// trusts, uniform hemisphere sampling and the reference's GenerateSample,
// combined by the balance heuristic (multi-sample MIS). A transmitting model
// is integrated over the whole sphere, each direction's W weighted by
// (eta_L / eta_V)^2: radiance / eta^2 is what a lossless boundary conserves
// (from inside glass the transmitted radiance alone is up to eta^2 times the incident).
#include <cmath>

#include "checks/CheckSupport.h"

namespace bxdflab {

using namespace checks;

CheckOutcome checkEnergy(CheckContext& c) {
    Exercise const& e = c.exercise;
    if (e.emitsOnly) return CheckOutcome::notApplicable("not applicable: an emitter reflects nothing");
    if (std::string why = notAttempted(c); !why.empty()) return CheckOutcome::fail(why);
    Frame const& f = frame();
    std::string const& params = e.params;
    size_t const n = 65536;
    double const ior = e.ior(params);
    std::string details;
    std::string const reflects = e.transmits ? "scatters (reflects and transmits, counting radiance / eta^2)" : "reflects";
    std::vector<double> views = {0.0, 45.0, 80.0};
    if (e.transmits) views.insert(views.end(), {150.0, 115.0});  // from inside; 115: mostly totally reflected
    for (double view : views) {
        Vec3 localV = direction(view, 20);
        ProbePoint point = f.point(localV);
        std::vector<ProbePoint> points(n, point);

        // Strategy 1: uniform over the hemisphere, or the sphere (stratified by the checker).
        double const zLow = e.transmits ? -1.0 : 0.0;
        std::vector<Vec3> L;
        uint32_t root = static_cast<uint32_t>(std::sqrt(static_cast<double>(n)));
        RixRNG::SampleCtx jitter{RixRNG::Hash(c.seed + 11u), 0, 0, -1.0f, -1.0f};
        for (uint32_t i = 0; i < n; ++i) {
            jitter.sampleid = i;
            RtFloat2 xi = RixRNG::Sample2D(jitter);
            jitter.draw = 0;
            double z = zLow + (1.0 - zLow) * ((i / root) + xi.x) / root, phi = 2 * M_PI * ((i % root) + xi.y) / root;
            L.push_back(f.toWorld(Vec3(static_cast<float>(std::sqrt(1 - z * z) * std::cos(phi)),
                                       static_cast<float>(std::sqrt(1 - z * z) * std::sin(phi)), static_cast<float>(z))));
        }
        // Strategy 2: the reference's own sampler.
        auto referenceDrawn = c.reference.generate(params, points, stratifiedSamples(n, c.seed + 13u));
        std::vector<int> fromReference;
        for (size_t i = 0; i < n; ++i)
            if (referenceDrawn[i].valid && referenceDrawn[i].FPdf > 0.0f && isFinite(referenceDrawn[i].L)) {
                L.push_back(glm::normalize(referenceDrawn[i].L));
                fromReference.push_back(static_cast<int>(i));
            }
        std::vector<ProbePoint> all(L.size(), point);
        auto mine = c.plugin.evaluate(params, all, L);
        auto theirs = c.reference.evaluate(params, all, L);

        double albedoMine[3] = {0, 0, 0}, albedoTheirs[3] = {0, 0, 0};
        double const uniformPdf = 1.0 / ((1.0 - zLow) * 2 * M_PI);
        double const etaV = indexOfSide(ior, localV);
        for (size_t k = 0; k < L.size(); ++k) {
            Vec3 const local = f.toLocal(L[k]);
            double pUniform = local.z > zLow ? uniformPdf : 0.0;
            double const etaL = indexOfSide(ior, local), radianceScale = (etaL * etaL) / (etaV * etaV);
            double pReference = std::max(0.0, static_cast<double>(theirs[k].FPdf));
            double denominator = pUniform + pReference;
            if (!(denominator > 0)) continue;
            for (int ch = 0; ch < 3; ++ch) {
                double wm = mine[k].W[ch] * radianceScale, wt = theirs[k].W[ch] * radianceScale;
                albedoMine[ch] += (std::isfinite(wm) ? wm : 0.0) / denominator;
                albedoTheirs[ch] += wt / denominator;
            }
        }
        std::string where = "with the viewer at " + describeDirection(localV);
        for (int ch = 0; ch < 3; ++ch) {
            albedoMine[ch] /= static_cast<double>(n);
            albedoTheirs[ch] /= static_cast<double>(n);
        }
        details += where + ": albedo " + number(albedoMine[1]) + " (the reference's " + number(albedoTheirs[1]) + ")\n";
        for (int ch = 0; ch < 3; ++ch) {
            if (e.conservesEnergy && albedoMine[ch] > 1.01)
                return CheckOutcome::fail(where + ": your surface " + reflects + " " + number(albedoMine[ch]) +
                                              " of the light it receives (directional albedo, channel " +
                                              std::to_string(ch) + " " + withParams(params) +
                                              "); a passive surface reflects at most 1",
                                          details);
            if (!close(albedoMine[ch], albedoTheirs[ch], 0.01, 0.002))
                return CheckOutcome::fail(where + ": your surface " + reflects + " " + number(albedoMine[ch]) +
                                              " of the light it receives, the reference " + number(albedoTheirs[ch]) +
                                              " (directional albedo, channel " + std::to_string(ch) + ", " +
                                              withParams(params) + "; 1% allowed)",
                                          details);
        }
    }
    return CheckOutcome::pass("the directional albedo matches the reference's at " + std::to_string(views.size()) + " views",
                              details);
}

}  // namespace bxdflab
