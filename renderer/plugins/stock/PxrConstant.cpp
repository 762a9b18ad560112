// PxrConstant — the stock "constant colour" material ("color emitColor",
// default white; "float presence", default 1, cuts the surface out where it
// is below 1): the surface shows exactly that colour, whatever the light.
// The emission is the chapter 6 emissive solution's; only the factory differs.
#include <new>

#include "Emissive.h"
#include "StockBxdf.h"

namespace {

class PxrConstantFactory : public stockbxdfs::StockBxdfWithPresence {
public:
    enum { k_emitColor, k_presence };
    PxrConstantFactory() : StockBxdfWithPresence(k_presence) {}
    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("emitColor"), k_RixSCColor, k_RixSCScatterInput),
                                         RixSCParamInfo(RtUString("presence"), k_RixSCFloat, k_RixSCPresenceInput),
                                         RixSCParamInfo()};
        return table;
    }
    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const&, RixSCShadingMode, void*,
                          RtPointer) override {
        RtColorRGB const* color;
        sCtx->EvalParam(k_emitColor, -1, &color, &m_default, true);
        RixShadingContext::Allocator pool(sCtx);
        return new (pool.AllocForBxdf<Emissive>(1)) Emissive(sCtx, this, color);
    }

private:
    RtColorRGB m_default{1.0f, 1.0f, 1.0f};
};

}  // namespace

STOCK_BXDF_PLUGIN(PxrConstantFactory)
