// PxrVoronoise — Inigo Quilez's "voronoise", which runs from a grid of cell values to Voronoi cells to noise
// with two knobs, in fractal octaves. Every unit cell (a square of (s, t), or with surfacePosition 1 a cube of
// object space) holds a random value and a point `jitter` (0 to 1) of the way from its corner to a random
// place in it; the pattern at p is the average of the values of the cells around p, each weighted by
// (1 - smoothstep(0, reach, distance to its point))^k (reach: the cell's diagonal, sqrt 2 or sqrt 3), with
// k = 1 + 63 (1 - smoothness)^4. smoothness 0 keeps only the nearest point (a grid of flat values, or Voronoi
// cells with jitter); smoothness 1 blends them into a smooth noise. `octaves` of it at `frequency` times
// lacunarity^n, each `gain` times the one before, are summed and normalised to 0 to 1; with `turbulent`
// each octave counts as |2 v - 1| (creases at its middle value). (s, t) are the manifold's, the texture
// coordinates unless one is connected. resultRGB holds three independent such patterns. The cells are this
// renderer's own: RenderMan's pattern in kind, not value for value.
#include <algorithm>
#include <cmath>

#include "NoiseLattice.h"

namespace {

float smoothstep(float edge0, float edge1, float x) {
    float const t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

/// One octave: the weighted average of the cell values around p, in [0, 1]; `flat`, of the squares of the plane.
float voronoise(RtPoint3 const& p, bool flat, float jitter, float sharpness) {
    float const cx = std::floor(p.x), cy = std::floor(p.y), cz = std::floor(p.z);
    float const reach = std::sqrt(flat ? 2.0f : 3.0f);  // beyond it a point weighs nothing
    float sum = 0.0f, weights = 0.0f;
    int const layers = flat ? 0 : 2;
    for (int dz = -layers; dz <= layers; ++dz)
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
                int const x = static_cast<int>(cx) + dx, y = static_cast<int>(cy) + dy, z = static_cast<int>(cz) + dz;
                uint32_t h = stockpatterns::latticeHash(x, y, z);
                float const value = stockpatterns::unitOf(h);
                h = stockpatterns::nextHash(h);
                float const ox = jitter * stockpatterns::unitOf(h);
                h = stockpatterns::nextHash(h);
                float const oy = jitter * stockpatterns::unitOf(h);
                h = stockpatterns::nextHash(h);
                float const oz = jitter * stockpatterns::unitOf(h);
                float const rx = static_cast<float>(x) + ox - p.x, ry = static_cast<float>(y) + oy - p.y,
                            rz = flat ? 0.0f : static_cast<float>(z) + oz - p.z;
                float const d = std::sqrt(rx * rx + ry * ry + rz * rz);
                if (d >= reach) continue;
                float const w = std::pow(1.0f - smoothstep(0.0f, reach, d), sharpness);
                sum += w * value;
                weights += w;
            }
    return weights > 0.0f ? sum / weights : 0.5f;
}

struct Octaves {
    int count;
    float frequency, gain, lacunarity, jitter, sharpness;
    bool turbulent, flat;

    float at(RtPoint3 const& p) const {
        return std::clamp(stockpatterns::octaveAverage(p, count, frequency, lacunarity, gain, 0.5f,
                                                       [this](RtPoint3 const& q) {
                                                           float const v = voronoise(q, flat, jitter, sharpness);
                                                           return turbulent ? std::fabs(2.0f * v - 1.0f) : v;
                                                       }),
                          0.0f, 1.0f);
    }
};

class PxrVoronoise : public stockpatterns::StockPattern {
public:
    enum { k_surfacePosition, k_frequency, k_octaves, k_gain, k_lacunarity, k_jitter, k_smoothness, k_turbulent,
           k_manifold, k_resultF, k_resultRGB };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("surfacePosition"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("frequency"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("octaves"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("gain"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("lacunarity"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("jitter"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("smoothness"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("turbulent"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("manifold"), k_RixSCPoint),
                                         RixSCParamInfo(RtUString("resultF"), k_RixSCFloat, k_RixSCOutput),
                                         RixSCParamInfo(RtUString("resultRGB"), k_RixSCColor, k_RixSCOutput),
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtInt const zero = 0, three = 3;
        RtFloat const one = 1.0f, half = 0.5f, two = 2.0f, none = 0.0f;
        RtInt const *surfacePosition, *octaves, *turbulent;
        RtFloat const *frequency, *gain, *lacunarity, *jitter, *smoothness;
        sCtx->EvalParam(k_surfacePosition, -1, &surfacePosition, &zero);
        sCtx->EvalParam(k_frequency, -1, &frequency, &one, true);
        sCtx->EvalParam(k_octaves, -1, &octaves, &three);
        sCtx->EvalParam(k_gain, -1, &gain, &half, true);
        sCtx->EvalParam(k_lacunarity, -1, &lacunarity, &two, true);
        sCtx->EvalParam(k_jitter, -1, &jitter, &none, true);
        sCtx->EvalParam(k_smoothness, -1, &smoothness, &one, true);
        sCtx->EvalParam(k_turbulent, -1, &turbulent, &zero);
        int const layers = std::clamp(*octaves, 0, 16);  // finer than 2^16 is below any pixel
        RtPoint3 const* where = stockpatterns::noisePositions(sCtx, *surfacePosition, k_manifold);
        bool const colourRead = stockpatterns::isOutputRead(sCtx, k_resultRGB);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(2);
        int count = 0;
        RtFloat* resultF = stockpatterns::addVaryingOutput<RtFloat>(sCtx, out, count, k_resultF);
        RtColorRGB* resultRGB = stockpatterns::addVaryingOutput<RtColorRGB>(sCtx, out, count, k_resultRGB);
        for (int i = 0; i < sCtx->numPts; ++i) {
            float const rough = 1.0f - std::clamp(smoothness[i], 0.0f, 1.0f);
            Octaves const pattern{layers,
                                  frequency[i],
                                  gain[i],
                                  lacunarity[i],
                                  std::clamp(jitter[i], 0.0f, 1.0f),
                                  1.0f + 63.0f * rough * rough * rough * rough,
                                  *turbulent != 0,
                                  *surfacePosition != 1};
            RtPoint3 const& p = where[i];
            resultF[i] = pattern.at(p);
            // The colour's other two channels are far-apart copies, worked out only when something reads them.
            resultRGB[i] = colourRead ? RtColorRGB(resultF[i], pattern.at(RtPoint3(p.x + 113.5f, p.y - 71.25f, p.z + 39.75f)),
                                                   pattern.at(RtPoint3(p.x - 57.125f, p.y + 201.5f, p.z - 97.375f)))
                                      : RtColorRGB(resultF[i]);
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrVoronoise)
