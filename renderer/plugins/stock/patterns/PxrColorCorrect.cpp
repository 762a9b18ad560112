// PxrColorCorrect — the classic colour corrections in one node, applied to inputRGB in the order of its
// parameters, channel by channel where the parameter is a triple:
//   x = (inputRGB - inputMin) / (inputMax - inputMin)        levels in (0 and 1 change nothing)
//   x = x^gamma                                              (ColorModels.h; 1 changes nothing)
//   x = pivot + (x - pivot) * k                              contrast c in [-1, 1]: k = 1 + c below 0,
//                                                            1 / (1 - c) above (0 changes nothing)
//   x = x * rgbGain
//   hsv: hue shifted by hsv[0] turns, saturation and value scaled by hsv[1] and hsv[2]
//   x = x * 2^exposure
//   x = outputMin + x * (outputMax - outputMin)              levels out
//   x = clamp(x, clampMin, clampMax)                         only with clampOutput
// and the result is mixed with the input by the mask: inputMask (1 - inputMask with invertMask) times mixMask.
// Exporters use it to tint a texture (rgbGain) or to turn a display-encoded one linear (gamma 2.2).
#include <algorithm>
#include <cmath>

#include "ColorModels.h"
#include "PatternHelpers.h"

namespace {

class PxrColorCorrect : public stockpatterns::StockPattern {
public:
    enum { k_inputRGB, k_inputMask, k_invertMask, k_mixMask, k_inputMin, k_inputMax, k_gamma, k_contrast,
           k_contrastPivot, k_rgbGain, k_hsv, k_exposure, k_outputMin, k_outputMax, k_clampOutput, k_clampMin,
           k_clampMax, k_resultRGB, k_resultR, k_resultG, k_resultB };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("inputRGB"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("inputMask"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("invertMask"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("mixMask"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("inputMin"), k_RixSCVector),
                                         RixSCParamInfo(RtUString("inputMax"), k_RixSCVector),
                                         RixSCParamInfo(RtUString("gamma"), k_RixSCVector),
                                         RixSCParamInfo(RtUString("contrast"), k_RixSCVector),
                                         RixSCParamInfo(RtUString("contrastPivot"), k_RixSCVector),
                                         RixSCParamInfo(RtUString("rgbGain"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("hsv"), k_RixSCVector),
                                         RixSCParamInfo(RtUString("exposure"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("outputMin"), k_RixSCVector),
                                         RixSCParamInfo(RtUString("outputMax"), k_RixSCVector),
                                         RixSCParamInfo(RtUString("clampOutput"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("clampMin"), k_RixSCVector),
                                         RixSCParamInfo(RtUString("clampMax"), k_RixSCVector),
                                         STOCK_PATTERN_COLOR_OUTPUTS,
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtColorRGB const black(0.0f), white(1.0f);
        RtVector3 const zeros(0.0f), ones(1.0f), halves(0.5f), neutralHsv(0.0f, 1.0f, 1.0f);
        RtFloat const one = 1.0f, none = 0.0f;
        RtInt const off = 0;
        RtColorRGB const *input, *rgbGain;
        RtFloat const *inputMask, *mixMask, *exposure;
        RtInt const *invertMask, *clampOutput;
        RtVector3 const *inputMin, *inputMax, *gamma, *contrast, *pivot, *hsv, *outputMin, *outputMax, *clampMin,
            *clampMax;
        sCtx->EvalParam(k_inputRGB, -1, &input, &black, true);
        sCtx->EvalParam(k_inputMask, -1, &inputMask, &one, true);
        sCtx->EvalParam(k_invertMask, -1, &invertMask, &off);
        sCtx->EvalParam(k_mixMask, -1, &mixMask, &one, true);
        sCtx->EvalParam(k_inputMin, -1, &inputMin, &zeros, true);
        sCtx->EvalParam(k_inputMax, -1, &inputMax, &ones, true);
        sCtx->EvalParam(k_gamma, -1, &gamma, &ones, true);
        sCtx->EvalParam(k_contrast, -1, &contrast, &zeros, true);
        sCtx->EvalParam(k_contrastPivot, -1, &pivot, &halves, true);
        sCtx->EvalParam(k_rgbGain, -1, &rgbGain, &white, true);
        sCtx->EvalParam(k_hsv, -1, &hsv, &neutralHsv, true);
        sCtx->EvalParam(k_exposure, -1, &exposure, &none, true);
        sCtx->EvalParam(k_outputMin, -1, &outputMin, &zeros, true);
        sCtx->EvalParam(k_outputMax, -1, &outputMax, &ones, true);
        sCtx->EvalParam(k_clampOutput, -1, &clampOutput, &off);
        sCtx->EvalParam(k_clampMin, -1, &clampMin, &zeros, true);
        sCtx->EvalParam(k_clampMax, -1, &clampMax, &ones, true);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(4);
        int count = 0;
        stockpatterns::ColorOutputs result(sCtx, out, count, k_resultRGB);
        for (int i = 0; i < sCtx->numPts; ++i) {
            RtColorRGB x = input[i];
            for (int c = 0; c < 3; ++c) {
                float const range = inputMax[i][c] - inputMin[i][c];
                float v = range != 0.0f ? (x[c] - inputMin[i][c]) / range : 0.0f;
                v = stockpatterns::applyGamma(v, gamma[i][c]);
                x[c] = pivot[i][c] + (v - pivot[i][c]) * contrastSlope(contrast[i][c]);
            }
            x *= rgbGain[i];
            if (hsv[i].x != 0.0f || hsv[i].y != 1.0f || hsv[i].z != 1.0f) {
                stockpatterns::HueColor h = stockpatterns::rgbToHsv(x);
                h.hue += hsv[i].x;
                h.saturation = std::clamp(h.saturation * hsv[i].y, 0.0f, 1.0f);
                h.third *= hsv[i].z;
                x = stockpatterns::hsvToRgb(h);
            }
            x *= std::exp2(exposure[i]);
            for (int c = 0; c < 3; ++c) {
                x[c] = outputMin[i][c] + x[c] * (outputMax[i][c] - outputMin[i][c]);
                if (*clampOutput) x[c] = std::clamp(x[c], clampMin[i][c], std::max(clampMin[i][c], clampMax[i][c]));
            }
            float const mask = (*invertMask ? 1.0f - inputMask[i] : inputMask[i]) * mixMask[i];
            result.set(i, input[i] + (x - input[i]) * mask);
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }

private:
    /// How much contrast c stretches a channel about its pivot: flat grey at -1, unchanged at 0, ever
    /// steeper towards 1 (kept finite there).
    static float contrastSlope(float c) {
        c = std::clamp(c, -1.0f, 0.999f);
        return c < 0.0f ? 1.0f + c : 1.0f / (1.0f - c);
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrColorCorrect)
