#include "WardFactory.h"

#include <new>

#include "Ward.h"

int WardFactory::Init(RixContext& ctx, RtUString const pluginPath) {
    PIXAR_ARGUSED(ctx);
    PIXAR_ARGUSED(pluginPath);
    return 0;
}

void WardFactory::Finalize(RixContext& ctx) { PIXAR_ARGUSED(ctx); }

RixSCParamInfo const* WardFactory::GetParamTable() {
    static RixSCParamInfo s_ptable[] = {
        RixSCParamInfo(RtUString("specularColor"), k_RixSCColor, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("uRoughness"), k_RixSCFloat, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("vRoughness"), k_RixSCFloat, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("diffuseColor"), k_RixSCColor, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("samplingMode"), k_RixSCInteger, k_RixSCScatterInput),
        RixSCParamInfo()  // end of table
    };
    return s_ptable;
}

void WardFactory::Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) {
    PIXAR_ARGUSED(parameterList);
    if (syncMsg == k_RixSCRenderBegin) {
        g_wardSpecularLobe = RixBXLookupLobeByName(ctx, false, true, true, false, 0, "Specular");
        g_wardDiffuseLobe = RixBXLookupLobeByName(ctx, false, false, true, false, 0, "Diffuse");
        g_wardTraits = RixBXLobeTraits(g_wardSpecularLobe) | RixBXLobeTraits(g_wardDiffuseLobe);
    }
}

RixBxdf* WardFactory::BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                                   RixSCShadingMode shadingMode, void* parentData, RtPointer instanceData) {
    PIXAR_ARGUSED(lobesWanted);
    PIXAR_ARGUSED(shadingMode);
    PIXAR_ARGUSED(parentData);
    PIXAR_ARGUSED(instanceData);

    WardParams params;
    sCtx->EvalParam(k_specularColor, -1, &params.specularColor, &m_defaultSpecularColor, true);
    sCtx->EvalParam(k_diffuseColor, -1, &params.diffuseColor, &m_defaultDiffuseColor, true);
    sCtx->EvalParam(k_uRoughness, -1, &params.uRoughness, &m_defaultRoughness, true);
    sCtx->EvalParam(k_vRoughness, -1, &params.vRoughness, &m_defaultRoughness, true);
    int const* samplingMode;
    sCtx->EvalParam(k_samplingMode, -1, &samplingMode, &m_defaultSamplingMode, false);
    params.samplingMode = *samplingMode;

    RixShadingContext::Allocator pool(sCtx);
    void* mem = pool.AllocForBxdf<Ward>(1);
    return new (mem) Ward(sCtx, this, params);
}

void WardFactory::EndScatter(RixBxdf* bxdf) { PIXAR_ARGUSED(bxdf); }

RIX_BXDFPLUGINCREATE {
    PIXAR_ARGUSED(hint);
    return new WardFactory();
}

RIX_BXDFPLUGINDESTROY { delete static_cast<WardFactory*>(bxdf); }
