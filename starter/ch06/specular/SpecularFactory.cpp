#include "SpecularFactory.h"

#include <new>

#include "Specular.h"

int SpecularFactory::Init(RixContext& ctx, RtUString const pluginPath) {
    PIXAR_ARGUSED(ctx);
    PIXAR_ARGUSED(pluginPath);
    return 0;
}

void SpecularFactory::Finalize(RixContext& ctx) { PIXAR_ARGUSED(ctx); }

RixSCParamInfo const* SpecularFactory::GetParamTable() {
    static RixSCParamInfo s_ptable[] = {
        RixSCParamInfo(RtUString("specularColor"), k_RixSCColor, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("gloss"), k_RixSCFloat, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("normalize"), k_RixSCInteger, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("samplingMode"), k_RixSCInteger, k_RixSCScatterInput),
        RixSCParamInfo()  // end of table
    };
    return s_ptable;
}

void SpecularFactory::Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) {
    PIXAR_ARGUSED(parameterList);
    if (syncMsg == k_RixSCRenderBegin) {
        // A glossy (specular, not discrete) reflection lobe.
        g_specularLobe = RixBXLookupLobeByName(ctx, false, true, true, false, 0, "Specular");
        g_specularTraits = RixBXLobeTraits(g_specularLobe);
    }
}

RixBxdf* SpecularFactory::BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                                       RixSCShadingMode shadingMode, void* parentData, RtPointer instanceData) {
    PIXAR_ARGUSED(lobesWanted);
    PIXAR_ARGUSED(shadingMode);
    PIXAR_ARGUSED(parentData);
    PIXAR_ARGUSED(instanceData);

    SpecularParams params;
    sCtx->EvalParam(k_specularColor, -1, &params.specularColor, &m_defaultSpecularColor, true);
    sCtx->EvalParam(k_gloss, -1, &params.gloss, &m_defaultGloss, true);
    // Integer switches are the same for the whole batch: no need to promote them.
    int const* normalize;
    int const* samplingMode;
    sCtx->EvalParam(k_normalize, -1, &normalize, &m_defaultNormalize, false);
    sCtx->EvalParam(k_samplingMode, -1, &samplingMode, &m_defaultSamplingMode, false);
    params.normalize = *normalize;
    params.samplingMode = *samplingMode;

    RixShadingContext::Allocator pool(sCtx);
    void* mem = pool.AllocForBxdf<Specular>(1);
    return new (mem) Specular(sCtx, this, params);
}

void SpecularFactory::EndScatter(RixBxdf* bxdf) { PIXAR_ARGUSED(bxdf); }

RIX_BXDFPLUGINCREATE {
    PIXAR_ARGUSED(hint);
    return new SpecularFactory();
}

RIX_BXDFPLUGINDESTROY { delete static_cast<SpecularFactory*>(bxdf); }
