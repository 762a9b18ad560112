#include "GGXFactory.h"

#include <new>

#include "GGX.h"

int GGXFactory::Init(RixContext& ctx, RtUString const pluginPath) {
    PIXAR_ARGUSED(ctx);
    PIXAR_ARGUSED(pluginPath);
    return 0;
}

void GGXFactory::Finalize(RixContext& ctx) { PIXAR_ARGUSED(ctx); }

RixSCParamInfo const* GGXFactory::GetParamTable() {
    // In the order of ParamId (GGXFactory.h): EvalParam finds a parameter by its place here.
    static RixSCParamInfo s_ptable[] = {
        RixSCParamInfo(RtUString("specularColor"), k_RixSCColor, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("uRoughness"), k_RixSCFloat, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("vRoughness"), k_RixSCFloat, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("samplingMode"), k_RixSCInteger, k_RixSCScatterInput),
        RixSCParamInfo()  // end of table
    };
    return s_ptable;
}

void GGXFactory::Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) {
    PIXAR_ARGUSED(parameterList);
    if (syncMsg == k_RixSCRenderBegin) {
        // One glossy reflection lobe (not discrete: the mirror limit is only approached).
        g_ggxSpecularLobe = RixBXLookupLobeByName(ctx, false, true, true, false, 0, "Specular");
        g_ggxTraits = RixBXLobeTraits(g_ggxSpecularLobe);
    }
}

RixBxdf* GGXFactory::BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                                  RixSCShadingMode shadingMode, void* parentData, RtPointer instanceData) {
    PIXAR_ARGUSED(lobesWanted);
    PIXAR_ARGUSED(shadingMode);
    PIXAR_ARGUSED(parentData);
    PIXAR_ARGUSED(instanceData);

    GGXParams params;
    sCtx->EvalParam(k_specularColor, -1, &params.specularColor, &m_defaultSpecularColor, true);
    sCtx->EvalParam(k_uRoughness, -1, &params.uRoughness, &m_defaultRoughness, true);
    sCtx->EvalParam(k_vRoughness, -1, &params.vRoughness, &m_defaultRoughness, true);
    int const* samplingMode;
    sCtx->EvalParam(k_samplingMode, -1, &samplingMode, &m_defaultSamplingMode, false);
    params.samplingMode = *samplingMode;

    RixShadingContext::Allocator pool(sCtx);
    void* mem = pool.AllocForBxdf<GGX>(1);
    return new (mem) GGX(sCtx, this, params);
}

void GGXFactory::EndScatter(RixBxdf* bxdf) { PIXAR_ARGUSED(bxdf); }

RIX_BXDFPLUGINCREATE {
    PIXAR_ARGUSED(hint);
    return new GGXFactory();
}

RIX_BXDFPLUGINDESTROY { delete static_cast<GGXFactory*>(bxdf); }
