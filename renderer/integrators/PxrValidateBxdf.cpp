// PxrValidateBxdf: a picture of whether a Bxdf's sampling, evaluation and
// pdfs agree. For each shade point it takes numSamples directions and writes
//   red    mean of luminance(W) / FPdf over GenerateSample's directions
//   green  the same directions re-evaluated with EvaluateSample, counted only
//          where EvaluateSample returns the same W and FPdf as GenerateSample
//   blue   cosine-distributed directions chosen by the integrator, evaluated
//          with EvaluateSample and divided by the cosine pdf
// All three estimate the directional albedo, so a correct Bxdf gives three
// equal channels (at most 1 for a white energy-conserving Bxdf). Red
// differing from blue points at a pdf that does not match the sampling;
// green darker than red at EvaluateSample disagreeing with GenerateSample.
//   int numSamples [4]
#include <cmath>

#include "RixBxdfScratch.h"
#include "common/Params.h"

using namespace bxdflab;

namespace {

bool agree(float a, float b) { return std::fabs(a - b) <= 1e-3f * std::fmax(std::fabs(a), std::fabs(b)) + 1e-12f; }

class ValidateBxdf : public RixIntegrator {
public:
    explicit ValidateBxdf(int numSamples) : m_numSamples(numSamples) {}

    void DescribeEffects(int, RixEffects& effects) const override {
        effects.Simulate("camera rays");
        effects.Simulate("Bxdf validation (GenerateSample, EvaluateSample, cosine directions)");
        effects.Skip("light sampling and shadow rays", "PxrValidateBxdf looks at the Bxdf alone");
        effects.Skip("indirect rays", "PxrValidateBxdf looks at the Bxdf alone");
    }

    void Integrate(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                   RtColorRGB* radiance) override {
        int const n = ctx.numPts;
        if (!bxdf.GetAllLobeTraits().HasAny()) return;
        RixBxdfScratch generated(ctx), evaluated(ctx);
        RtNormal3 const* Nn;
        RtVector3 const* Vn;
        ctx.GetBuiltinVar(RixShadingContext::k_Nn, &Nn);
        ctx.GetBuiltinVar(RixShadingContext::k_Vn, &Vn);
        RtFloat2* xi = RixShadingContext::Allocator(&ctx).AllocFor<RtFloat2>(n);
        float* cosinePdf = RixShadingContext::Allocator(&ctx).AllocFor<float>(n);
        float const scale = 1.0f / static_cast<float>(m_numSamples);

        for (int s = 0; s < m_numSamples; ++s) {
            // Red and green: the Bxdf's own samples, then the same directions re-evaluated.
            generated.generate(bxdf, rng, ictx);
            for (int i = 0; i < n; ++i) evaluated.Ln[i] = generated.Ln[i];
            evaluated.evaluate(bxdf, rng, ictx);
            for (int i = 0; i < n; ++i) {
                if (!generated.lobeSampled[i].GetValid() || !(generated.FPdf[i] > 0.0f)) continue;
                float w = generated.W.SumAtPoint(i).Luminance();
                float red = w / generated.FPdf[i];
                if (!std::isfinite(red)) {
                    ictx.CountNonFinite();
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
            evaluated.evaluate(bxdf, rng, ictx);
            for (int i = 0; i < n; ++i) {
                if (!(cosinePdf[i] > 0.0f)) continue;
                float blue = evaluated.W.SumAtPoint(i).Luminance() / cosinePdf[i];
                if (std::isfinite(blue))
                    radiance[i].b += blue * scale;
                else
                    ictx.CountNonFinite();
            }
        }
    }

private:
    int m_numSamples;
};

}  // namespace

RIX_INTEGRATORCREATE {
    int numSamples;
    if (!ReadInt(params, messages, "numSamples", 4, 1, 4096, numSamples)) return nullptr;
    return new ValidateBxdf(numSamples);
}

RIX_INTEGRATORDESTROY { delete integrator; }
