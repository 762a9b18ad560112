// PxrHSL — adjusts a colour in hue, saturation and lightness (ColorModels.h): the hue turns by `hue`
// (in turns: 0.5 gives the complementary colour), saturation and lightness are multiplied by
// `saturation` and `luminance`; the result is RGB again. Saturation stays within 0 to 1.
#include <algorithm>

#include "ColorModels.h"
#include "PatternHelpers.h"

namespace {

class PxrHSL : public stockpatterns::StockPattern {
public:
    enum { k_inputRGB, k_hue, k_saturation, k_luminance, k_resultRGB, k_resultR, k_resultG, k_resultB };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("inputRGB"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("hue"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("saturation"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("luminance"), k_RixSCFloat),
                                         STOCK_PATTERN_COLOR_OUTPUTS,
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtColorRGB const black(0.0f);
        RtFloat const none = 0.0f, one = 1.0f;
        RtColorRGB const* input;
        RtFloat const *hue, *saturation, *luminance;
        sCtx->EvalParam(k_inputRGB, -1, &input, &black, true);
        sCtx->EvalParam(k_hue, -1, &hue, &none, true);
        sCtx->EvalParam(k_saturation, -1, &saturation, &one, true);
        sCtx->EvalParam(k_luminance, -1, &luminance, &one, true);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(4);
        int count = 0;
        stockpatterns::ColorOutputs result(sCtx, out, count, k_resultRGB);
        for (int i = 0; i < sCtx->numPts; ++i) {
            stockpatterns::HueColor hsl = stockpatterns::rgbToHsl(input[i]);
            hsl.hue += hue[i];
            hsl.saturation = std::clamp(hsl.saturation * saturation[i], 0.0f, 1.0f);
            hsl.third *= luminance[i];
            result.set(i, stockpatterns::hslToRgb(hsl));
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrHSL)
