// PxrConstant — the stock "constant colour" material ("color emitColor",
// default white): the surface shows exactly that colour, whatever the light.
// The emission is the chapter 6 emissive solution's; only the factory differs.
#include <new>

#include "Emissive.h"

namespace {

class PxrConstantFactory : public RixBxdfFactory {
public:
    int Init(RixContext&, RtUString const) override { return 0; }
    void Finalize(RixContext&) override {}
    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("emitColor"), k_RixSCColor, k_RixSCScatterInput),
                                         RixSCParamInfo()};
        return table;
    }
    void Synchronize(RixContext&, RixSCSyncMsg, RixParameterList const*) override {}
    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const&, RixSCShadingMode, void*,
                          RtPointer) override {
        RtColorRGB const* color;
        sCtx->EvalParam(0, -1, &color, &m_default, true);
        RixShadingContext::Allocator pool(sCtx);
        return new (pool.AllocForBxdf<Emissive>(1)) Emissive(sCtx, this, color);
    }
    void EndScatter(RixBxdf*) override {}

private:
    RtColorRGB m_default{1.0f, 1.0f, 1.0f};
};

}  // namespace

RIX_BXDFPLUGINCREATE {
    PIXAR_ARGUSED(hint);
    return new PxrConstantFactory();
}
RIX_BXDFPLUGINDESTROY { delete static_cast<PxrConstantFactory*>(bxdf); }
