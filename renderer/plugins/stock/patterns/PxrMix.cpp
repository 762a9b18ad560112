// PxrMix — blends two colours: resultRGB = (1 - mix) * color1 + mix * color2,
// and each of its channels as resultR, resultG and resultB (a float, e.g. for
// a presence). Any of the three inputs may be connected, e.g. two textures
// mixed by a mask:
//
//   Pattern "PxrMix" "blend" "reference color color1" ["bark:resultRGB"]
//       "reference color color2" ["moss:resultRGB"] "reference float mix" ["mask:resultR"]
#include <algorithm>

#include "PatternHelpers.h"

namespace {

class PxrMix : public stockpatterns::StockPattern {
public:
    enum { k_color1, k_color2, k_mix, k_clampMix, k_resultRGB, k_resultR, k_resultG, k_resultB };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("color1"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("color2"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("mix"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("clampMix"), k_RixSCInteger),
                                         STOCK_PATTERN_COLOR_OUTPUTS,
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtColorRGB const black(0.0f), white(1.0f);
        RtFloat const half = 0.5f;
        RtInt const clampOn = 1;
        RtColorRGB const *color1, *color2;
        RtFloat const* mix;
        RtInt const* clampMix;
        // promoteToVarying: one value per point whether connected or not.
        sCtx->EvalParam(k_color1, -1, &color1, &black, true);
        sCtx->EvalParam(k_color2, -1, &color2, &white, true);
        sCtx->EvalParam(k_mix, -1, &mix, &half, true);
        sCtx->EvalParam(k_clampMix, -1, &clampMix, &clampOn);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(4);
        int count = 0;
        stockpatterns::ColorOutputs result(sCtx, out, count, k_resultRGB);
        for (int i = 0; i < sCtx->numPts; ++i) {
            float m = *clampMix ? std::clamp(mix[i], 0.0f, 1.0f) : mix[i];
            result.set(i, color1[i] * (1.0f - m) + color2[i] * m);
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrMix)
