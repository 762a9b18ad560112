#include "GGXFactory.h"

#include <new>

#include "GGX.h"
#include "Todo.h"

int GGXFactory::Init(RixContext& ctx, RtUString const pluginPath) {
    PIXAR_ARGUSED(ctx);
    PIXAR_ARGUSED(pluginPath);
    return 0;
}

void GGXFactory::Finalize(RixContext& ctx) { PIXAR_ARGUSED(ctx); }

RixSCParamInfo const* GGXFactory::GetParamTable() {
    // In the order of ParamId (GGXFactory.h): EvalParam finds a parameter by its place here.
    // TODO (exercise 4): one entry per parameter of GGX.h, in that order, each a
    //   RixSCParamInfo(RtUString(name), type, k_RixSCScatterInput)
    // with the type k_RixSCColor, k_RixSCFloat or k_RixSCInteger. (ward's factory is a model.)
    // Until then the renderer knows no parameter of ggx: the RIB's values are ignored.
    static RixSCParamInfo s_ptable[] = {
        RixSCParamInfo()  // end of table
    };
    return s_ptable;
}

void GGXFactory::Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) {
    PIXAR_ARGUSED(parameterList);
    if (syncMsg == k_RixSCRenderBegin) {
        // TODO (exercise 4): look up the one lobe ggx has, a glossy (not discrete) reflection lobe
        //   named "Specular", into g_ggxSpecularLobe, and make g_ggxTraits the traits of that lobe
        //   (RixBXLookupLobeByName(ctx, discrete, specular, reflect, user, id, name); chapter 5).
        //   Until then ggx declares no lobe, and the integrator never samples it.
        ReportTodo(ctx, "GGXFactory::Synchronize (the lobe lookup)");
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
    // TODO (exercise 4): the roughnesses, one value per point as for specularColor above
    //   (the last argument, true, asks for an array of numPts values), and the sampling mode,
    //   one value for the whole batch (false). Until then every point has the defaults.
    sCtx->EvalParam(k_numParams, -1, &params.uRoughness, &m_defaultRoughness, true);  // no such parameter: defaults
    params.vRoughness = params.uRoughness;
    params.samplingMode = m_defaultSamplingMode;
    RIX_TODO(sCtx, "GGXFactory::BeginScatter (the roughness and sampling-mode parameters)");

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
