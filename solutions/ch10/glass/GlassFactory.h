// The factory of the glass plugin.
#pragma once

#include "RixBxdf.h"

class GlassFactory : public RixBxdfFactory {
public:
    int Init(RixContext& ctx, RtUString const pluginPath) override;
    void Finalize(RixContext& ctx) override;
    RixSCParamInfo const* GetParamTable() override;
    void Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) override;

    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                          RixSCShadingMode shadingMode, void* parentData, RtPointer instanceData) override;
    void EndScatter(RixBxdf* bxdf) override;

private:
    enum ParamId { k_ior = 0, k_roughness, k_transmissionColor, k_numParams };
    float m_defaultIor = 1.5f;
    float m_defaultRoughness = 0.0f;
    RtColorRGB m_defaultTransmissionColor{1.0f, 1.0f, 1.0f};
};
