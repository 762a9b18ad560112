// PxrToFloat — one channel of a colour as a float: `mode` 0, 1 or 2 picks red, green or blue
// (the counterpart of PxrToFloat3). Other modes are warned about and read red.
#include "PatternHelpers.h"

namespace {

class PxrToFloat : public stockpatterns::StockPattern {
public:
    enum { k_input, k_mode, k_resultF };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("input"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("mode"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("resultF"), k_RixSCFloat, k_RixSCOutput),
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtColorRGB const black(0.0f);
        RtInt const red = 0;
        RtColorRGB const* input;
        RtInt const* mode;
        sCtx->EvalParam(k_input, -1, &input, &black, true);
        sCtx->EvalParam(k_mode, -1, &mode, &red);
        int channel = *mode;
        if (channel < 0 || channel > 2) {
            if (auto* messages = static_cast<RixMessages*>(sCtx->GetRixInterface(k_RixMessages)))
                messages->Warning("PxrToFloat: mode %d is not one of 0 (red), 1 (green), 2 (blue); red is used",
                                  channel);
            channel = 0;
        }

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(1);
        int count = 0;
        RtFloat* resultF = stockpatterns::addVaryingOutput<RtFloat>(sCtx, out, count, k_resultF);
        for (int i = 0; i < sCtx->numPts; ++i) resultF[i] = input[i][channel];
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrToFloat)
