// PxrPathTracer: unidirectional path tracing. At every surface a path
// reaches it (1) adds the surface's emission, (2) samples the lights
// directly (next-event estimation), and (3) samples the Bxdf: a sampled
// direction that reaches a light adds that light (weighted against the
// light samples by MIS), and otherwise the path continues to the surface
// it hits. Continuing paths are traced and shaded batch by batch, grouped
// by Bxdf like camera hits.
//
// Parameters
//   int maxPathLength    [10]  surfaces a path may visit (1 = direct lighting only)
//   int numLightSamples  [1]   light samples per light at every vertex
//   int numBxdfSamples   [1]   Bxdf samples at every vertex (the first continues the path)
//   int allowCaustics    [0]   0: once a path has bounced off a diffuse lobe, a
//                              specular bounce does not continue it (no caustics:
//                              they are noisy for a path tracer)
// Russian roulette ends paths from the fourth vertex on with probability
// 1 - min(0.95, the path's largest throughput channel), and compensates the survivors.
#pragma once

#include "integrate/Integrator.h"

namespace bxdflab {

class PathTracer : public Integrator {
public:
    PathTracer(int maxPathLength, int numLightSamples, int numBxdfSamples, bool allowCaustics)
        : m_maxPathLength(maxPathLength),
          m_numLightSamples(numLightSamples),
          m_numBxdfSamples(numBxdfSamples),
          m_allowCaustics(allowCaustics) {}

    std::string name() const override { return "PxrPathTracer"; }
    void describeEffects(Scene const& scene, EffectReport& report) const override;
    void integrate(ShadingContextImpl const& ctx, RixBxdf& bxdf, RixRNG& rng, IntegratorServices& services,
                   RtColorRGB* radiance) override;

private:
    /// Shades one batch of path vertices; throughput[i] is the path's weight
    /// so far, diffusePath[i] whether it has bounced off a diffuse lobe.
    void vertex(ShadingContextImpl const& ctx, RixBxdf& bxdf, RixRNG& rng, IntegratorServices& services,
                RtColorRGB const* throughput, bool const* diffusePath, RtColorRGB* radiance, int depth);

    int m_maxPathLength;
    int m_numLightSamples;
    int m_numBxdfSamples;
    bool m_allowCaustics;
};

}  // namespace bxdflab
