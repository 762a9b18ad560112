// A test pattern written as RenderMan 22 and later write them (OutputSpec,
// the baking methods overridden) that outputs what GetParamInfo says of its
// input: resultRGB = grey of k_RixSCDefaultValue (0), k_RixSCParameterListValue
// (0.5) or k_RixSCNetworkValue (1) for "color input", asked of the pattern's
// own shading context.
#include "RixPattern.h"

namespace {

enum { kResultRGB = 0, kInput };

class ConnectionPattern : public RixPattern {
public:
    int Init(RixContext&, RtUString const) override { return 0; }
    void Finalize(RixContext&) override {}
    void Synchronize(RixContext&, RixSCSyncMsg, RixParameterList const*) override {}
    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("resultRGB"), k_RixSCColor, k_RixSCOutput),
                                         RixSCParamInfo(RtUString("input"), k_RixSCColor),
                                         RixSCParamInfo()};
        return table;
    }
    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpec** outputs, RtPointer,
                            RixSCParamInfo const*) override {
        RixSCType type;
        RixSCConnectionInfo cinfo = k_RixSCInvalidConnection;
        if (sCtx->GetParamInfo(kInput, &type, &cinfo) != 0 || type != k_RixSCColor) return 1;
        RixShadingContext::Allocator pool(sCtx);
        OutputSpec* out = pool.AllocForPattern<OutputSpec>(1);
        RtColorRGB* grey = pool.AllocForPattern<RtColorRGB>(1);
        *grey = RtColorRGB(0.5f * static_cast<float>(cinfo));
        out[0].paramId = kResultRGB;
        out[0].detail = k_RixSCUniform;
        out[0].value = grey;
        *numOutputs = 1;
        *outputs = out;
        return 0;
    }
    bool Bake2dOutput(RixBakeContext const*, Bake2dSpec&, RtPointer) override { return false; }
    bool Bake3dOutput(RixBakeContext const*, Bake3dSpec&, RtPointer) override { return false; }
};

}  // namespace

RIX_PATTERNCREATE {
    PIXAR_ARGUSED(hint);
    return new ConnectionPattern();
}
RIX_PATTERNDESTROY { delete static_cast<ConnectionPattern*>(pattern); }
