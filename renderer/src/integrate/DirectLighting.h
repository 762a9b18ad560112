// PxrDirectLighting: light that reaches a surface straight from the lights
// (one bounce), estimated with two strategies combined by multiple importance
// sampling. Read DirectLighting.cpp as the course's example integrator.
#pragma once

#include <memory>

#include "integrate/Integrator.h"

namespace bxdflab {

class DirectLighting : public Integrator {
public:
    /// `ownLight` replaces the scene's lights when given (PxrDefault's headlight).
    DirectLighting(int numLightSamples, int numBxdfSamples, std::unique_ptr<Light> ownLight = nullptr);

    std::string name() const override { return m_ownLight ? "PxrDefault" : "PxrDirectLighting"; }
    std::vector<Light const*> extraLights() const override;
    void describeEffects(Scene const& scene, EffectReport& report) const override;
    void integrate(ShadingContextImpl const& ctx, RixBxdf& bxdf, RixRNG& rng, IntegratorServices& services,
                   RtColorRGB* radiance) override;

private:
    int m_numLightSamples;
    int m_numBxdfSamples;
    std::unique_ptr<Light> m_ownLight;
};

}  // namespace bxdflab
