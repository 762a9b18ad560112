// PxrRemap — maps a colour from one range to another, channel by channel:
//   x = (inputRGB - inputMin) / (inputMax - inputMin)   (kept in [0, 1] with clampInput, the default)
//   x = gain(bias(x))                                   (Perlin's bias and gain; 0.5 leaves x alone)
//   result = outputMin + x * (outputMax - outputMin)    (kept in [0, 1] with clampOutput, the default)
// bias(x) = x^(log bias / log 0.5) pushes the middle up (bias > 0.5) or down;
// gain > 0.5 steepens the curve around 0.5 and flattens it near 0 and 1. Each
// channel has its own bias and gain. resultA, which RenderMan lists without saying what it
// holds, is the result's luminance here.
#include <algorithm>
#include <cmath>

#include "PatternHelpers.h"

namespace {

float perlinBias(float x, float b) {
    if (x <= 0.0f) return 0.0f;
    b = std::clamp(b, 1e-4f, 1.0f - 1e-4f);
    return std::pow(x, std::log(b) / std::log(0.5f));
}

float perlinGain(float x, float g) {
    return x < 0.5f ? 0.5f * perlinBias(2.0f * x, 1.0f - g) : 1.0f - 0.5f * perlinBias(2.0f - 2.0f * x, 1.0f - g);
}

class PxrRemap : public stockpatterns::StockPattern {
public:
    enum { k_inputRGB, k_inputMin, k_inputMax, k_clampInput, k_bias, k_gain, k_outputMin, k_outputMax, k_clampOutput,
           k_resultRGB, k_resultR, k_resultG, k_resultB, k_resultA };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("inputRGB"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("inputMin"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("inputMax"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("clampInput"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("bias"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("gain"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("outputMin"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("outputMax"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("clampOutput"), k_RixSCInteger),
                                         STOCK_PATTERN_COLOR_OUTPUTS,
                                         RixSCParamInfo(RtUString("resultA"), k_RixSCFloat, k_RixSCOutput),
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtColorRGB const black(0.0f), half(0.5f);
        RtFloat const zero = 0.0f, one = 1.0f;
        RtInt const on = 1;
        RtColorRGB const *input, *bias, *gain;
        RtFloat const *inMin, *inMax, *outMin, *outMax;
        RtInt const *clampInput, *clampOutput;
        sCtx->EvalParam(k_inputRGB, -1, &input, &black, true);
        sCtx->EvalParam(k_inputMin, -1, &inMin, &zero, true);
        sCtx->EvalParam(k_inputMax, -1, &inMax, &one, true);
        sCtx->EvalParam(k_bias, -1, &bias, &half, true);
        sCtx->EvalParam(k_gain, -1, &gain, &half, true);
        sCtx->EvalParam(k_outputMin, -1, &outMin, &zero, true);
        sCtx->EvalParam(k_outputMax, -1, &outMax, &one, true);
        sCtx->EvalParam(k_clampInput, -1, &clampInput, &on);
        sCtx->EvalParam(k_clampOutput, -1, &clampOutput, &on);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(5);
        int count = 0;
        stockpatterns::ColorOutputs result(sCtx, out, count, k_resultRGB);
        RtFloat* alpha = stockpatterns::addVaryingOutput<RtFloat>(sCtx, out, count, k_resultA);
        for (int i = 0; i < sCtx->numPts; ++i) {
            float const span = inMax[i] - inMin[i];
            auto remap = [&](float value, float b, float g) {
                float x = span != 0.0f ? (value - inMin[i]) / span : (value >= inMax[i] ? 1.0f : 0.0f);
                if (*clampInput) x = std::clamp(x, 0.0f, 1.0f);
                if (x >= 0.0f && x <= 1.0f) x = perlinGain(perlinBias(x, b), g);  // both are defined on [0, 1]
                float y = outMin[i] + x * (outMax[i] - outMin[i]);
                return *clampOutput ? std::clamp(y, 0.0f, 1.0f) : y;
            };
            RtColorRGB const c(remap(input[i].r, bias[i].r, gain[i].r), remap(input[i].g, bias[i].g, gain[i].g),
                               remap(input[i].b, bias[i].b, gain[i].b));
            result.set(i, c);
            alpha[i] = c.Luminance();
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrRemap)
