#include "EmissiveFactory.h"

#include <new>

#include "Emissive.h"

int EmissiveFactory::Init(RixContext& ctx, RtUString const pluginPath) {
    PIXAR_ARGUSED(ctx);
    PIXAR_ARGUSED(pluginPath);
    return 0;  // success
}

void EmissiveFactory::Finalize(RixContext& ctx) { PIXAR_ARGUSED(ctx); }

RixSCParamInfo const* EmissiveFactory::GetParamTable() {
    // One row per parameter, in the order of ParamId, ended by an empty entry.
    static RixSCParamInfo s_ptable[] = {
        RixSCParamInfo(RtUString("emissiveColor"), k_RixSCColor, k_RixSCScatterInput),
        RixSCParamInfo()  // end of table
    };
    return s_ptable;
}

void EmissiveFactory::Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) {
    PIXAR_ARGUSED(ctx);
    PIXAR_ARGUSED(syncMsg);
    PIXAR_ARGUSED(parameterList);
    // No lobes to look up: an emissive surface only emits.
}

RixBxdf* EmissiveFactory::BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                                       RixSCShadingMode shadingMode, void* parentData, RtPointer instanceData) {
    PIXAR_ARGUSED(lobesWanted);
    PIXAR_ARGUSED(shadingMode);
    PIXAR_ARGUSED(parentData);
    PIXAR_ARGUSED(instanceData);

    // The colour for every point of the batch (promoted to one value per point).
    RtColorRGB const* emissiveColor;
    sCtx->EvalParam(k_emissiveColor, -1, &emissiveColor, &m_defaultEmissiveColor, true);

    // The Bxdf lives in the shading context's memory: no new/delete per batch.
    RixShadingContext::Allocator pool(sCtx);
    void* mem = pool.AllocForBxdf<Emissive>(1);
    return new (mem) Emissive(sCtx, this, emissiveColor);
}

void EmissiveFactory::EndScatter(RixBxdf* bxdf) {
    PIXAR_ARGUSED(bxdf);  // its memory goes away with the shading context
}

RIX_BXDFPLUGINCREATE {
    PIXAR_ARGUSED(hint);
    return new EmissiveFactory();
}

RIX_BXDFPLUGINDESTROY { delete static_cast<EmissiveFactory*>(bxdf); }
