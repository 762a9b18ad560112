// PxrDirectLighting: light that reaches a surface straight from the lights
// (one bounce), estimated with two strategies combined by multiple importance
// sampling. Read DirectLighting.cpp as the course's example integrator.
#pragma once

#include <memory>

#include "integrate/Integrator.h"

namespace bxdflab {

/// Next-event estimation for a batch: adds to radiance[i] the light arriving
/// straight from the lights and reflected toward the viewer, times
/// throughput[i] (or 1 when throughput is null), from numLightSamples samples
/// per light, MIS-weighted against numBxdfSamples Bxdf samples.
void addLightSamples(ShadingContextImpl const& ctx, RixBxdf& bxdf, RixRNG& rng, IntegratorServices& services,
                     int numLightSamples, int numBxdfSamples, RtColorRGB const* throughput, RtColorRGB* radiance);

/// Adds a contribution, or counts it when it is not finite (a Bxdf bug).
void accumulate(IntegratorServices& services, RtColorRGB& radiance, RtColorRGB const& contribution);

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
