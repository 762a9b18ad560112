// A test Bxdf written the way many studio plugins are: its factory is a class
// in the global namespace with GetParamTable written inside the class. Built
// twice (sameclass_a and sameclass_b, with different parameter names) without
// hidden symbols, as a plain Makefile builds it, the two plugins share the
// compiler's one copy of that function's static table; the renderer must say
// so instead of reading one plugin's parameters with the other's table.
#include <new>

#include "EmitOnlyBxdf.h"

class BxdfFactory : public RixBxdfFactory {
public:
    int Init(RixContext&, RtUString const) override { return 0; }
    void Finalize(RixContext&) override {}
    void Synchronize(RixContext&, RixSCSyncMsg, RixParameterList const*) override {}
    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString(SAMECLASS_PARAMETER), k_RixSCColor), RixSCParamInfo()};
        return table;
    }
    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const&, RixSCShadingMode, void*,
                          RtPointer) override {
        RtColorRGB const black(0.0f);
        RtColorRGB const* glow;
        sCtx->EvalParam(0, -1, &glow, &black, true);
        RixShadingContext::Allocator pool(sCtx);
        return new (pool.AllocForBxdf<ColourEmitter>(1)) ColourEmitter(sCtx, this, glow);
    }
    void EndScatter(RixBxdf*) override {}
};

RIX_BXDFPLUGINCREATE { return new BxdfFactory(); }
RIX_BXDFPLUGINDESTROY { delete static_cast<BxdfFactory*>(bxdf); }
