// The factory of the specular plugin.
#pragma once

#include "RixBxdf.h"

class SpecularFactory : public RixBxdfFactory {
public:
    int Init(RixContext& ctx, RtUString const pluginPath) override;
    void Finalize(RixContext& ctx) override;
    RixSCParamInfo const* GetParamTable() override;
    void Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) override;

    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                          RixSCShadingMode shadingMode, void* parentData, RtPointer instanceData) override;
    void EndScatter(RixBxdf* bxdf) override;

private:
    enum ParamId { k_specularColor = 0, k_gloss, k_normalize, k_samplingMode, k_numParams };
    RtColorRGB m_defaultSpecularColor{1.0f, 1.0f, 1.0f};
    float m_defaultGloss = 20.0f;
    int m_defaultNormalize = 1;
    int m_defaultSamplingMode = 0;
};
