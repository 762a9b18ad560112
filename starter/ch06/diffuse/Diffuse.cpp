#include "Todo.h"
#include "Diffuse.h"

#include "RixShadingUtils.h"

RixBXLobeSampled g_diffuseLobe;
RixBXLobeTraits g_diffuseTraits;

Diffuse::Diffuse(RixShadingContext const* sc, RixBxdfFactory* factory, RtColorRGB const* albedo, int samplingMode)
    : RixBxdf(sc, factory), m_albedo(albedo), m_samplingMode(samplingMode) {
    // Builtins are arrays with one entry per shade point.
    sc->GetBuiltinVar(RixShadingContext::k_Nn, &m_Nn);
    sc->GetBuiltinVar(RixShadingContext::k_Ngn, &m_Ngn);
    sc->GetBuiltinVar(RixShadingContext::k_Vn, &m_Vn);
}

bool Diffuse::evaluate(int i, RtVector3 const& Ln, RtColorRGB& weight, float& fpdf, float& rpdf) const {
    float NdV;
    RtNormal3 Nf = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i], &NdV);
    RtNormal3 Ngf = RixGetForwardFacingNormal(m_Vn[i], m_Ngn[i]);
    // TODO: the Lambertian weight and pdfs for direction Ln.
    //  1. NdL = Nf.Dot(Ln). If NdL <= 0, or Ln is below the geometric normal
    //     (Ngf.Dot(Ln) <= 0), Ln gets no light: set everything to 0, return false.
    //  2. fpdf = the cosine-sampling pdf of Ln:  NdL / pi   (use F_INVPI)
    //     rpdf = the same for V:                 NdV / pi
    //  3. weight = W = f * cos(theta_L) = (albedo / pi) * NdL   (albedo: m_albedo[i])
    PIXAR_ARGUSED(Ln);
    PIXAR_ARGUSED(NdV);
    PIXAR_ARGUSED(Nf);
    PIXAR_ARGUSED(Ngf);
    RIX_TODO(shadingCtx, "Diffuse::evaluate");
    weight = RtColorRGB(0.0f);
    fpdf = rpdf = 0.0f;
    return false;
}

void Diffuse::GenerateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG* rng,
                             RixBXLobeSampled* lobeSampled, RtVector3* Ln, RixBXLobeWeights& W, float* FPdf,
                             float* RPdf, RtColorRGB*) {
    int const n = shadingCtx->numPts;
    RtColorRGB* weights = W.AddActiveLobe(g_diffuseLobe);
    RixBXLobeTraits const all = GetAllLobeTraits();

    // One 2-D random sample per point, drawn for the whole batch at once.
    RtFloat2* xi = static_cast<RtFloat2*>(RixAlloca(sizeof(RtFloat2) * n));
    rng->DrawSamples2D(xi);

    for (int i = 0; i < n; ++i) {
        lobeSampled[i].SetValid(false);
        FPdf[i] = RPdf[i] = 0.0f;
        if (!(all & lobesWanted[i] & g_diffuseTraits).HasAny()) continue;  // the integrator wants no diffuse

        // TODO: choose a cosine-distributed direction around the forward-facing
        // normal with RixCosDirectionalDistribution(xi[i], Nf, Ln[i], NdL), then
        // fill its weight and pdfs with evaluate(i, Ln[i], weights[i], FPdf[i], RPdf[i]);
        // if evaluate returns false, leave the sample invalid (continue).
        RIX_TODO(shadingCtx, "Diffuse::GenerateSample");
        PIXAR_ARGUSED(weights);
        Ln[i] = m_Nn[i];
        continue;  // an invalid sample: the integrator ignores it
        lobeSampled[i] = g_diffuseLobe;
        lobeSampled[i].SetValid(true);
    }
}

void Diffuse::EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG*,
                             RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln, RixBXLobeWeights& W, float* FPdf,
                             float* RPdf) {
    RtColorRGB* weights = W.AddActiveLobe(g_diffuseLobe);
    RixBXLobeTraits const all = GetAllLobeTraits();
    for (int i = 0; i < shadingCtx->numPts; ++i) {
        lobesEvaluated[i].SetNone();
        FPdf[i] = RPdf[i] = 0.0f;
        if (!(all & lobesWanted[i] & g_diffuseTraits).HasAny()) continue;
        if (evaluate(i, Ln[i], weights[i], FPdf[i], RPdf[i])) {
            lobesEvaluated[i] |= g_diffuseTraits;
            lobesEvaluated[i].SetValid(true);
        }
    }
}

void Diffuse::EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const& lobesWanted, RixRNG*, int index,
                                     int numSamples, RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln,
                                     RixBXLobeWeights& W, float* FPdf, float* RPdf) {
    RtColorRGB* weights = W.AddActiveLobe(g_diffuseLobe);
    bool wanted = (GetAllLobeTraits() & lobesWanted & g_diffuseTraits).HasAny();
    for (int s = 0; s < numSamples; ++s) {
        lobesEvaluated[s].SetNone();
        FPdf[s] = RPdf[s] = 0.0f;
        if (wanted && evaluate(index, Ln[s], weights[s], FPdf[s], RPdf[s])) {
            lobesEvaluated[s] |= g_diffuseTraits;
            lobesEvaluated[s].SetValid(true);
        }
    }
}
