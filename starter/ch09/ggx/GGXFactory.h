// The factory of the ggx plugin.
#pragma once

#include "RixBxdf.h"

class GGXFactory : public RixBxdfFactory {
public:
    int Init(RixContext& ctx, RtUString const pluginPath) override;
    void Finalize(RixContext& ctx) override;
    RixSCParamInfo const* GetParamTable() override;
    void Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) override;

    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                          RixSCShadingMode shadingMode, void* parentData, RtPointer instanceData) override;
    void EndScatter(RixBxdf* bxdf) override;

private:
    enum ParamId { k_specularColor = 0, k_uRoughness, k_vRoughness, k_samplingMode, k_numParams };
    RtColorRGB m_defaultSpecularColor{1.0f, 1.0f, 1.0f};
    float m_defaultRoughness = 0.2f;
    int m_defaultSamplingMode = 2;
};
