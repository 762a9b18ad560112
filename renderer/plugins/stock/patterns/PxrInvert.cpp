// PxrInvert — inverts chosen channels of a colour in a colour model: colorModel 0 is RGB, 1 HSL, 2 HSV
// (ColorModels.h). The RGB input is taken into the model, each channel whose invertChannel0/1/2 is on is
// inverted there, and the colour is brought back to RGB, kept within black and white. A channel v
// becomes 1 - v; a hue turns half way round (to its complement), since 1 - hue would leave red red.
#include <algorithm>

#include "ColorModels.h"
#include "PatternHelpers.h"

namespace {

class PxrInvert : public stockpatterns::StockPattern {
public:
    enum { k_inputRGB, k_colorModel, k_invertChannel0, k_invertChannel1, k_invertChannel2, k_resultRGB, k_resultR,
           k_resultG, k_resultB };
    enum Model { RGB, HSL, HSV };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("inputRGB"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("colorModel"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("invertChannel0"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("invertChannel1"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("invertChannel2"), k_RixSCInteger),
                                         STOCK_PATTERN_COLOR_OUTPUTS,
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtColorRGB const black(0.0f);
        RtInt const rgb = RGB, on = 1;
        RtColorRGB const* input;
        RtInt const *colorModel, *invert[3];
        sCtx->EvalParam(k_inputRGB, -1, &input, &black, true);
        sCtx->EvalParam(k_colorModel, -1, &colorModel, &rgb);
        for (int c = 0; c < 3; ++c) sCtx->EvalParam(k_invertChannel0 + c, -1, &invert[c], &on);
        Model model = static_cast<Model>(*colorModel);
        if (*colorModel < RGB || *colorModel > HSV) {
            if (auto* messages = static_cast<RixMessages*>(sCtx->GetRixInterface(k_RixMessages)))
                messages->Warning("PxrInvert: colorModel %d is not one of 0 (RGB), 1 (HSL), 2 (HSV); RGB is used",
                                  *colorModel);
            model = RGB;
        }

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(4);
        int count = 0;
        stockpatterns::ColorOutputs result(sCtx, out, count, k_resultRGB);
        for (int i = 0; i < sCtx->numPts; ++i) {
            RtColorRGB x = input[i];
            if (model == RGB) {
                for (int c = 0; c < 3; ++c)
                    if (*invert[c]) x[c] = 1.0f - x[c];
            } else {
                stockpatterns::HueColor h = model == HSL ? stockpatterns::rgbToHsl(x) : stockpatterns::rgbToHsv(x);
                if (*invert[0]) h.hue += 0.5f;
                if (*invert[1]) h.saturation = 1.0f - h.saturation;
                if (*invert[2]) h.third = 1.0f - h.third;
                x = model == HSL ? stockpatterns::hslToRgb(h) : stockpatterns::hsvToRgb(h);
            }
            for (int c = 0; c < 3; ++c) x[c] = std::clamp(x[c], 0.0f, 1.0f);
            result.set(i, x);
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrInvert)
