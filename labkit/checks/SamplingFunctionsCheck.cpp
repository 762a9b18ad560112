// The ch08 sampling exercise: three samplers of directions about +z with
// their pdfs -- uniform over the hemisphere, cosine-weighted, and the Phong
// lobe cos^n. The same check names as a Bxdf's, applied to each function:
//   values       the pdf functions equal the reference's at fixed directions
//   chi2         sampled directions follow the reference's pdf
//   jacobian     each sampler's pdf is the density of its own mapping
//   consistency  the pdf a sampler returns equals its pdf function there
//   hardcases    xi = 0 and 1 - 2^-24, exponents 0 and 1e5: finite unit
//                directions above the horizon with finite positive pdfs
#include <cmath>

#include "checks/CheckSupport.h"
#include "stats/DirectionTest.h"

namespace bxdflab {

using namespace checks;

namespace {

struct Case {
    SamplingFunction function;
    float exponent;
    std::string name;
};

std::vector<Case> cases() {
    return {{SamplingFunction::UniformHemisphere, 0.0f, "the uniform hemisphere sampler"},
            {SamplingFunction::CosineHemisphere, 0.0f, "the cosine sampler"},
            {SamplingFunction::PhongLobe, 1.0f, "the Phong lobe sampler with n = 1"},
            {SamplingFunction::PhongLobe, 20.0f, "the Phong lobe sampler with n = 20"},
            {SamplingFunction::PhongLobe, 300.0f, "the Phong lobe sampler with n = 300"}};
}

std::vector<RtFloat2> grid(int count, uint32_t seed) {
    std::vector<RtFloat2> xi;
    for (auto const& s : independentSamples(static_cast<size_t>(count), seed)) {
        RixRNG::SampleCtx ctx = s;
        xi.push_back(RixRNG::Sample2D(ctx));
    }
    return xi;
}

CheckOutcome values(CheckContext& c) {
    std::vector<Vec3> w;
    for (double theta : {0.0, 10.0, 35.0, 60.0, 85.0, 89.9, 100.0})
        for (double phi : {0.0, 130.0, 250.0}) w.push_back(direction(theta, phi));
    int compared = 0;
    for (Case const& k : cases()) {
        auto mine = c.plugin.directionPdfs(k.function, k.exponent, w);
        auto theirs = c.reference.directionPdfs(k.function, k.exponent, w);
        for (size_t i = 0; i < w.size(); ++i) {
            ++compared;
            if (!close(mine[i], theirs[i], 1e-3, 1e-7))
                return CheckOutcome::fail("the pdf of " + k.name + " at " + describeDirection(w[i]) + " is " +
                                          number(mine[i]) + "; it should be " + number(theirs[i]));
        }
    }
    return CheckOutcome::pass("all " + std::to_string(compared) + " pdf values match");
}

CheckOutcome chiSquared(CheckContext& c) {
    auto all = cases();
    double const alphaEach = sidak(c.alpha, static_cast<int>(all.size()));
    int const n = c.chiSquaredSamples;
    std::string details;
    uint32_t index = 0;
    for (Case const& k : all) {
        DirectionCells cells;
        DirectionCounts counts(cells);
        for (auto const& d : c.plugin.sampleDirections(k.function, k.exponent, grid(n, c.seed * 31u + ++index)))
            counts.add(true, d.w, d.pdf);
        BatchPdf pdf = [&](std::vector<Vec3> const& w) {
            std::vector<double> out;
            for (float p : c.reference.directionPdfs(k.function, k.exponent, w)) out.push_back(p);
            return out;
        };
        DirectionTestResult t = testDirections(counts, integrateCells(cells, pdf, toleranceForSamples(n)));
        details += k.name + ": chi-squared " + number(t.chi.statistic) + " with " +
                   std::to_string(t.chi.degreesOfFreedom) + " degrees of freedom, p = " + number(t.chi.pValue) + "\n";
        if (counts.nonFinite)
            return CheckOutcome::fail(k.name + " returned " + std::to_string(counts.nonFinite) +
                                          " directions or pdfs that are NaN, infinite or zero-length",
                                      details);
        if (t.impossible)
            return CheckOutcome::fail(k.name + " returned " + std::to_string(t.impossible) +
                                          " directions where the density is zero (below the horizon?)",
                                      details);
        if (!(t.chi.pValue > alphaEach))
            return CheckOutcome::fail(k.name + "'s directions do not follow the density it should sample (chi-squared " +
                                          number(t.chi.statistic) + ", p = " + number(t.chi.pValue) + "); " +
                                          t.worstCell + ".",
                                      details);
    }
    return CheckOutcome::pass("all five samplers follow their densities", details);
}

CheckOutcome jacobian(CheckContext& c) {
    std::vector<RtFloat2> const& offsets = jacobianOffsets();
    int compared = 0;
    for (Case const& k : cases()) {
        std::vector<RtFloat2> xi, centres;
        for (float u : {0.15f, 0.4f, 0.65f, 0.85f})
            for (float v : {0.1f, 0.45f, 0.8f}) {
                centres.emplace_back(u, v);
                for (RtFloat2 const& o : offsets) xi.emplace_back(u + o.x, v + o.y);
            }
        auto d = c.plugin.sampleDirections(k.function, k.exponent, xi);
        for (size_t j = 0; j < centres.size(); ++j) {
            std::vector<Vec3> w;
            for (size_t o = 0; o < offsets.size(); ++o) w.push_back(d[j * offsets.size() + o].w);
            double density;
            if (!jacobianDensity(w.data(), density)) continue;
            ++compared;
            float pdf = d[j * offsets.size()].pdf;
            if (!(std::fabs(density - pdf) <= 0.01 * density))
                return CheckOutcome::fail("at xi = (" + number(centres[j].x) + ", " + number(centres[j].y) + "), " +
                                          k.name + " returns pdf " + number(pdf) +
                                          " but the directions it produces there have density " + number(density) +
                                          " (1 / |dw/du x dw/dv|)");
        }
    }
    if (compared < 20) return CheckOutcome::fail("too few smooth points to compare (" + std::to_string(compared) + ")");
    return CheckOutcome::pass("each sampler's pdf is the density of its mapping at " + std::to_string(compared) + " points");
}

CheckOutcome consistency(CheckContext& c) {
    int compared = 0;
    for (Case const& k : cases()) {
        auto drawn = c.plugin.sampleDirections(k.function, k.exponent, grid(256, c.seed + 17u));
        std::vector<Vec3> w;
        for (auto const& d : drawn) w.push_back(d.w);
        auto pdfs = c.plugin.directionPdfs(k.function, k.exponent, w);
        for (size_t i = 0; i < drawn.size(); ++i) {
            ++compared;
            if (!close(drawn[i].pdf, pdfs[i], 1e-4, 1e-9))
                return CheckOutcome::fail(k.name + " returned pdf " + number(drawn[i].pdf) + " for the direction " +
                                          describeDirection(drawn[i].w) + ", but its pdf function gives " +
                                          number(pdfs[i]) + " there");
        }
    }
    return CheckOutcome::pass("samplers and pdf functions agree at " + std::to_string(compared) + " directions");
}

CheckOutcome hardCases(CheckContext& c) {
    std::vector<RtFloat2> const xi = {{0, 0}, {0, 1 - 0x1p-24f}, {1 - 0x1p-24f, 0}, {1 - 0x1p-24f, 1 - 0x1p-24f}, {0.5f, 0.5f}};
    std::vector<Case> all = cases();
    all.push_back({SamplingFunction::PhongLobe, 0.0f, "the Phong lobe sampler with n = 0"});
    all.push_back({SamplingFunction::PhongLobe, 1e5f, "the Phong lobe sampler with n = 100000"});
    for (Case const& k : all) {
        auto d = c.plugin.sampleDirections(k.function, k.exponent, xi);
        for (size_t i = 0; i < xi.size(); ++i) {
            std::string at = k.name + " at xi = (" + number(xi[i].x) + ", " + number(xi[i].y) + ")";
            if (!isFinite(d[i].w) || std::fabs(glm::length(d[i].w) - 1.0f) > 1e-3f)
                return CheckOutcome::fail(at + " returned the direction (" + number(d[i].w.x) + ", " + number(d[i].w.y) +
                                          ", " + number(d[i].w.z) + "), not a unit vector");
            if (d[i].w.z < 0) return CheckOutcome::fail(at + " returned a direction below the horizon");
            if (!std::isfinite(d[i].pdf) || !(d[i].pdf > 0))
                return CheckOutcome::fail(at + " returned the pdf " + number(d[i].pdf) + "; a sampled direction has a finite positive pdf");
        }
    }
    return CheckOutcome::pass("every sampler survives xi = 0, xi -> 1 and extreme exponents");
}

}  // namespace

CheckOutcome checkSamplingFunctions(std::string const& check, CheckContext& context) {
    if (check == "values") return values(context);
    if (check == "chi2") return chiSquared(context);
    if (check == "jacobian") return jacobian(context);
    if (check == "consistency") return consistency(context);
    if (check == "hardcases") return hardCases(context);
    if (check == "loads") {
        context.plugin.directionPdfs(SamplingFunction::CosineHemisphere, 0.0f, {Vec3(0, 0, 1)});
        return CheckOutcome::pass("the sampling functions load");
    }
    throw std::invalid_argument("no check \"" + check + "\" for the sampling exercise");
}

}  // namespace bxdflab
