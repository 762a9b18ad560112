// PxrGamma — raises each channel of a colour to a power: resultRGB = inputRGB^gamma (ColorModels.h).
// A gamma of 2.2 turns a colour stored for display (an sRGB texture) linear; 1/2.2 does the reverse.
#include "ColorModels.h"
#include "PatternHelpers.h"

namespace {

class PxrGamma : public stockpatterns::StockPattern {
public:
    enum { k_inputRGB, k_gamma, k_resultRGB, k_resultR, k_resultG, k_resultB };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("inputRGB"), k_RixSCColor),
                                         RixSCParamInfo(RtUString("gamma"), k_RixSCFloat),
                                         STOCK_PATTERN_COLOR_OUTPUTS,
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtColorRGB const black(0.0f);
        RtFloat const one = 1.0f;
        RtColorRGB const* input;
        RtFloat const* gamma;
        sCtx->EvalParam(k_inputRGB, -1, &input, &black, true);
        sCtx->EvalParam(k_gamma, -1, &gamma, &one, true);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(4);
        int count = 0;
        stockpatterns::ColorOutputs result(sCtx, out, count, k_resultRGB);
        for (int i = 0; i < sCtx->numPts; ++i) {
            using stockpatterns::applyGamma;
            result.set(i, RtColorRGB(applyGamma(input[i].r, gamma[i]), applyGamma(input[i].g, gamma[i]),
                                     applyGamma(input[i].b, gamma[i])));
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrGamma)
