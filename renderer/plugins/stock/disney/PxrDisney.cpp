// The PxrDisney factory: RenderMan's parameter names and defaults, one
// Disney Bxdf per shading context (the model is in Disney.h).
#include <new>

#include "../StockBxdf.h"
#include "Disney.h"

namespace {

class PxrDisneyFactory : public stockbxdfs::StockBxdfWithPresence {
public:
    enum ParamId {
        k_baseColor, k_emitColor, k_subsurface, k_subsurfaceColor, k_metallic, k_specular, k_specularTint, k_roughness,
        k_anisotropic, k_sheen, k_sheenTint, k_clearcoat, k_clearcoatGloss, k_bumpNormal, k_presence
    };
    PxrDisneyFactory() : StockBxdfWithPresence(k_presence) {}

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {
            RixSCParamInfo(RtUString("baseColor"), k_RixSCColor, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("emitColor"), k_RixSCColor, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("subsurface"), k_RixSCFloat, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("subsurfaceColor"), k_RixSCColor, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("metallic"), k_RixSCFloat, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("specular"), k_RixSCFloat, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("specularTint"), k_RixSCFloat, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("roughness"), k_RixSCFloat, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("anisotropic"), k_RixSCFloat, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("sheen"), k_RixSCFloat, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("sheenTint"), k_RixSCFloat, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("clearcoat"), k_RixSCFloat, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("clearcoatGloss"), k_RixSCFloat, k_RixSCScatterInput),
            // A bent normal to shade with (PxrNormalMap's resultN); used only when connected.
            RixSCParamInfo(RtUString("bumpNormal"), k_RixSCNormal, k_RixSCScatterInput),
            // 1: present; below 1 or connected: a cut-out (see StockBxdfWithPresence).
            RixSCParamInfo(RtUString("presence"), k_RixSCFloat, k_RixSCPresenceInput),
            RixSCParamInfo()};
        return table;
    }
    void Synchronize(RixContext& ctx, RixSCSyncMsg msg, RixParameterList const*) override {
        if (msg != k_RixSCRenderBegin) return;
        g_disneyLobes.diffuse = RixBXLookupLobeByName(ctx, false, false, true, false, 0, "Diffuse");
        g_disneyLobes.specular = RixBXLookupLobeByName(ctx, false, true, true, false, 1, "Specular");
        g_disneyLobes.clearcoat = RixBXLookupLobeByName(ctx, false, true, true, false, 2, "Clearcoat");
        g_disneyLobes.all = RixBXLobeTraits(g_disneyLobes.diffuse) | RixBXLobeTraits(g_disneyLobes.specular) |
                            RixBXLobeTraits(g_disneyLobes.clearcoat);
    }

    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const&, RixSCShadingMode, void*,
                          RtPointer) override {
        DisneyParams p;
        sCtx->EvalParam(k_baseColor, -1, &p.baseColor, &m_baseColor, true);
        sCtx->EvalParam(k_emitColor, -1, &p.emitColor, &m_black, true);
        sCtx->EvalParam(k_subsurface, -1, &p.subsurface, &m_zero, true);
        sCtx->EvalParam(k_subsurfaceColor, -1, &p.subsurfaceColor, &m_black, true);
        sCtx->EvalParam(k_metallic, -1, &p.metallic, &m_zero, true);
        sCtx->EvalParam(k_specular, -1, &p.specular, &m_half, true);
        sCtx->EvalParam(k_specularTint, -1, &p.specularTint, &m_zero, true);
        sCtx->EvalParam(k_roughness, -1, &p.roughness, &m_roughness, true);
        sCtx->EvalParam(k_anisotropic, -1, &p.anisotropic, &m_zero, true);
        sCtx->EvalParam(k_sheen, -1, &p.sheen, &m_zero, true);
        sCtx->EvalParam(k_sheenTint, -1, &p.sheenTint, &m_half, true);
        sCtx->EvalParam(k_clearcoat, -1, &p.clearcoat, &m_zero, true);
        sCtx->EvalParam(k_clearcoatGloss, -1, &p.clearcoatGloss, &m_one, true);
        if (sCtx->EvalParam(k_bumpNormal, -1, &p.bumpNormal) != k_RixSCVarying) p.bumpNormal = nullptr;
        p.anyAnisotropic = false;
        for (int i = 0; i < sCtx->numPts; ++i) p.anyAnisotropic = p.anyAnisotropic || p.anisotropic[i] != 0.0f;
        RixShadingContext::Allocator pool(sCtx);
        return new (pool.AllocForBxdf<Disney>(1)) Disney(sCtx, this, p);
    }

private:
    RtColorRGB const m_baseColor{0.2f, 0.5f, 0.8f}, m_black{0.0f, 0.0f, 0.0f};
    float const m_zero = 0.0f, m_half = 0.5f, m_one = 1.0f, m_roughness = 0.25f;
};

}  // namespace

STOCK_BXDF_PLUGIN(PxrDisneyFactory)
