// Direct lighting, shared by the PxrDirectLighting and PxrDefault plugins
// (and the light sampling by PxrPathTracer). Read DirectLighting.cpp as the
// course's example integrator.
#pragma once

#include "RixBxdfScratch.h"
#include "RixIntegrator.h"

namespace bxdflab {

/// A Bxdf's weight toward one direction with its diffuse and specular lobes'
/// parts kept apart: a light's "diffuse" and "specular" multipliers scale them
/// (RixLightSample), and a ray traced along a Bxdf sample learns which light it
/// reaches, and so the multipliers, only after it has been traced.
struct LobeWeight {
    RtColorRGB all;       ///< every lobe (W.SumAtPoint)
    RtColorRGB diffuse;   ///< the diffuse lobes' part of it
    RtColorRGB specular;  ///< the specular lobes' part of it
    RtColorRGB user;      ///< the user lobes' part, which the multipliers leave alone

    /// Point i's weight in W.
    static LobeWeight at(RixBXLobeWeights const& W, int i) {
        LobeWeight w{W.SumAtPoint(i), RtColorRGB(0.0f), RtColorRGB(0.0f), RtColorRGB(0.0f)};
        for (int k = 0; k < W.GetNumActiveLobes(); ++k) {
            RixBXLobeSampled const lobe = W.GetActiveLobe(k);
            (lobe.GetDiffuse() ? w.diffuse : lobe.GetSpecular() ? w.specular : w.user) += W.GetActiveLobeWeights(k)[i];
        }
        return w;
    }
    /// What the Bxdf takes of light with these multipliers (exactly `all` at the usual 1 and 1).
    RtColorRGB litBy(float diffuseMultiplier, float specularMultiplier) const {
        if (diffuseMultiplier == 1.0f && specularMultiplier == 1.0f) return all;
        return diffuse * diffuseMultiplier + specular * specularMultiplier + user;
    }
    LobeWeight operator*(RtColorRGB const& c) const { return {all * c, diffuse * c, specular * c, user * c}; }
    LobeWeight operator/(float s) const { return {all / s, diffuse / s, specular / s, user / s}; }
};

/// The shadow rays of one round of samples, gathered to be traced together
/// (RixIntegratorContext's batched Unoccluded and VisibleLights): ray k leaves
/// point[k] toward dir[k]; toward a sampled light it must stay clear for
/// distance[k] (toward a Bxdf sample, VisibleLights finds the light).
struct ShadowRays {
    ShadowRays(RixShadingContext::Allocator& pool, int size)
        : point(pool.AllocFor<int>(size)),
          dir(pool.AllocFor<RtVector3>(size)),
          distance(pool.AllocFor<float>(size)),
          weight(pool.AllocFor<LobeWeight>(size)),
          clear(pool.AllocFor<bool>(size)) {}
    void add(int i, RtVector3 const& towards, float reach, LobeWeight const& W) {
        point[count] = i;
        dir[count] = towards;
        distance[count] = reach;
        weight[count] = W;
        ++count;
    }
    int count = 0;
    int* point;
    RtVector3* dir;
    float* distance;
    LobeWeight* weight;  ///< what the light found is multiplied by (the Bxdf's W for that direction, times any
                         ///< path throughput), before the light's multipliers
    bool* clear;
};

/// One sample on `light` for every point of a batch, as next-event estimation
/// takes it: draws xi, sets sample[i] to a point on the light seen from P[i]
/// (with no radiance where light linking turns the light off for point i),
/// evaluates the Bxdf toward it into q, and fills `shadow` with a ray for each
/// point the light would add to, ready for Unoccluded.
void sampleLight(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx, int light,
                 RtPoint3 const* P, RtFloat2* xi, RixLightSample* sample, RixBxdfScratch& q, ShadowRays& shadow);

/// Next-event estimation for a batch: adds to radiance[i] the light arriving
/// straight from the lights and reflected toward the viewer, times
/// throughput[i] (or 1 when throughput is null), from numLightSamples samples
/// per light, MIS-weighted against numBxdfSamples Bxdf samples.
void addLightSamples(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                     int numLightSamples, int numBxdfSamples, RtColorRGB const* throughput, RtColorRGB* radiance);

/// The second half of Bxdf sampling for a round: traces the gathered rays
/// along q's sampled directions (RixIntegratorContext::VisibleLights) and adds
/// to radiance[point[k]] the light each finds times its weight, MIS-weighted
/// against numLightSamples light samples (hit: room for rays.count answers).
void addLightsFound(RixShadingContext const& ctx, RixIntegratorContext& ictx, RixBxdfScratch const& q,
                    ShadowRays const& rays, RixLightHit* hit, int numLightSamples, int numBxdfSamples,
                    RtColorRGB* radiance);

/// Adds a contribution, or reports it when it is not finite (a Bxdf bug).
void accumulate(RixIntegratorContext& ictx, RtColorRGB& radiance, RtColorRGB const& contribution);

/// Adds what the batch's surfaces emit (EmitLocal) times throughput[i], the way
/// a path that meets an emissive surface counts it; returns whether the Bxdf has
/// lobes to go on with (a purely emissive one has none).
bool addEmission(RixShadingContext const& ctx, RixBxdf& bxdf, RixIntegratorContext& ictx,
                 RtColorRGB const* throughput, RtColorRGB* radiance);

class DirectLighting : public RixIntegrator {
public:
    /// With headlight set, the lights are PxrDefault's light at the camera (a
    /// point light no Bxdf sample can hit), so only light samples are taken.
    DirectLighting(int numLightSamples, int numBxdfSamples, bool headlight)
        : m_numLightSamples(numLightSamples), m_numBxdfSamples(headlight ? 0 : numBxdfSamples), m_headlight(headlight) {}

    bool WantsHeadlight() const override { return m_headlight; }
    void DescribeEffects(int numLights, RixEffects& effects) const override;
    void Integrate(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                   RtColorRGB* radiance) override;

private:
    int m_numLightSamples;
    int m_numBxdfSamples;
    bool m_headlight;
};

}  // namespace bxdflab
