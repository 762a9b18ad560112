#include "integrate/ValidateBxdf.h"

#include <cmath>

#include "RixShadingUtils.h"
#include "integrate/BxdfScratch.h"

namespace bxdflab {
namespace {

bool agree(float a, float b) { return std::fabs(a - b) <= 1e-3f * std::fmax(std::fabs(a), std::fabs(b)) + 1e-12f; }

}  // namespace

void ValidateBxdf::describeEffects(Scene const&, EffectReport& report) const {
    report.simulate("camera rays");
    report.simulate("Bxdf validation (" + std::to_string(m_numSamples) + " directions per camera sample)");
    report.skip("light sampling and shadow rays", "PxrValidateBxdf looks at the Bxdf alone");
    report.skip("indirect rays", "PxrValidateBxdf looks at the Bxdf alone");
}

void ValidateBxdf::integrate(ShadingContextImpl const& ctx, RixBxdf& bxdf, RixRNG& rng, IntegratorServices& services,
                             RtColorRGB* radiance) {
    int const n = ctx.numPts;
    if (!bxdf.GetAllLobeTraits().HasAny()) return;
    BxdfScratch generated(ctx), evaluated(ctx);
    RtNormal3 const* Nn;
    RtVector3 const* Vn;
    ctx.GetBuiltinVar(RixShadingContext::k_Nn, &Nn);
    ctx.GetBuiltinVar(RixShadingContext::k_Vn, &Vn);
    RtFloat2* xi = RixShadingContext::Allocator(&ctx).AllocFor<RtFloat2>(n);
    float* cosinePdf = RixShadingContext::Allocator(&ctx).AllocFor<float>(n);
    float const scale = 1.0f / static_cast<float>(m_numSamples);

    for (int s = 0; s < m_numSamples; ++s) {
        // Red and green: the Bxdf's own samples, then the same directions re-evaluated.
        generated.generate(bxdf, rng);
        for (int i = 0; i < n; ++i) evaluated.Ln[i] = generated.Ln[i];
        evaluated.evaluate(bxdf, rng);
        for (int i = 0; i < n; ++i) {
            if (!generated.lobeSampled[i].GetValid() || !(generated.FPdf[i] > 0.0f)) continue;
            float w = generated.W.SumAtPoint(i).Luminance();
            float red = w / generated.FPdf[i];
            if (!std::isfinite(red)) {
                services.countNonFinite();
                continue;
            }
            radiance[i].r += red * scale;
            if (agree(evaluated.W.SumAtPoint(i).Luminance(), w) && agree(evaluated.FPdf[i], generated.FPdf[i]))
                radiance[i].g += red * scale;
        }
        // Blue: the integrator's own cosine-distributed directions.
        rng.DrawSamples2D(xi);
        for (int i = 0; i < n; ++i) {
            float cosTheta;
            RixCosDirectionalDistribution(xi[i], RixGetForwardFacingNormal(Vn[i], Nn[i]), evaluated.Ln[i], cosTheta);
            cosinePdf[i] = cosTheta * F_INVPI;  // the integrator's pdf, not the Bxdf's
        }
        evaluated.evaluate(bxdf, rng);
        for (int i = 0; i < n; ++i) {
            if (!(cosinePdf[i] > 0.0f)) continue;
            float blue = evaluated.W.SumAtPoint(i).Luminance() / cosinePdf[i];
            if (std::isfinite(blue))
                radiance[i].b += blue * scale;
            else
                services.countNonFinite();
        }
    }
}

DebugShadingContext::DebugShadingContext(std::string channel, SourceLocation const& where) : m_channel(std::move(channel)) {
    static const char* channels[] = {"Nn", "Ngn", "Vn", "Tn", "P", "dPdu", "dPdv", "VLen", "UV", "ST", "InsideOutside"};
    for (const char* c : channels)
        if (m_channel == c) return;
    std::string list;
    for (const char* c : channels) list += std::string(list.empty() ? "" : ", ") + c;
    throw RibError(where, "PxrDebugShadingContext: unknown viewchannel \"" + m_channel + "\" (choose one of " + list + ")");
}

void DebugShadingContext::describeEffects(Scene const&, EffectReport& report) const {
    report.simulate("camera rays");
    report.simulate("shading-context view of " + m_channel);
    report.skip("light sampling and shadow rays", "PxrDebugShadingContext shows geometry only");
    report.skip("indirect rays", "PxrDebugShadingContext shows geometry only");
}

void DebugShadingContext::integrate(ShadingContextImpl const& ctx, RixBxdf&, RixRNG&, IntegratorServices&,
                                    RtColorRGB* radiance) {
    int const n = ctx.numPts;
    auto asColor = [](RtFloat3 const& v) { return RtColorRGB(0.5f + 0.5f * v.x, 0.5f + 0.5f * v.y, 0.5f + 0.5f * v.z); };
    auto showVector = [&](RixShadingContext::BuiltinId id) {
        RtVector3 const* values;
        ctx.GetBuiltinVar(id, &values);
        for (int i = 0; i < n; ++i) radiance[i] = asColor(values[i]);
    };
    auto showPair = [&](RixShadingContext::BuiltinId a, RixShadingContext::BuiltinId b) {
        float const *x, *y;
        ctx.GetBuiltinVar(a, &x);
        ctx.GetBuiltinVar(b, &y);
        for (int i = 0; i < n; ++i) radiance[i] = RtColorRGB(x[i], y[i], 0.0f);
    };
    if (m_channel == "Nn") showVector(RixShadingContext::k_Nn);
    else if (m_channel == "Ngn") showVector(RixShadingContext::k_Ngn);
    else if (m_channel == "Vn") showVector(RixShadingContext::k_Vn);
    else if (m_channel == "Tn") showVector(RixShadingContext::k_Tn);
    else if (m_channel == "P") showVector(RixShadingContext::k_P);
    else if (m_channel == "dPdu") showVector(RixShadingContext::k_dPdu);
    else if (m_channel == "dPdv") showVector(RixShadingContext::k_dPdv);
    else if (m_channel == "UV") showPair(RixShadingContext::k_u, RixShadingContext::k_v);
    else if (m_channel == "ST") showPair(RixShadingContext::k_s, RixShadingContext::k_t);
    else if (m_channel == "VLen") {
        float const* length;
        ctx.GetBuiltinVar(RixShadingContext::k_VLen, &length);
        for (int i = 0; i < n; ++i) radiance[i] = RtColorRGB(length[i]);
    } else {  // InsideOutside
        RtVector3 const* Vn;
        RtNormal3 const* Ngn;
        ctx.GetBuiltinVar(RixShadingContext::k_Vn, &Vn);
        ctx.GetBuiltinVar(RixShadingContext::k_Ngn, &Ngn);
        for (int i = 0; i < n; ++i) radiance[i] = Vn[i].Dot(Ngn[i]) >= 0.0f ? RtColorRGB(0, 1, 0) : RtColorRGB(1, 0, 0);
    }
}

void Occlusion::describeEffects(Scene const&, EffectReport& report) const {
    report.simulate("camera rays");
    report.simulate("occlusion rays (" + std::to_string(m_numSamples) + " per camera sample)");
    report.skip("lights and Bxdfs", "PxrOcclusion shows how open each point is to the sky");
}

void Occlusion::integrate(ShadingContextImpl const& ctx, RixBxdf&, RixRNG& rng, IntegratorServices& services,
                          RtColorRGB* radiance) {
    int const n = ctx.numPts;
    RtPoint3 const* P;
    RtNormal3 const *Nn, *Ngn;
    RtVector3 const* Vn;
    ctx.GetBuiltinVar(RixShadingContext::k_P, &P);
    ctx.GetBuiltinVar(RixShadingContext::k_Nn, &Nn);
    ctx.GetBuiltinVar(RixShadingContext::k_Ngn, &Ngn);
    ctx.GetBuiltinVar(RixShadingContext::k_Vn, &Vn);
    Vec3 const* pError = ctx.pError();
    RtFloat2* xi = RixShadingContext::Allocator(&ctx).AllocFor<RtFloat2>(n);
    for (int s = 0; s < m_numSamples; ++s) {
        rng.DrawSamples2D(xi);
        for (int i = 0; i < n; ++i) {
            RtNormal3 N = RixGetForwardFacingNormal(Vn[i], Nn[i]);
            RtVector3 dir;
            float cosTheta;
            RixCosDirectionalDistribution(xi[i], N, dir, cosTheta);
            Vec3 Ng = toVec3(RixGetForwardFacingNormal(Vn[i], Ngn[i]));
            if (glm::dot(toVec3(dir), Ng) <= 0.0f) continue;  // below the geometric surface: occluded
            if (services.unoccluded(toVec3(P[i]), pError[i], Ng, toVec3(dir), m_maxDistance))
                radiance[i] += RtColorRGB(1.0f / static_cast<float>(m_numSamples));
        }
    }
}

}  // namespace bxdflab
