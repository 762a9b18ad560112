// PxrConstant — the stock "constant colour" material ("color emitColor",
// default white): the surface shows exactly that colour, whatever the light.
// The emission is the chapter 6 emissive solution's; only the factory differs.
#include <new>

#include "Emissive.h"
#include "StockBxdf.h"

namespace {

class PxrConstantFactory : public stockbxdfs::StockBxdfFactory {
public:
    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("emitColor"), k_RixSCColor, k_RixSCScatterInput),
                                         RixSCParamInfo()};
        return table;
    }
    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const&, RixSCShadingMode, void*,
                          RtPointer) override {
        RtColorRGB const* color;
        sCtx->EvalParam(0, -1, &color, &m_default, true);
        RixShadingContext::Allocator pool(sCtx);
        return new (pool.AllocForBxdf<Emissive>(1)) Emissive(sCtx, this, color);
    }

private:
    RtColorRGB m_default{1.0f, 1.0f, 1.0f};
};

}  // namespace

STOCK_BXDF_PLUGIN(PxrConstantFactory)
