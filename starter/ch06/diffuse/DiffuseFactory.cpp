#include "DiffuseFactory.h"

#include <new>

#include "Diffuse.h"

int DiffuseFactory::Init(RixContext& ctx, RtUString const pluginPath) {
    PIXAR_ARGUSED(ctx);
    PIXAR_ARGUSED(pluginPath);
    return 0;  // success
}

void DiffuseFactory::Finalize(RixContext& ctx) { PIXAR_ARGUSED(ctx); }

RixSCParamInfo const* DiffuseFactory::GetParamTable() {
    static RixSCParamInfo s_ptable[] = {
        RixSCParamInfo(RtUString("diffuseColor"), k_RixSCColor, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("samplingMode"), k_RixSCInteger, k_RixSCScatterInput),
        RixSCParamInfo()  // end of table
    };
    return s_ptable;
}

void DiffuseFactory::Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) {
    PIXAR_ARGUSED(parameterList);
    if (syncMsg == k_RixSCRenderBegin) {
        // One diffuse (non-specular), reflective lobe with id 0.
        g_diffuseLobe = RixBXLookupLobeByName(ctx, false, false, true, false, 0, "Diffuse");
        g_diffuseTraits = RixBXLobeTraits(g_diffuseLobe);
    }
}

RixBxdf* DiffuseFactory::BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                                      RixSCShadingMode shadingMode, void* parentData, RtPointer instanceData) {
    PIXAR_ARGUSED(lobesWanted);
    PIXAR_ARGUSED(shadingMode);
    PIXAR_ARGUSED(parentData);
    PIXAR_ARGUSED(instanceData);

    RtColorRGB const* diffuseColor;
    int const* samplingMode;
    sCtx->EvalParam(k_diffuseColor, -1, &diffuseColor, &m_defaultDiffuseColor, true);
    sCtx->EvalParam(k_samplingMode, -1, &samplingMode, &m_defaultSamplingMode, false);

    RixShadingContext::Allocator pool(sCtx);
    void* mem = pool.AllocForBxdf<Diffuse>(1);
    return new (mem) Diffuse(sCtx, this, diffuseColor, *samplingMode);
}

void DiffuseFactory::EndScatter(RixBxdf* bxdf) { PIXAR_ARGUSED(bxdf); }

RIX_BXDFPLUGINCREATE {
    PIXAR_ARGUSED(hint);
    return new DiffuseFactory();
}

RIX_BXDFPLUGINDESTROY { delete static_cast<DiffuseFactory*>(bxdf); }
