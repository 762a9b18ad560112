// PxrDiffuse — the stock Lambertian material that RIBs from other courses and
// tools name ("color diffuseColor", default 0.5 grey; "float presence",
// default 1, cuts the surface out where it is below 1). It is also the
// material of surfaces that have no Bxdf. The scattering is the chapter 6
// diffuse solution's; only the factory (name and defaults) differs.
#include <new>

#include "Diffuse.h"
#include "StockBxdf.h"

namespace {

class PxrDiffuseFactory : public stockbxdfs::StockBxdfWithPresence {
public:
    enum { k_diffuseColor, k_presence };
    PxrDiffuseFactory() : StockBxdfWithPresence(k_presence) {}
    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("diffuseColor"), k_RixSCColor, k_RixSCScatterInput),
                                         RixSCParamInfo(RtUString("presence"), k_RixSCFloat, k_RixSCPresenceInput),
                                         RixSCParamInfo()};
        return table;
    }
    void Synchronize(RixContext& ctx, RixSCSyncMsg msg, RixParameterList const*) override {
        if (msg != k_RixSCRenderBegin) return;
        g_diffuseLobe = RixBXLookupLobeByName(ctx, false, false, true, false, 0, "Diffuse");
        g_diffuseTraits = RixBXLobeTraits(g_diffuseLobe);
    }
    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const&, RixSCShadingMode, void*,
                          RtPointer) override {
        RtColorRGB const* color;
        sCtx->EvalParam(k_diffuseColor, -1, &color, &m_default, true);
        RixShadingContext::Allocator pool(sCtx);
        return new (pool.AllocForBxdf<Diffuse>(1)) Diffuse(sCtx, this, color);
    }

private:
    RtColorRGB m_default{0.5f, 0.5f, 0.5f};
};

}  // namespace

STOCK_BXDF_PLUGIN(PxrDiffuseFactory)
