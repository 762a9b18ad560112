// PxrOcclusion: ambient occlusion, the share of a point's sample directions
// that nothing blocks within maxDistance (white = fully open to the sky).
// RenderMan's parameters and defaults:
//   int   numSamples   [4]  occlusion rays per camera sample
//   int   distribution [1]  0 uniform over the hemisphere (every direction
//                           counts alike), 1 cosine (directions near the
//                           normal count more: what a matte surface under an
//                           even sky receives), 2 reflection (the cosine
//                           distribution turned to the mirror direction of
//                           the view, for reflection occlusion)
//   float maxDistance  [0]  occluders farther than this do not count;
//                           0 (or less): no limit
//   float cosineSpread [1], float falloff [0], int useAlbedo [0]:
//                           read, and only their defaults are rendered (a
//                           warning says so for any other value)
// Directions below the geometric surface never reach the sky: they count as
// blocked, without a ray.
#include <string>

#include "common/Params.h"

using namespace bxdflab;

namespace {

enum Distribution { k_uniform = 0, k_cosine = 1, k_reflection = 2 };

class Occlusion : public RixIntegrator {
public:
    Occlusion(int numSamples, Distribution distribution, float maxDistance)
        : m_numSamples(numSamples), m_distribution(distribution), m_maxDistance(maxDistance) {}

    void DescribeEffects(int, RixEffects& effects) const override {
        static char const* const names[] = {"uniform", "cosine", "reflection"};
        effects.Simulate("camera rays");
        effects.Simulate(("occlusion rays (" + std::to_string(m_numSamples) + " per camera sample, " +
                          names[m_distribution] + " distribution)")
                             .c_str());
        effects.Skip("lights and Bxdfs", "PxrOcclusion shows how open each point is to the sky");
    }

    void Integrate(RixShadingContext const& ctx, RixBxdf&, RixRNG& rng, RixIntegratorContext& ictx,
                   RtColorRGB* radiance) override {
        int const n = ctx.numPts;
        RtNormal3 const *Nn, *Ngn;
        RtVector3 const* Vn;
        ctx.GetBuiltinVar(RixShadingContext::k_Nn, &Nn);
        ctx.GetBuiltinVar(RixShadingContext::k_Ngn, &Ngn);
        ctx.GetBuiltinVar(RixShadingContext::k_Vn, &Vn);
        RixShadingContext::Allocator pool(&ctx);
        RtFloat2* xi = pool.AllocFor<RtFloat2>(n);
        // This round's rays (ray k from point[k] toward dir[k]), traced together.
        int* point = pool.AllocFor<int>(n);
        RtVector3* dir = pool.AllocFor<RtVector3>(n);
        float* reach = pool.AllocFor<float>(n);
        bool* clear = pool.AllocFor<bool>(n);
        RtColorRGB const share(1.0f / static_cast<float>(m_numSamples));
        for (int s = 0; s < m_numSamples; ++s) {
            rng.DrawSamples2D(xi);
            int rays = 0;
            for (int i = 0; i < n; ++i) {
                RtNormal3 const N = RixGetForwardFacingNormal(Vn[i], Nn[i]);
                float cosTheta;
                if (m_distribution == k_uniform)
                    RixUniformDirectionalDistribution(xi[i], N, dir[rays], cosTheta);
                else if (m_distribution == k_cosine)
                    RixCosDirectionalDistribution(xi[i], N, dir[rays], cosTheta);
                else
                    RixCosDirectionalDistribution(xi[i], RtNormal3(RixReflect(-Vn[i], N)), dir[rays], cosTheta);
                if (RixGetForwardFacingNormal(Vn[i], Ngn[i]).Dot(dir[rays]) <= 0.0f) continue;  // below the surface
                point[rays] = i;
                reach[rays++] = m_maxDistance;
            }
            ictx.Unoccluded(ctx, rays, point, dir, reach, clear);
            for (int k = 0; k < rays; ++k)
                if (clear[k]) radiance[point[k]] += share;
        }
    }

private:
    int m_numSamples;
    Distribution m_distribution;
    float m_maxDistance;
};

}  // namespace

RIX_INTEGRATORCREATE {
    int numSamples, distribution, useAlbedo;
    if (!ReadInt(params, messages, "numSamples", 4, 1, 4096, numSamples) ||
        !ReadInt(params, messages, "distribution", k_cosine, k_uniform, k_reflection, distribution) ||
        !ReadInt(params, messages, "useAlbedo", 0, 0, 1, useAlbedo))
        return nullptr;
    float const maxDistance = ReadFloat(params, "maxDistance", 0.0f);
    if (float const spread = ReadFloat(params, "cosineSpread", 1.0f); spread != 1.0f)
        messages->Warning("cosineSpread %g is not used: the distribution keeps its spread of 1", spread);
    if (float const falloff = ReadFloat(params, "falloff", 0.0f); falloff != 0.0f)
        messages->Warning("falloff %g is not used: every occluder within maxDistance blocks fully", falloff);
    if (useAlbedo) messages->Warning("useAlbedo 1 is not used: occlusion is not tinted by the surfaces' albedo");
    // RenderMan's maxDistance 0 means no limit.
    return new Occlusion(numSamples, static_cast<Distribution>(distribution),
                         maxDistance > 0.0f ? maxDistance : 1e30f);
}

RIX_INTEGRATORDESTROY { delete integrator; }
