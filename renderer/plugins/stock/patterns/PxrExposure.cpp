// PxrExposure — brightens or darkens a colour by photographic stops: each stop
// doubles it (or, negative, halves it): resultRGB = inputRGB * 2^stops.
#include <cmath>

#include "PatternHelpers.h"

namespace {

class PxrExposure : public stockpatterns::StockPattern {
public:
    enum { k_inputRGB, k_stops, k_resultRGB, k_resultR, k_resultG, k_resultB };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("inputRGB"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("stops"), k_RixSCFloat),
                                         STOCK_PATTERN_COLOR_OUTPUTS,
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtColorRGB const black(0.0f);
        RtFloat const none = 0.0f;
        RtColorRGB const* input;
        RtFloat const* stops;
        sCtx->EvalParam(k_inputRGB, -1, &input, &black, true);
        sCtx->EvalParam(k_stops, -1, &stops, &none, true);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(4);
        int count = 0;
        stockpatterns::ColorOutputs result(sCtx, out, count, k_resultRGB);
        for (int i = 0; i < sCtx->numPts; ++i) {
            result.set(i, input[i] * std::exp2(stops[i]));
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrExposure)
