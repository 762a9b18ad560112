// PxrFractal — fractal noise: `layers` octaves of gradient noise, each at
// `lacunarity` times the frequency of the one before and lacunarity^-dimension
// times its amplitude (dimension 1 and lacunarity 2 halve it), starting at
// `frequency`. With `turbulent` each octave counts by its absolute value (sharp
// creases instead of rolling hills). resultF lies in [0, 1] around 0.5
// (turbulent: from 0 up); resultRGB holds three independent such noises, e.g.
// for PxrNormalMap's inputRGB to make a surface uneven:
//   Pattern "PxrFractal" "uneven" "float frequency" [0.8] "int layers" [2]
//   Pattern "PxrNormalMap" "bumps" "reference color inputRGB" ["uneven:resultRGB"] "float bumpScale" [0.1]
// It is evaluated at (s, t) of the manifold (texture coordinates unless one is
// connected), or with surfacePosition 1 at the point's position in object space;
// `variation` moves through the noise along a third (a fourth) axis, giving
// another pattern of the same kind. This noise is this renderer's own: the
// pattern is RenderMan's in kind, not value for value. erosion is not modelled.
#include <cmath>
#include <cstdint>

#include "NoiseLattice.h"

namespace {

/// The dot product of the lattice point's pseudo-random gradient (one of the 12 edge directions of a cube)
/// with the offset from it.
float gradientDot(uint32_t h, float x, float y, float z) {
    switch (h % 12u) {
        case 0: return x + y;
        case 1: return -x + y;
        case 2: return x - y;
        case 3: return -x - y;
        case 4: return x + z;
        case 5: return -x + z;
        case 6: return x - z;
        case 7: return -x - z;
        case 8: return y + z;
        case 9: return -y + z;
        case 10: return y - z;
        default: return -y - z;
    }
}

float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }
float lerp(float a, float b, float t) { return a + (b - a) * t; }

/// Gradient noise in about [-1, 1], zero on the integer lattice.
float gradientNoise(float x, float y, float z) {
    float const fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    int const ix = static_cast<int>(fx), iy = static_cast<int>(fy), iz = static_cast<int>(fz);
    float const dx = x - fx, dy = y - fy, dz = z - fz;
    float corner[8];
    for (int c = 0; c < 8; ++c) {
        int const ox = c & 1, oy = (c >> 1) & 1, oz = (c >> 2) & 1;
        corner[c] = gradientDot(stockpatterns::latticeHash(ix + ox, iy + oy, iz + oz), dx - static_cast<float>(ox),
                                dy - static_cast<float>(oy), dz - static_cast<float>(oz));
    }
    float const u = fade(dx), v = fade(dy), w = fade(dz);
    float const x00 = lerp(corner[0], corner[1], u), x10 = lerp(corner[2], corner[3], u);
    float const x01 = lerp(corner[4], corner[5], u), x11 = lerp(corner[6], corner[7], u);
    return lerp(lerp(x00, x10, v), lerp(x01, x11, v), w);
}

struct Octaves {
    int layers;
    float frequency, lacunarity, dimension;
    bool turbulent;

    /// The fractal at p, in [0, 1].
    float at(RtPoint3 const& p) const {
        float const value = stockpatterns::octaveAverage(
            p, layers, frequency, lacunarity, std::pow(lacunarity, -dimension), 0.0f, [this](RtPoint3 const& q) {
                float const n = gradientNoise(q.x, q.y, q.z);
                return turbulent ? std::fabs(n) : n;
            });
        return std::fmin(1.0f, std::fmax(0.0f, turbulent ? value : 0.5f + 0.5f * value));
    }
};

class PxrFractal : public stockpatterns::StockPattern {
public:
    enum { k_surfacePosition, k_layers, k_frequency, k_lacunarity, k_dimension, k_erosion, k_variation, k_turbulent,
           k_manifold, k_resultF, k_resultRGB };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("surfacePosition"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("layers"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("frequency"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("lacunarity"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("dimension"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("erosion"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("variation"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("turbulent"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("manifold"), k_RixSCPoint),
                                         RixSCParamInfo(RtUString("resultF"), k_RixSCFloat, k_RixSCOutput),
                                         RixSCParamInfo(RtUString("resultRGB"), k_RixSCColor, k_RixSCOutput),
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtInt const zero = 0, six = 6;
        RtFloat const one = 1.0f, two = 2.0f, none = 0.0f;
        RtInt const *surfacePosition, *layers, *turbulent;
        RtFloat const *frequency, *lacunarity, *dimension, *erosion, *variation;
        sCtx->EvalParam(k_surfacePosition, -1, &surfacePosition, &zero);
        sCtx->EvalParam(k_layers, -1, &layers, &six);
        sCtx->EvalParam(k_turbulent, -1, &turbulent, &zero);
        sCtx->EvalParam(k_frequency, -1, &frequency, &one, true);
        sCtx->EvalParam(k_lacunarity, -1, &lacunarity, &two, true);
        sCtx->EvalParam(k_dimension, -1, &dimension, &one, true);
        sCtx->EvalParam(k_erosion, -1, &erosion, &none);
        sCtx->EvalParam(k_variation, -1, &variation, &none, true);
        if (*erosion != 0.0f)
            if (auto* messages = static_cast<RixMessages*>(sCtx->GetRixInterface(k_RixMessages)))
                messages->Warning("PxrFractal: erosion is not modelled; the noise is as with erosion 0");
        int const octaves = *layers < 0 ? 0 : *layers > 16 ? 16 : *layers;  // finer than 2^16 is below any pixel
        RtPoint3 const* where = stockpatterns::noisePositions(sCtx, *surfacePosition, k_manifold);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(2);
        int count = 0;
        RtFloat* resultF = stockpatterns::addVaryingOutput<RtFloat>(sCtx, out, count, k_resultF);
        RtColorRGB* resultRGB = stockpatterns::addVaryingOutput<RtColorRGB>(sCtx, out, count, k_resultRGB);
        for (int i = 0; i < sCtx->numPts; ++i) {
            Octaves const fractal{octaves, frequency[i], lacunarity[i], dimension[i], *turbulent != 0};
            // variation moves along an axis of its own; the three colour channels are far-apart copies.
            RtPoint3 p = where[i];
            p.z += 7.31f * variation[i];
            resultF[i] = fractal.at(p);
            resultRGB[i] = RtColorRGB(resultF[i], fractal.at(RtPoint3(p.x + 113.5f, p.y - 71.25f, p.z + 39.75f)),
                                      fractal.at(RtPoint3(p.x - 57.125f, p.y + 201.5f, p.z - 97.375f)));
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrFractal)
