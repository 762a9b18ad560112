// PxrOcclusion: ambient occlusion, the fraction of cosine-distributed
// directions that escape within maxDistance (white = fully open to the sky).
//   int numSamples [16]   float maxDistance [1e30]
#include <string>

#include "common/Params.h"

using namespace bxdflab;

namespace {

class Occlusion : public RixIntegrator {
public:
    Occlusion(int numSamples, float maxDistance) : m_numSamples(numSamples), m_maxDistance(maxDistance) {}

    void DescribeEffects(int, RixEffects& effects) const override {
        effects.Simulate("camera rays");
        effects.Simulate(("occlusion rays (" + std::to_string(m_numSamples) + " per camera sample)").c_str());
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
                float cosTheta;
                RixCosDirectionalDistribution(xi[i], RixGetForwardFacingNormal(Vn[i], Nn[i]), dir[rays], cosTheta);
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
    float m_maxDistance;
};

}  // namespace

RIX_INTEGRATORCREATE {
    int numSamples;
    if (!ReadInt(params, messages, "numSamples", 16, 1, 4096, numSamples)) return nullptr;
    float maxDistance = ReadFloat(params, "maxDistance", 1e30f);
    if (!(maxDistance > 0.0f)) {
        messages->Error("maxDistance must be positive");
        return nullptr;
    }
    return new Occlusion(numSamples, maxDistance);
}

RIX_INTEGRATORDESTROY { delete integrator; }
