// The factory of the plastic plugin.
#pragma once

#include "RixBxdf.h"

class PlasticFactory : public RixBxdfFactory {
public:
    int Init(RixContext& ctx, RtUString const pluginPath) override;
    void Finalize(RixContext& ctx) override;
    RixSCParamInfo const* GetParamTable() override;
    void Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) override;
    /// Checks the parameters once per Bxdf statement (warns if the surface would create energy).
    void CreateInstanceData(RixContext& ctx, RtUString const handle, RixParameterList const* parameterList,
                            InstanceData* instance) override;

    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                          RixSCShadingMode shadingMode, void* parentData, RtPointer instanceData) override;
    void EndScatter(RixBxdf* bxdf) override;

private:
    enum ParamId { k_diffuseColor = 0, k_specularColor, k_gloss, k_normalize, k_numParams };
    RtColorRGB m_defaultDiffuseColor{0.5f, 0.5f, 0.5f};
    RtColorRGB m_defaultSpecularColor{0.2f, 0.2f, 0.2f};
    float m_defaultGloss = 50.0f;
    int m_defaultNormalize = 1;
};
