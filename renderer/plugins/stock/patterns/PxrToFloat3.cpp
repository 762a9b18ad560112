// PxrToFloat3 — makes a colour of floats: "input" copied into all three
// channels, or, where any of inputR, inputG and inputB is connected, those
// three as the channels (an unconnected one keeps its own value):
//   Pattern "PxrToFloat3" "grey" "reference float input" ["noise:resultF"]
#include "PatternHelpers.h"

namespace {

class PxrToFloat3 : public stockpatterns::StockPattern {
public:
    enum { k_input, k_inputR, k_inputG, k_inputB, k_resultRGB };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("input"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("inputR"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("inputG"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("inputB"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("resultRGB"), k_RixSCColor, k_RixSCOutput),
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtFloat const zero = 0.0f;
        bool channels = false;
        for (int id : {k_inputR, k_inputG, k_inputB}) {
            RixSCConnectionInfo how = k_RixSCDefaultValue;
            sCtx->GetParamInfo(id, nullptr, &how);
            channels = channels || how == k_RixSCNetworkValue;
        }
        RtFloat const *r, *g, *b;
        if (channels) {
            sCtx->EvalParam(k_inputR, -1, &r, &zero, true);
            sCtx->EvalParam(k_inputG, -1, &g, &zero, true);
            sCtx->EvalParam(k_inputB, -1, &b, &zero, true);
        } else {
            sCtx->EvalParam(k_input, -1, &r, &zero, true);
            g = b = r;
        }
        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(1);
        int count = 0;
        RtColorRGB* result = stockpatterns::addVaryingOutput<RtColorRGB>(sCtx, out, count, k_resultRGB);
        for (int i = 0; i < sCtx->numPts; ++i) result[i] = RtColorRGB(r[i], g[i], b[i]);
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrToFloat3)
