// jacobian: at fixed random numbers xi, finite differences of the mapping
// xi -> L give the solid angle one unit of xi covers, |dL/du x dL/dv|; its
// inverse is the density of the sampled directions, which FPdf must equal
// (Lajolla's check), to 1%. How the derivatives are taken: jacobianDensity.
//
// A sampler may also choose a lobe with a 1-D random number (a diffuse and a
// specular lobe, each with its own mapping). Its FPdf is then the mixture's
// density, which no one lobe's mapping has, so a point whose direction changes
// when only the 1-D number does (from its lowest to its highest value) is not
// compared: chi2 checks the mixture.
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
    // The stencil is taken with the lowest 1-D number; the centre is taken
    // again with the highest, to see whether that number chooses the mapping.
    float const lowestChoice = 0.0f, highestChoice = 1.0f - 0x1p-24f;
    size_t const perCentre = offsets.size() + 1;
    std::string details;
    int compared = 0, skipped = 0, lobeChosen = 0;
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
                        samples.push_back(fixedSamples(1, RtFloat2(u + o.x, v + o.y), lowestChoice)[0]);
                    }
                    points.push_back(point);
                    samples.push_back(fixedSamples(1, RtFloat2(u, v), highestChoice)[0]);
                }
            auto results = c.plugin.generate(params, points, samples);
            for (size_t k = 0; k < centres.size(); ++k) {
                ProbeResult const* r = &results[k * perCentre];
                ProbeResult const& otherChoice = r[offsets.size()];
                if (otherChoice.valid != r[0].valid ||
                    (r[0].valid && !(glm::length(otherChoice.L - r[0].L) <= 1e-5f))) {
                    ++lobeChosen;  // the 1-D number chose between mappings
                    continue;
                }
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
    if (compared < 8 && lobeChosen > 0) {
        std::string const where = std::to_string(lobeChosen) + " of " + std::to_string(compared + skipped + lobeChosen);
        return CheckOutcome::notApplicable(
            "not applicable to your sampler: at " + where +
                " fixed random numbers its direction changed with the 1-D random number alone (it chooses a lobe "
                "with it), so its FPdf is a mixture's density, which no one mapping has; chi2 checks its sampling",
            details);
    }
    if (compared < 8)
        return CheckOutcome::fail("only " + std::to_string(compared) + " of " + std::to_string(compared + skipped) +
                                      " fixed random numbers gave a valid sample with a smooth mapping around it "
                                      "(at least 8 needed)",
                                  details);
    std::string lobes =
        lobeChosen > 0 ? ", " + std::to_string(lobeChosen) + " where the 1-D random number chose the lobe"
                       : "";
    return CheckOutcome::pass("FPdf equals the density of the sampling mapping at " +
                                  std::to_string(compared) + " points (" + std::to_string(skipped) +
                                  " skipped on folds or invalid samples" + lobes + ")",
                              details);
}

}  // namespace bxdflab
