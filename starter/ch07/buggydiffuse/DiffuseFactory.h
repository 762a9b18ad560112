// The factory of the diffuse plugin: declares its parameter, looks up its
// lobe when the render begins, and builds a Diffuse Bxdf for every batch.
#pragma once

#include "RixBxdf.h"

class DiffuseFactory : public RixBxdfFactory {
public:
    int Init(RixContext& ctx, RtUString const pluginPath) override;
    void Finalize(RixContext& ctx) override;
    RixSCParamInfo const* GetParamTable() override;
    void Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const* parameterList) override;

    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                          RixSCShadingMode shadingMode, void* parentData, RtPointer instanceData) override;
    void EndScatter(RixBxdf* bxdf) override;

private:
    enum ParamId { k_diffuseColor = 0, k_samplingMode, k_numParams };
    RtColorRGB m_defaultDiffuseColor{0.8f, 0.8f, 0.8f};
    int m_defaultSamplingMode = 0;
};
