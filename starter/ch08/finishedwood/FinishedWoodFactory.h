// The factory of the finishedwood plugin.
#pragma once

#include "RixBxdf.h"

class FinishedWoodFactory : public RixBxdfFactory {
public:
    int Init(RixContext& ctx, RtUString const pluginPath) override;
    void Finalize(RixContext& ctx) override;
    RixSCParamInfo const* GetParamTable() override;
    void Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) override;

    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                          RixSCShadingMode shadingMode, void* parentData, RtPointer instanceData) override;
    void EndScatter(RixBxdf* bxdf) override;

private:
    enum ParamId {
        k_eta = 0, k_diffuseColor, k_fiberColor, k_fiberAxis, k_beta, k_specularColor, k_roughness, k_numParams
    };
    float m_defaultEta = 1.5f;
    RtColorRGB m_defaultDiffuseColor{0.35f, 0.18f, 0.07f};
    RtColorRGB m_defaultFiberColor{0.5f, 0.3f, 0.12f};
    RtVector3 m_defaultFiberAxis{1.0f, 0.0f, 0.0f};
    float m_defaultBeta = 0.1f;
    RtColorRGB m_defaultSpecularColor{1.0f, 1.0f, 1.0f};
    float m_defaultRoughness = 0.05f;
};
