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
        RtFloat2* xi = RixShadingContext::Allocator(&ctx).AllocFor<RtFloat2>(n);
        RtColorRGB const share(1.0f / static_cast<float>(m_numSamples));
        for (int s = 0; s < m_numSamples; ++s) {
            rng.DrawSamples2D(xi);
            for (int i = 0; i < n; ++i) {
                RtVector3 dir;
                float cosTheta;
                RixCosDirectionalDistribution(xi[i], RixGetForwardFacingNormal(Vn[i], Nn[i]), dir, cosTheta);
                if (RixGetForwardFacingNormal(Vn[i], Ngn[i]).Dot(dir) <= 0.0f) continue;  // below the surface
                if (ictx.Unoccluded(ctx, i, dir, m_maxDistance)) radiance[i] += share;
            }
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
