#include "PlasticFactory.h"

#include <new>

#include "Plastic.h"

int PlasticFactory::Init(RixContext& ctx, RtUString const pluginPath) {
    PIXAR_ARGUSED(ctx);
    PIXAR_ARGUSED(pluginPath);
    return 0;
}

void PlasticFactory::Finalize(RixContext& ctx) { PIXAR_ARGUSED(ctx); }

RixSCParamInfo const* PlasticFactory::GetParamTable() {
    static RixSCParamInfo s_ptable[] = {
        RixSCParamInfo(RtUString("diffuseColor"), k_RixSCColor, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("specularColor"), k_RixSCColor, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("gloss"), k_RixSCFloat, k_RixSCScatterInput),
        RixSCParamInfo(RtUString("normalize"), k_RixSCInteger, k_RixSCScatterInput),
        RixSCParamInfo()  // end of table
    };
    return s_ptable;
}

void PlasticFactory::Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) {
    PIXAR_ARGUSED(parameterList);
    if (syncMsg == k_RixSCRenderBegin) {
        g_plasticDiffuseLobe = RixBXLookupLobeByName(ctx, false, false, true, false, 0, "Diffuse");
        g_plasticSpecularLobe = RixBXLookupLobeByName(ctx, false, true, true, false, 0, "Specular");
        g_plasticTraits = RixBXLobeTraits(g_plasticDiffuseLobe) | RixBXLobeTraits(g_plasticSpecularLobe);
    }
}

void PlasticFactory::CreateInstanceData(RixContext& ctx, RtUString const handle, RixParameterList const* parameterList,
                                        InstanceData* instance) {
    PIXAR_ARGUSED(instance);
    RtColorRGB diffuse = m_defaultDiffuseColor, specular = m_defaultSpecularColor;
    int id;
    if (parameterList->GetParamId(RtUString("diffuseColor"), &id) == 0) parameterList->EvalParam(id, -1, &diffuse);
    if (parameterList->GetParamId(RtUString("specularColor"), &id) == 0) parameterList->EvalParam(id, -1, &specular);
    RtColorRGB total = diffuse + specular;
    if (total.ChannelMax() > 1.0f) {
        auto* messages = static_cast<RixMessages*>(ctx.GetRixInterface(k_RixMessages));
        if (messages)
            messages->Warning("\"%s\": diffuseColor + specularColor = (%g %g %g) exceeds 1: the surface reflects "
                              "more light than it receives",
                              handle.CStr(), total.r, total.g, total.b);
    }
}

RixBxdf* PlasticFactory::BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                                      RixSCShadingMode shadingMode, void* parentData, RtPointer instanceData) {
    PIXAR_ARGUSED(lobesWanted);
    PIXAR_ARGUSED(shadingMode);
    PIXAR_ARGUSED(parentData);
    PIXAR_ARGUSED(instanceData);

    PlasticParams params;
    sCtx->EvalParam(k_diffuseColor, -1, &params.diffuseColor, &m_defaultDiffuseColor, true);
    sCtx->EvalParam(k_specularColor, -1, &params.specularColor, &m_defaultSpecularColor, true);
    sCtx->EvalParam(k_gloss, -1, &params.gloss, &m_defaultGloss, true);
    int const* normalize;
    sCtx->EvalParam(k_normalize, -1, &normalize, &m_defaultNormalize, false);
    params.normalize = *normalize;

    RixShadingContext::Allocator pool(sCtx);
    void* mem = pool.AllocForBxdf<Plastic>(1);
    return new (mem) Plastic(sCtx, this, params);
}

void PlasticFactory::EndScatter(RixBxdf* bxdf) { PIXAR_ARGUSED(bxdf); }

RIX_BXDFPLUGINCREATE {
    PIXAR_ARGUSED(hint);
    return new PlasticFactory();
}

RIX_BXDFPLUGINDESTROY { delete static_cast<PlasticFactory*>(bxdf); }
