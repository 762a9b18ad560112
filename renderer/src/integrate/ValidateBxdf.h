// PxrValidateBxdf: a picture of whether a Bxdf's sampling, evaluation and
// pdfs agree. For each shade point it takes numSamples directions and writes
//   red    mean of luminance(W) / FPdf over GenerateSample's directions
//   green  the same directions re-evaluated with EvaluateSample, counted only
//          where EvaluateSample returns the same W and FPdf as GenerateSample
//   blue   cosine-distributed directions chosen by the integrator, evaluated
//          with EvaluateSample and divided by the cosine pdf
// All three estimate the directional albedo, so a correct Bxdf gives three
// equal channels (grey, at most 1 for a white energy-conserving Bxdf).
// Red differing from blue points at a pdf that does not match the sampling;
// green darker than red at EvaluateSample disagreeing with GenerateSample.
#pragma once

#include "integrate/Integrator.h"

namespace bxdflab {

class ValidateBxdf : public Integrator {
public:
    explicit ValidateBxdf(int numSamples) : m_numSamples(numSamples) {}
    std::string name() const override { return "PxrValidateBxdf"; }
    void describeEffects(Scene const& scene, EffectReport& report) const override;
    void integrate(ShadingContextImpl const& ctx, RixBxdf& bxdf, RixRNG& rng, IntegratorServices& services,
                   RtColorRGB* radiance) override;

private:
    int m_numSamples;
};

/// PxrDebugShadingContext: shows one builtin of the shading context as a
/// colour: Nn, Ngn, Vn, Tn, P, dPdu, dPdv map xyz to rgb with 0 at mid-grey;
/// VLen is grey; UV and ST map (u, v) to (r, g); InsideOutside is green where
/// the viewer is on the outside (the side Ngn points to), red inside.
class DebugShadingContext : public Integrator {
public:
    /// Throws RibError for an unknown channel (the message lists the valid ones).
    DebugShadingContext(std::string channel, SourceLocation const& where);
    std::string name() const override { return "PxrDebugShadingContext"; }
    void describeEffects(Scene const& scene, EffectReport& report) const override;
    void integrate(ShadingContextImpl const& ctx, RixBxdf& bxdf, RixRNG& rng, IntegratorServices& services,
                   RtColorRGB* radiance) override;

private:
    std::string m_channel;
};

/// PxrOcclusion: ambient occlusion, the fraction of cosine-distributed
/// directions that escape within maxDistance (white = fully open).
class Occlusion : public Integrator {
public:
    Occlusion(int numSamples, float maxDistance) : m_numSamples(numSamples), m_maxDistance(maxDistance) {}
    std::string name() const override { return "PxrOcclusion"; }
    void describeEffects(Scene const& scene, EffectReport& report) const override;
    void integrate(ShadingContextImpl const& ctx, RixBxdf& bxdf, RixRNG& rng, IntegratorServices& services,
                   RtColorRGB* radiance) override;

private:
    int m_numSamples;
    float m_maxDistance;
};

}  // namespace bxdflab
