// PxrWorley — Worley's cellular noise: every unit cell (a square of (s, t) scaled by `frequency`, or with
// surfacePosition 1 a cube of object space) holds one feature point, `jitter` (0 to 1) of the way from the cell's centre
// to a random place in it. F1 and F2 are the distances to the nearest and second-nearest feature points, and
//   resultF = c1 * F1 + c2 * F2      (kept within 0 and 1 with `clamp`, the default; 1 - that with `invert`)
// The defaults, 0.8 F1 - 0.2 F2, give rounded cells with dark centres and bright borders. `distancemetric`
// measures distance as 0 Euclidean, 1 Manhattan (|dx| + |dy| + |dz|), 2 Chebyshev (the largest |d|) or
// 3 Minkowski (with `minkowskiExponent`). resultRGB is resultF in every channel. The cells are this
// renderer's own: the pattern is RenderMan's in kind, not value for value; `shape` and the random
// scaling (randomScale) are not modelled and are warned about when set.
#include <algorithm>
#include <cmath>

#include "NoiseLattice.h"

namespace {

enum class Metric { Euclidean, Manhattan, Chebyshev, Minkowski };

float distanceOf(Metric metric, float dx, float dy, float dz, float exponent) {
    dx = std::fabs(dx), dy = std::fabs(dy), dz = std::fabs(dz);
    switch (metric) {
        case Metric::Manhattan: return dx + dy + dz;
        case Metric::Chebyshev: return std::max({dx, dy, dz});
        case Metric::Minkowski:
            return std::pow(std::pow(dx, exponent) + std::pow(dy, exponent) + std::pow(dz, exponent), 1.0f / exponent);
        default: return std::sqrt(dx * dx + dy * dy + dz * dz);
    }
}

/// F1 and F2 at p: the distances to the two nearest feature points of the cells around p's cell; `flat`, in
/// the plane (cells of (s, t), whose points lie in the plane too).
void nearestTwo(RtPoint3 const& p, bool flat, float jitter, Metric metric, float exponent, float& f1, float& f2) {
    float const cx = std::floor(p.x), cy = std::floor(p.y), cz = std::floor(p.z);
    f1 = f2 = 1e30f;
    int const layers = flat ? 0 : 1;
    for (int dz = -layers; dz <= layers; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                int const x = static_cast<int>(cx) + dx, y = static_cast<int>(cy) + dy, z = static_cast<int>(cz) + dz;
                uint32_t h = stockpatterns::latticeHash(x, y, z);
                float const rx = stockpatterns::unitOf(h);
                h = stockpatterns::nextHash(h);
                float const ry = stockpatterns::unitOf(h);
                h = stockpatterns::nextHash(h);
                float const rz = stockpatterns::unitOf(h);
                float const fx = static_cast<float>(x) + 0.5f + jitter * (rx - 0.5f);
                float const fy = static_cast<float>(y) + 0.5f + jitter * (ry - 0.5f);
                float const fz = flat ? p.z : static_cast<float>(z) + 0.5f + jitter * (rz - 0.5f);
                float const d = distanceOf(metric, fx - p.x, fy - p.y, fz - p.z, exponent);
                if (d < f1) {
                    f2 = f1;
                    f1 = d;
                } else if (d < f2) {
                    f2 = d;
                }
            }
}

class PxrWorley : public stockpatterns::StockPattern {
public:
    enum { k_surfacePosition, k_frequency, k_distancemetric, k_jitter, k_c1, k_c2, k_minkowskiExponent, k_shape,
           k_clamp, k_invert, k_randomScale, k_randomScaleCenter, k_manifold, k_resultF, k_resultRGB };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("surfacePosition"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("frequency"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("distancemetric"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("jitter"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("c1"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("c2"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("minkowskiExponent"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("shape"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("clamp"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("invert"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("randomScale"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("randomScaleCenter"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("manifold"), k_RixSCPoint),
                                         RixSCParamInfo(RtUString("resultF"), k_RixSCFloat, k_RixSCOutput),
                                         RixSCParamInfo(RtUString("resultRGB"), k_RixSCColor, k_RixSCOutput),
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtInt const zero = 0, one = 1;
        RtFloat const four = 4.0f, threeQuarters = 0.75f, c1Default = 0.8f, c2Default = -0.2f, none = 0.0f;
        RtInt const *surfacePosition, *metric, *shape, *clampResult, *invert;
        RtFloat const *frequency, *jitter, *c1, *c2, *exponent, *randomScale;
        sCtx->EvalParam(k_surfacePosition, -1, &surfacePosition, &zero);
        sCtx->EvalParam(k_frequency, -1, &frequency, &four, true);
        sCtx->EvalParam(k_distancemetric, -1, &metric, &zero);
        sCtx->EvalParam(k_jitter, -1, &jitter, &threeQuarters, true);
        sCtx->EvalParam(k_c1, -1, &c1, &c1Default, true);
        sCtx->EvalParam(k_c2, -1, &c2, &c2Default, true);
        sCtx->EvalParam(k_minkowskiExponent, -1, &exponent, &four, true);
        sCtx->EvalParam(k_shape, -1, &shape, &zero);
        sCtx->EvalParam(k_clamp, -1, &clampResult, &one);
        sCtx->EvalParam(k_invert, -1, &invert, &zero);
        sCtx->EvalParam(k_randomScale, -1, &randomScale, &none);
        warnAboutUnmodelled(sCtx, *metric, *shape, *randomScale);
        Metric const measure = *metric >= 0 && *metric <= 3 ? static_cast<Metric>(*metric) : Metric::Euclidean;
        RtPoint3 const* where = stockpatterns::noisePositions(sCtx, *surfacePosition, k_manifold);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(2);
        int count = 0;
        RtFloat* resultF = stockpatterns::addVaryingOutput<RtFloat>(sCtx, out, count, k_resultF);
        RtColorRGB* resultRGB = stockpatterns::addVaryingOutput<RtColorRGB>(sCtx, out, count, k_resultRGB);
        for (int i = 0; i < sCtx->numPts; ++i) {
            float f1, f2;
            nearestTwo(where[i] * frequency[i], *surfacePosition != 1, std::clamp(jitter[i], 0.0f, 1.0f), measure,
                       std::max(exponent[i], 0.1f), f1, f2);
            float value = c1[i] * f1 + c2[i] * f2;
            if (*clampResult) value = std::clamp(value, 0.0f, 1.0f);
            if (*invert) value = 1.0f - value;
            resultF[i] = value;
            resultRGB[i] = RtColorRGB(value);
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }

private:
    static void warnAboutUnmodelled(RixShadingContext const* sCtx, int metric, int shape, float randomScale) {
        auto* messages = static_cast<RixMessages*>(sCtx->GetRixInterface(k_RixMessages));
        if (!messages) return;
        if (metric < 0 || metric > 3)
            messages->Warning("PxrWorley: distancemetric %d is not one of 0 (Euclidean), 1 (Manhattan), 2 (Chebyshev), "
                              "3 (Minkowski); Euclidean is used",
                              metric);
        if (shape != 0) messages->Warning("PxrWorley: shape %d is not modelled; the cells are as with shape 0", shape);
        if (randomScale != 0.0f)
            messages->Warning("PxrWorley: randomScale is not modelled; every cell counts at its own size");
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrWorley)
