#include "GlassFactory.h"

#include <new>

#include "Glass.h"

int GlassFactory::Init(RixContext& ctx, RtUString const pluginPath) {
    PIXAR_ARGUSED(ctx);
    PIXAR_ARGUSED(pluginPath);
    return 0;
}

void GlassFactory::Finalize(RixContext& ctx) { PIXAR_ARGUSED(ctx); }

RixSCParamInfo const* GlassFactory::GetParamTable() {
    // In the order of ParamId (GlassFactory.h).
    static RixSCParamInfo s_ptable[] = {
        RixSCParamInfo(RtUString("ior"), k_RixSCFloat, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("roughness"), k_RixSCFloat, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("transmissionColor"), k_RixSCColor, k_RixSCScatterInput),
        RixSCParamInfo()  // end of table
    };
    return s_ptable;
}

void GlassFactory::Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) {
    PIXAR_ARGUSED(parameterList);
    if (syncMsg == k_RixSCRenderBegin) {
        // Four specular lobes, each with its own name (and so its own weights):
        //                                         discrete specular reflect user id
        g_glassMirrorLobe = RixBXLookupLobeByName(ctx, true, true, true, false, 0, "Specular");
        g_glassRefractLobe = RixBXLookupLobeByName(ctx, true, true, false, false, 1, "Transmission");
        g_glassRoughReflectLobe = RixBXLookupLobeByName(ctx, false, true, true, false, 2, "RoughSpecular");
        g_glassRoughRefractLobe = RixBXLookupLobeByName(ctx, false, true, false, false, 3, "RoughTransmission");
        g_glassTraits = RixBXLobeTraits(g_glassMirrorLobe) | RixBXLobeTraits(g_glassRefractLobe) |
                        RixBXLobeTraits(g_glassRoughReflectLobe) | RixBXLobeTraits(g_glassRoughRefractLobe);
    }
}

RixBxdf* GlassFactory::BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                                    RixSCShadingMode shadingMode, void* parentData, RtPointer instanceData) {
    PIXAR_ARGUSED(lobesWanted);
    PIXAR_ARGUSED(shadingMode);
    PIXAR_ARGUSED(parentData);
    PIXAR_ARGUSED(instanceData);

    GlassParams params;
    sCtx->EvalParam(k_ior, -1, &params.ior, &m_defaultIor, true);
    sCtx->EvalParam(k_roughness, -1, &params.roughness, &m_defaultRoughness, true);
    sCtx->EvalParam(k_transmissionColor, -1, &params.transmissionColor, &m_defaultTransmissionColor, true);

    RixShadingContext::Allocator pool(sCtx);
    void* mem = pool.AllocForBxdf<Glass>(1);
    return new (mem) Glass(sCtx, this, params);
}

void GlassFactory::EndScatter(RixBxdf* bxdf) { PIXAR_ARGUSED(bxdf); }

RIX_BXDFPLUGINCREATE {
    PIXAR_ARGUSED(hint);
    return new GlassFactory();
}

RIX_BXDFPLUGINDESTROY { delete static_cast<GlassFactory*>(bxdf); }
