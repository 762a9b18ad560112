#include "image/RenderComparison.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace bxdflab {
namespace {

/// The z beyond which a two-sided normal test rejects at level alpha (bisection on erfc).
double criticalZ(double alpha) {
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > alpha ? lo : hi) = mid;
    }
    return hi;
}

/// The reference's variance with a floor from its neighbourhood: a pixel
/// whose samples all happened to agree (a penumbra every sample of which
/// missed the light) reports zero variance although its neighbours, lit by
/// the same rare event, show what its noise really is. Regions that are
/// noise-free as a whole keep zero, so there the renders must still agree exactly.
std::vector<double> varianceWithNeighbourhoodFloor(RenderImage const& r) {
    int const radius = 2;
    std::vector<double> floored(r.variance.size());
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x)
            for (int c = 0; c < 3; ++c) {
                double sum = 0.0;
                int count = 0;
                for (int yy = std::max(0, y - radius); yy <= std::min(r.height - 1, y + radius); ++yy)
                    for (int xx = std::max(0, x - radius); xx <= std::min(r.width - 1, x + radius); ++xx) {
                        sum += std::max(0.0f, r.variance[3 * (static_cast<size_t>(yy) * r.width + xx) + c]);
                        ++count;
                    }
                size_t i = 3 * (static_cast<size_t>(y) * r.width + x) + c;
                floored[i] = std::max(static_cast<double>(std::max(0.0f, r.variance[i])), sum / count);
            }
    return floored;
}

}  // namespace

double relativeMse(std::vector<float> const& a, std::vector<float> const& b) {
    double sum = 0.0;
    size_t n = std::min(a.size(), b.size());
    for (size_t i = 0; i < n; ++i) {
        double d = static_cast<double>(a[i]) - b[i];
        sum += d * d / (static_cast<double>(b[i]) * b[i] + 0.01);
    }
    return n ? sum / static_cast<double>(n) : 0.0;
}

RenderImage averageBlocks(RenderImage const& image, int block) {
    RenderImage out;
    out.width = (image.width + block - 1) / block;
    out.height = (image.height + block - 1) / block;
    out.rgb.assign(3 * static_cast<size_t>(out.width) * out.height, 0.0f);
    out.variance.assign(out.rgb.size(), 0.0f);
    for (int by = 0; by < out.height; ++by)
        for (int bx = 0; bx < out.width; ++bx) {
            int x1 = std::min(image.width, (bx + 1) * block), y1 = std::min(image.height, (by + 1) * block);
            double count = static_cast<double>(x1 - bx * block) * (y1 - by * block);
            for (int c = 0; c < 3; ++c) {
                double sum = 0.0, variance = 0.0;
                for (int y = by * block; y < y1; ++y)
                    for (int x = bx * block; x < x1; ++x) {
                        size_t i = 3 * (static_cast<size_t>(y) * image.width + x) + c;
                        sum += image.rgb[i];
                        variance += image.variance[i];
                    }
                size_t o = 3 * (static_cast<size_t>(by) * out.width + bx) + c;
                out.rgb[o] = static_cast<float>(sum / count);
                out.variance[o] = static_cast<float>(variance / (count * count));  // of the mean of independent pixels
            }
        }
    return out;
}

namespace {
RenderVerdict compareUnits(RenderImage const& a, RenderImage const& b, double varianceCap, char const* unit);
}  // namespace

RenderVerdict compareRenders(RenderImage const& tested, RenderImage const& reference, double varianceCap, int block) {
    if (block <= 1 || tested.width != reference.width || tested.height != reference.height ||
        tested.rgb.size() != reference.rgb.size() || tested.variance.size() != reference.variance.size())
        return compareUnits(tested, reference, varianceCap, "pixel");
    std::string const unit = std::to_string(block) + "x" + std::to_string(block) + " square";
    RenderVerdict v = compareUnits(averageBlocks(tested, block), averageBlocks(reference, block), varianceCap, unit.c_str());
    // The map the report draws stays at full resolution: each pixel shows its square's z.
    std::vector<float> full(static_cast<size_t>(tested.width) * tested.height);
    int const blocksWide = (tested.width + block - 1) / block;
    for (int y = 0; y < tested.height; ++y)
        for (int x = 0; x < tested.width; ++x)
            full[static_cast<size_t>(y) * tested.width + x] = v.zMap[static_cast<size_t>(y / block) * blocksWide + x / block];
    v.zMap = std::move(full);
    return v;
}

namespace {

/// The comparison itself, over the units of an image (pixels, or squares of them).
RenderVerdict compareUnits(RenderImage const& a, RenderImage const& b, double varianceCap, char const* unit) {
    RenderVerdict v;
    size_t const pixels = static_cast<size_t>(a.width) * static_cast<size_t>(a.height);
    if (a.width != b.width || a.height != b.height || a.rgb.size() != 3 * pixels || b.rgb.size() != 3 * pixels ||
        a.variance.size() != 3 * pixels || b.variance.size() != 3 * pixels) {
        v.message = "the renders have different sizes";
        return v;
    }
    double const alpha = 1.0 - std::pow(1.0 - 0.01, 1.0 / static_cast<double>(pixels));  // Sidak over pixels
    v.zCritical = criticalZ(alpha);
    v.zMap.assign(pixels, 0.0f);
    std::vector<double> const referenceVariance = varianceWithNeighbourhoodFloor(b);
    size_t passing = 0;
    double sumDiff[3] = {0, 0, 0}, sumVariance[3] = {0, 0, 0}, sumA = 0, sumB = 0;
    for (size_t p = 0; p < pixels; ++p) {
        bool pass = true;
        double worst = 0.0;
        for (int c = 0; c < 3; ++c) {
            size_t i = 3 * p + static_cast<size_t>(c);
            double va = std::isfinite(a.variance[i]) ? std::max(0.0f, a.variance[i]) : 0.0;
            double vb = referenceVariance[i];
            va = std::min(va, varianceCap * vb + 1e-12);
            double d = std::isfinite(a.rgb[i]) ? static_cast<double>(a.rgb[i]) - b.rgb[i] : 1e30;
            sumDiff[c] += d;
            sumVariance[c] += va + vb;
            double sigma = std::sqrt(va + vb);
            // Noise-free pixels must agree to float precision; noisy ones within zCritical sigmas.
            double z = sigma > 0.0 ? d / sigma : (std::fabs(d) <= 1e-4 * (std::fabs(b.rgb[i]) + 1e-3) ? 0.0 : (d > 0 ? 1e9 : -1e9));
            pass = pass && std::fabs(z) <= v.zCritical;
            if (std::fabs(z) > std::fabs(worst)) worst = z;
            sumA += std::isfinite(a.rgb[i]) ? a.rgb[i] : 0.0;
            sumB += b.rgb[i];
        }
        v.zMap[p] = static_cast<float>(std::max(-50.0, std::min(50.0, worst)));
        passing += pass;
    }
    std::vector<float> finiteA(a.rgb);
    for (float& x : finiteA)
        if (!std::isfinite(x)) x = 0.0f;
    v.relMse = relativeMse(finiteA, b.rgb);
    v.passFraction = static_cast<double>(passing) / static_cast<double>(pixels);
    v.meanTested = sumA / static_cast<double>(3 * pixels);
    v.meanReference = sumB / static_cast<double>(3 * pixels);
    for (int c = 0; c < 3; ++c) {
        double sigma = std::sqrt(sumVariance[c]);
        double z = sigma > 0 ? sumDiff[c] / sigma : (std::fabs(sumDiff[c]) > 1e-6 * static_cast<double>(pixels) ? 1e9 : 0.0);
        if (std::fabs(z) > std::fabs(v.meanZ)) v.meanZ = z;
    }
    v.pixelsAgree = v.passFraction >= 0.9975;
    v.meansAgree = std::fabs(v.meanZ) <= criticalZ(0.01 / 3.0);
    char text[512];
    if (!v.pixelsAgree) {
        std::snprintf(text, sizeof text,
                      "%.2f%% of the %ss differ from the solution's by more than the noise allows (at most 0.25%% may); "
                      "image means %.4g (yours) and %.4g; relMSE %.3g",
                      100.0 * (1.0 - v.passFraction), unit, v.meanTested, v.meanReference, v.relMse);
    } else if (!v.meansAgree) {
        double percent = v.meanReference != 0 ? 100.0 * (v.meanTested - v.meanReference) / v.meanReference : 0.0;
        std::snprintf(text, sizeof text,
                      "your image is %.2f%% %s than the solution's on average (means %.5g and %.5g, z = %.1f): a bias "
                      "too spread out for single %ss to show; every %s is within its noise; relMSE %.3g",
                      std::fabs(percent), v.meanTested > v.meanReference ? "brighter" : "darker", v.meanTested,
                      v.meanReference, std::min(std::fabs(v.meanZ), 1e6), unit, unit, v.relMse);
    } else {
        std::snprintf(text, sizeof text,
                      "%.2f%% of the %ss agree with the solution's within their noise (99.75%% needed), and the "
                      "image means agree (%.5g and %.5g, z = %.1f); relMSE %.3g",
                      100.0 * v.passFraction, unit, v.meanTested, v.meanReference, v.meanZ, v.relMse);
    }
    v.message = text;
    return v;
}

}  // namespace

NoiseVerdict compareNoise(RenderImage const& tested, RenderImage const& reference, double limit, bool bothWays) {
    NoiseVerdict v;
    // The sum of the per-pixel variances without each image's largest 1%: a
    // few pixels whose handful of samples caught a rare bright path would
    // otherwise decide the ratio (two renders by the same estimator then
    // differ by up to a third; trimmed, by a few percent).
    auto trimmedSum = [](std::vector<float> const& variance) {
        std::vector<double> values;
        values.reserve(variance.size());
        for (float x : variance) values.push_back(std::isfinite(x) ? std::max(0.0, static_cast<double>(x)) : 1e30);
        size_t keep = values.size() - values.size() / 100;
        std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(keep), values.end());
        double sum = 0.0;
        for (size_t i = 0; i < keep; ++i) sum += values[i];
        return sum;
    };
    double const mine = trimmedSum(tested.variance), theirs = trimmedSum(reference.variance);
    v.ratio = theirs > 0.0 ? mine / theirs : (mine > 0.0 ? 1e30 : 1.0);
    bool const tooNoisy = v.ratio > limit, tooSmooth = bothWays && v.ratio < 1.0 / limit;
    v.passed = !tooNoisy && !tooSmooth;
    char allowed[64];
    if (bothWays)
        std::snprintf(allowed, sizeof allowed, "between %.3g and %.3g", 1.0 / limit, limit);
    else
        std::snprintf(allowed, sizeof allowed, "at most %.3g", limit);
    char const* why = tooNoisy ? ": the estimate is right on average but converges slower; is a sampling strategy "
                                 "or a MIS weight missing?"
                      : tooSmooth ? ": the scene's parameters fix the sampling, so a right integrator is as noisy as "
                                    "the solution, and a smoother image takes samples the scene does not ask for; "
                                    "does the integrator read its sample counts (numLightSamples, numBxdfSamples)?"
                                  : "";
    char text[512];
    std::snprintf(text, sizeof text,
                  "your image's variance is %.3g times the solution's at the same samples per pixel (%s allowed)%s",
                  std::min(v.ratio, 1e6), allowed, why);
    v.message = text;
    return v;
}

}  // namespace bxdflab
