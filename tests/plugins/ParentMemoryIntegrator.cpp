// A test integrator that uses its batch the way the Rix API allows but the
// course's integrators do not: from inside a TraceIndirect callback it asks the
// *outer* batch for a builtin for the first time, and allocates from it. Both
// must stay valid for as long as that batch does. After the trace it fills
// the memory the renderer shares between batches with other values, then
// checks what it got is unchanged:
//   white  all still as they were      red   something changed under it
//   blue   the callback never ran (no surface above to shade)
#include <vector>

#include "RixIntegrator.h"
#include "RixShadingUtils.h"

namespace {

class ParentMemory : public RixIntegrator {
public:
    void DescribeEffects(int, RixEffects& effects) const override {
        effects.Simulate("one indirect ray per point, along its normal (toward the viewer)");
    }

    void Integrate(RixShadingContext const& ctx, RixBxdf&, RixRNG& rng, RixIntegratorContext& ictx,
                   RtColorRGB* radiance) override {
        int const n = ctx.numPts;
        RtNormal3 const* Nn;
        RtVector3 const* Vn;
        ctx.GetBuiltinVar(RixShadingContext::k_Nn, &Nn);
        ctx.GetBuiltinVar(RixShadingContext::k_Vn, &Vn);
        RixShadingContext::Allocator pool(&ctx);
        int* index = pool.AllocFor<int>(n);
        RtVector3* dir = pool.AllocFor<RtVector3>(n);
        bool* shade = pool.AllocFor<bool>(n);
        RixRNG::SampleCtx* samples = pool.AllocFor<RixRNG::SampleCtx>(n);
        for (int i = 0; i < n; ++i) {
            index[i] = i;
            dir[i] = RixGetForwardFacingNormal(Vn[i], Nn[i]);
            shade[i] = true;
            samples[i] = rng.sampleCtxArray[i].NewDomain(7);
        }

        float const* uInside = nullptr;  // the outer batch's u, first asked for in the callback
        float* keptInside = nullptr;     // memory of the outer batch, allocated in the callback
        std::vector<float> uSeen;
        ictx.TraceIndirect(ctx, n, index, dir, shade, samples, nullptr, [&](RixShadeBatch& batch) {
            RtPoint3 const* childP;  // the inner batch's own builtins, as any integrator asks
            batch.ctx.GetBuiltinVar(RixShadingContext::k_P, &childP);
            if (uInside) return;
            ctx.GetBuiltinVar(RixShadingContext::k_u, &uInside);
            uSeen.assign(uInside, uInside + n);
            keptInside = pool.AllocFor<float>(n);
            for (int i = 0; i < n; ++i) keptInside[i] = static_cast<float>(i) + 0.5f;
        });
        if (!uInside) {
            for (int i = 0; i < n; ++i) radiance[i] = RtColorRGB(0, 0, 1);
            return;
        }
        // Memory of this batch, taken now: where the callback's would have been reused.
        for (int round = 0; round < 64; ++round) {
            float* scribble = pool.AllocFor<float>(1024);
            for (int k = 0; k < 1024; ++k) scribble[k] = -7.0f;
        }
        float const* uAfter;
        ctx.GetBuiltinVar(RixShadingContext::k_u, &uAfter);
        for (int i = 0; i < n; ++i) {
            bool const same = uAfter == uInside && uAfter[i] == uSeen[static_cast<size_t>(i)] &&
                              keptInside[i] == static_cast<float>(i) + 0.5f;
            radiance[i] = same ? RtColorRGB(1, 1, 1) : RtColorRGB(1, 0, 0);
        }
    }
};

}  // namespace

RIX_INTEGRATORCREATE {
    (void)params;
    (void)messages;
    return new ParentMemory;
}

RIX_INTEGRATORDESTROY { delete integrator; }
