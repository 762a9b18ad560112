// jacobian: at fixed random numbers xi, finite differences of the mapping
// xi -> L give the solid angle one unit of xi covers, |dL/du x dL/dv|; its
// inverse is the density of the sampled directions, which FPdf must equal
// (Lajolla's check), to 1%. How the derivatives are taken: jacobianDensity.
#include <cmath>

#include "checks/CheckSupport.h"

namespace bxdflab {

using namespace checks;

CheckOutcome checkJacobian(CheckContext& c) {
    Exercise const& e = c.exercise;
    std::vector<SamplingMode> modes;
    for (auto const& m : e.samplingModes)
        if (m.singleDraw) modes.push_back(m);
    if (modes.empty())
        return CheckOutcome::notApplicable(
            "not applicable: this sampler first chooses a lobe with one random number, so its mapping from random "
            "numbers to directions is not smooth; chi2 checks its sampling");
    if (std::string why = notAttempted(c); !why.empty()) return CheckOutcome::fail(why);
    Frame const& f = frame();
    double const tolerance = 0.01;
    std::vector<RtFloat2> const& offsets = jacobianOffsets();
    std::string details;
    int compared = 0, skipped = 0;
    for (SamplingMode const& mode : modes) {
        std::string const params = e.withMode(e.params, mode);
        for (double view : {30.0, 60.0}) {
            ProbePoint point = f.point(direction(view, 20));
            std::vector<ProbePoint> points;
            std::vector<SampleSpec> samples;
            std::vector<RtFloat2> centres;
            for (float u : {0.15f, 0.35f, 0.55f, 0.75f})
                for (float v : {0.1f, 0.3f, 0.6f, 0.85f}) {
                    centres.emplace_back(u, v);
                    for (RtFloat2 const& o : offsets) {
                        points.push_back(point);
                        samples.push_back(fixedSamples(1, RtFloat2(u + o.x, v + o.y))[0]);
                    }
                }
            auto results = c.plugin.generate(params, points, samples);
            for (size_t k = 0; k < centres.size(); ++k) {
                ProbeResult const* r = &results[k * offsets.size()];
                std::vector<Vec3> local;
                bool valid = true;
                for (size_t j = 0; j < offsets.size(); ++j) {
                    valid = valid && r[j].valid;
                    local.push_back(f.toLocal(r[j].L));
                }
                double density;
                if (!valid || !jacobianDensity(local.data(), density)) {
                    ++skipped;  // an invalid sample, or a fold or seam of the mapping
                    continue;
                }
                ++compared;
                double fpdf = r[0].FPdf;
                char line[256];
                std::snprintf(line, sizeof line, "mode \"%s\", viewer at %.0f deg, xi = (%.2f, %.2f): FPdf %.5g, 1/|J| %.5g\n",
                              mode.name.c_str(), view, centres[k].x, centres[k].y, fpdf, density);
                details += line;
                if (!(std::fabs(density - fpdf) <= tolerance * std::max(density, 1e-12)))
                    return CheckOutcome::fail(
                        "with sampling mode \"" + mode.name + "\", the viewer at theta " + number(view) +
                            " deg and xi = (" + number(centres[k].x) + ", " + number(centres[k].y) + "), your FPdf is " +
                            number(fpdf) + " but the directions your mapping produces there have density " +
                            number(density) + " (1 / |dL/du x dL/dv|, differing by " +
                            number(100 * std::fabs(density - fpdf) / density) + "%; 1% allowed)",
                        details);
            }
        }
    }
    if (compared < 8)
        return CheckOutcome::fail("only " + std::to_string(compared) + " of " + std::to_string(compared + skipped) +
                                      " fixed random numbers gave a valid sample with a smooth mapping around it "
                                      "(at least 8 needed)",
                                  details);
    return CheckOutcome::pass("FPdf equals the density of the sampling mapping at " + std::to_string(compared) +
                                  " points (" + std::to_string(skipped) + " skipped on folds or invalid samples)",
                              details);
}

}  // namespace bxdflab
