// PxrClamp — keeps each channel of a colour between `min` and `max`. With `modulus` on, a channel outside
// the range wraps round into it instead (min + (x - min) mod (max - min)), which repeats a ramp.
#include <algorithm>
#include <cmath>

#include "PatternHelpers.h"

namespace {

class PxrClamp : public stockpatterns::StockPattern {
public:
    enum { k_inputRGB, k_min, k_max, k_modulus, k_resultRGB, k_resultR, k_resultG, k_resultB };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("inputRGB"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("min"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("max"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("modulus"), k_RixSCInteger),
                                         STOCK_PATTERN_COLOR_OUTPUTS,
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtColorRGB const black(0.0f), white(1.0f);
        RtInt const off = 0;
        RtColorRGB const *input, *low, *high;
        RtInt const* modulus;
        sCtx->EvalParam(k_inputRGB, -1, &input, &black, true);
        sCtx->EvalParam(k_min, -1, &low, &black, true);
        sCtx->EvalParam(k_max, -1, &high, &white, true);
        sCtx->EvalParam(k_modulus, -1, &modulus, &off);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(4);
        int count = 0;
        stockpatterns::ColorOutputs result(sCtx, out, count, k_resultRGB);
        for (int i = 0; i < sCtx->numPts; ++i) {
            RtColorRGB x = input[i];
            for (int c = 0; c < 3; ++c) {
                float const lo = low[i][c], hi = std::max(lo, high[i][c]), range = hi - lo;
                if (*modulus && range > 0.0f)
                    x[c] = lo + (x[c] - lo) - range * std::floor((x[c] - lo) / range);
                else
                    x[c] = std::clamp(x[c], lo, hi);
            }
            result.set(i, x);
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrClamp)
