// PxrBlend — lays a top colour over a bottom one with one of Photoshop's blend
// modes (BlendModes.h; operation 19, Normal, is the default), the top's alpha
// saying how much of the blend shows:
//   result = (1 - topA) * bottom + topA * blend(bottom, top)
// where the bottom stands on black where its own alpha is below 1 (bottom =
// bottomRGB * bottomA), and resultA = topA + bottomA * (1 - topA). clampOutput
// (on by default) keeps each channel in [0, 1]. A decal from a texture:
//   Pattern "PxrBlend" "decal" "int operation" [19] "reference color topRGB" ["logo:resultRGB"]
//       "reference float topA" ["logo:resultA"] "color bottomRGB" [0.8 0.1 0.1]
// Dissolve (6) picks the top colour at a share topA of the points, by a hash of where they are.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "BlendModes.h"
#include "PatternHelpers.h"

namespace {

using stockpatterns::BlendMode;

/// A number in [0, 1) that depends only on the point's position (for Dissolve).
float hashOf(RtPoint3 const& p) {
    uint32_t h = 2166136261u;
    for (float c : {p.x, p.y, p.z}) {
        uint32_t bits;
        std::memcpy(&bits, &c, sizeof bits);
        h = (h ^ bits) * 16777619u;
        h ^= h >> 15;
    }
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

class PxrBlend : public stockpatterns::StockPattern {
public:
    enum { k_operation, k_topRGB, k_topA, k_bottomRGB, k_bottomA, k_clampOutput,
           k_resultRGB, k_resultR, k_resultG, k_resultB, k_resultA };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("operation"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("topRGB"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("topA"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("bottomRGB"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("bottomA"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("clampOutput"), k_RixSCInteger),
                                         STOCK_PATTERN_COLOR_OUTPUTS,
                                         RixSCParamInfo(RtUString("resultA"), k_RixSCFloat, k_RixSCOutput),
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtInt const normal = static_cast<RtInt>(BlendMode::Normal), clampOn = 1;
        RtColorRGB const black(0.0f);
        RtFloat const opaque = 1.0f;
        RtInt const *operation, *clampOutput;
        RtColorRGB const *top, *bottom;
        RtFloat const *topA, *bottomA;
        sCtx->EvalParam(k_operation, -1, &operation, &normal);
        sCtx->EvalParam(k_clampOutput, -1, &clampOutput, &clampOn);
        sCtx->EvalParam(k_topRGB, -1, &top, &black, true);
        sCtx->EvalParam(k_topA, -1, &topA, &opaque, true);
        sCtx->EvalParam(k_bottomRGB, -1, &bottom, &black, true);
        sCtx->EvalParam(k_bottomA, -1, &bottomA, &opaque, true);
        BlendMode mode = static_cast<BlendMode>(*operation);
        if (*operation < 0 || *operation >= static_cast<int>(BlendMode::Count)) {
            if (auto* messages = static_cast<RixMessages*>(sCtx->GetRixInterface(k_RixMessages)))
                messages->Warning("PxrBlend: operation %d is not one of the blend modes (0-26); Normal (19) is used",
                                  *operation);
            mode = BlendMode::Normal;
        }
        RtPoint3 const* P = nullptr;
        if (mode == BlendMode::Dissolve) sCtx->GetBuiltinVar(RixShadingContext::k_P, &P);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(5);
        int count = 0;
        stockpatterns::ColorOutputs result(sCtx, out, count, k_resultRGB);
        RtFloat* alpha = stockpatterns::addVaryingOutput<RtFloat>(sCtx, out, count, k_resultA);
        for (int i = 0; i < sCtx->numPts; ++i) {
            RtColorRGB const base = bottom[i] * bottomA[i];
            RtColorRGB c;
            if (mode == BlendMode::Dissolve)
                c = hashOf(P[i]) < topA[i] ? top[i] : base;
            else
                c = base * (1.0f - topA[i]) + stockpatterns::blendColors(mode, base, top[i]) * topA[i];
            float a = topA[i] + bottomA[i] * (1.0f - topA[i]);
            if (*clampOutput) {
                c = RtColorRGB(std::clamp(c.r, 0.0f, 1.0f), std::clamp(c.g, 0.0f, 1.0f), std::clamp(c.b, 0.0f, 1.0f));
                a = std::clamp(a, 0.0f, 1.0f);
            }
            result.set(i, c);
            alpha[i] = a;
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrBlend)
