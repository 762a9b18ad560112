#include "FinishedWoodFactory.h"

#include <new>

#include "FinishedWood.h"

int FinishedWoodFactory::Init(RixContext& ctx, RtUString const pluginPath) {
    PIXAR_ARGUSED(ctx);
    PIXAR_ARGUSED(pluginPath);
    return 0;
}

void FinishedWoodFactory::Finalize(RixContext& ctx) { PIXAR_ARGUSED(ctx); }

RixSCParamInfo const* FinishedWoodFactory::GetParamTable() {
    static RixSCParamInfo s_ptable[] = {
        RixSCParamInfo(RtUString("eta"), k_RixSCFloat, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("diffuseColor"), k_RixSCColor, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("fiberColor"), k_RixSCColor, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("fiberAxis"), k_RixSCVector, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("beta"), k_RixSCFloat, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("specularColor"), k_RixSCColor, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("roughness"), k_RixSCFloat, k_RixSCScatterInput),
        RixSCParamInfo()  // end of table
    };
    return s_ptable;
}

void FinishedWoodFactory::Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) {
    PIXAR_ARGUSED(parameterList);
    if (syncMsg == k_RixSCRenderBegin) {
        g_woodSubsurfaceLobe = RixBXLookupLobeByName(ctx, false, false, true, false, 0, "Diffuse");
        g_woodCoatLobe = RixBXLookupLobeByName(ctx, false, true, true, false, 0, "Specular");
        g_woodFiberLobe = RixBXLookupLobeByName(ctx, false, true, true, false, 1, "Fiber");
        g_woodTraits = RixBXLobeTraits(g_woodSubsurfaceLobe) | RixBXLobeTraits(g_woodCoatLobe) |
                       RixBXLobeTraits(g_woodFiberLobe);
    }
}

RixBxdf* FinishedWoodFactory::BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                                           RixSCShadingMode shadingMode, void* parentData, RtPointer instanceData) {
    PIXAR_ARGUSED(lobesWanted);
    PIXAR_ARGUSED(shadingMode);
    PIXAR_ARGUSED(parentData);
    PIXAR_ARGUSED(instanceData);

    FinishedWoodParams params;
    sCtx->EvalParam(k_eta, -1, &params.eta, &m_defaultEta, true);
    sCtx->EvalParam(k_diffuseColor, -1, &params.diffuseColor, &m_defaultDiffuseColor, true);
    sCtx->EvalParam(k_fiberColor, -1, &params.fiberColor, &m_defaultFiberColor, true);
    sCtx->EvalParam(k_fiberAxis, -1, &params.fiberAxis, &m_defaultFiberAxis, true);
    sCtx->EvalParam(k_beta, -1, &params.beta, &m_defaultBeta, true);
    sCtx->EvalParam(k_specularColor, -1, &params.specularColor, &m_defaultSpecularColor, true);
    sCtx->EvalParam(k_roughness, -1, &params.roughness, &m_defaultRoughness, true);

    RixShadingContext::Allocator pool(sCtx);
    void* mem = pool.AllocForBxdf<FinishedWood>(1);
    return new (mem) FinishedWood(sCtx, this, params);
}

void FinishedWoodFactory::EndScatter(RixBxdf* bxdf) { PIXAR_ARGUSED(bxdf); }

RIX_BXDFPLUGINCREATE {
    PIXAR_ARGUSED(hint);
    return new FinishedWoodFactory();
}

RIX_BXDFPLUGINDESTROY { delete static_cast<FinishedWoodFactory*>(bxdf); }
