// The factory of the emissive plugin: declares its one parameter and builds
// an Emissive Bxdf for every batch of shade points.
#pragma once

#include "RixBxdf.h"

class EmissiveFactory : public RixBxdfFactory {
public:
    int Init(RixContext& ctx, RtUString const pluginPath) override;
    void Finalize(RixContext& ctx) override;
    RixSCParamInfo const* GetParamTable() override;
    void Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) override;

    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                          RixSCShadingMode shadingMode, void* parentData, RtPointer instanceData) override;
    void EndScatter(RixBxdf* bxdf) override;

private:
    /// Parameter ids: the row of each parameter in the table.
    enum ParamId { k_emissiveColor = 0, k_numParams };
    RtColorRGB m_defaultEmissiveColor{1.0f, 1.0f, 1.0f};
};
