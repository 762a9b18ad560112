// A diffuse Bxdf in the course text's style, with everything that style
// leaves to the renderer (rix-api.md, "What code in the course text's style
// leaves to the renderer"):
//  - one file: factory and Bxdf, statics for the lobe;
//  - one-sided: it tests N.V > 0 on the raw normal and declares outside reflection only;
//  - GenerateSample only calls lobeSampled[i].SetValid(true), without assigning
//    the lobe, and leaves pdfs and weights unwritten where it does not sample;
//  - EvaluateSample leaves lobesEvaluated and the pdfs alone where it does not evaluate;
//  - the factory overrides every member RenderMan 24's header has, as empty ones.
// It builds with a plain Makefile against $(RMANTREE)/include with -std=c++14
// (tests/plugins/textstyle/Makefile), and in the project's build.
#include <new>
#include <vector>

#include "RixBxdf.h"
#include "RixShadingUtils.h"

static RixBXLobeSampled s_diffLobe;
static RixBXLobeTraits s_diffTraits;

class TextDiffuse : public RixBxdf {
public:
    TextDiffuse(RixShadingContext const* sc, RixBxdfFactory* bx, RtColorRGB const* diff) : RixBxdf(sc, bx), m_diff(diff) {
        sc->GetBuiltinVar(RixShadingContext::k_Nn, &m_Nn);
        sc->GetBuiltinVar(RixShadingContext::k_Vn, &m_Vn);
    }

    virtual RixBXEvaluateDomain GetEvaluateDomain() { return k_RixBXOutsideReflect; }
    virtual void GetAggregateLobeTraits(RixBXLobeTraits* t) { *t = s_diffTraits; }

    virtual void GenerateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG* rng,
                                RixBXLobeSampled* lobeSampled, RtVector3* Ln, RixBXLobeWeights& W, float* FPdf,
                                float* RPdf, RtColorRGB*) {
        RtInt nPts = shadingCtx->numPts;
        RtColorRGB* diffW = W.AddActiveLobe(s_diffLobe);
        RtFloat2* xi = (RtFloat2*)RixAlloca(sizeof(RtFloat2) * nPts);
        rng->DrawSamples2D(xi);
        for (int i = 0; i < nPts; i++) {
            if (!(lobesWanted[i] & s_diffTraits).HasAny()) continue;
            RtNormal3 Nn = m_Nn[i];
            float NdV = Nn.Dot(m_Vn[i]);
            if (NdV <= 0.0f) continue;  // seen from below: no sample (one-sided)
            float NdL;
            RixCosDirectionalDistribution(xi[i], Nn, Ln[i], NdL);
            FPdf[i] = NdL * F_INVPI;
            RPdf[i] = NdV * F_INVPI;
            diffW[i] = m_diff[i] * FPdf[i];
            lobeSampled[i].SetValid(true);
        }
    }

    virtual void EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG*,
                                RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln, RixBXLobeWeights& W,
                                float* FPdf, float* RPdf) {
        RtInt nPts = shadingCtx->numPts;
        RtColorRGB* diffW = W.AddActiveLobe(s_diffLobe);
        for (int i = 0; i < nPts; i++) {
            if (!(lobesWanted[i] & s_diffTraits).HasAny()) continue;
            float NdV = m_Nn[i].Dot(m_Vn[i]);
            float NdL = m_Nn[i].Dot(Ln[i]);
            if (NdV <= 0.0f || NdL <= 0.0f) continue;
            FPdf[i] = NdL * F_INVPI;
            RPdf[i] = NdV * F_INVPI;
            diffW[i] = m_diff[i] * FPdf[i];
            lobesEvaluated[i] |= s_diffTraits;
        }
    }

    virtual void EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const& lobesWanted, RixRNG*, int index,
                                        int numSamples, RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln,
                                        RixBXLobeWeights& W, float* FPdf, float* RPdf) {
        RtColorRGB* diffW = W.AddActiveLobe(s_diffLobe);
        if (!(lobesWanted & s_diffTraits).HasAny()) return;
        float NdV = m_Nn[index].Dot(m_Vn[index]);
        for (int s = 0; s < numSamples; s++) {
            float NdL = m_Nn[index].Dot(Ln[s]);
            if (NdV <= 0.0f || NdL <= 0.0f) continue;
            FPdf[s] = NdL * F_INVPI;
            RPdf[s] = NdV * F_INVPI;
            diffW[s] = m_diff[index] * FPdf[s];
            lobesEvaluated[s] |= s_diffTraits;
        }
    }

private:
    RtColorRGB const* m_diff;
    RtNormal3 const* m_Nn;
    RtVector3 const* m_Vn;
};

class TextDiffuseFactory : public RixBxdfFactory {
public:
    enum paramId { k_diffuseColor = 0 };
    TextDiffuseFactory() : m_diffuseColor(0.5f, 0.5f, 0.5f) {}

    virtual int Init(RixContext&, RtUString const) { return 0; }
    virtual void Finalize(RixContext&) {}
    virtual RixSCParamInfo const* GetParamTable() {
        static RixSCParamInfo s_ptable[] = {RixSCParamInfo(RtUString("diffuseColor"), k_RixSCColor, k_RixSCScatterInput),
                                            RixSCParamInfo()};
        return &s_ptable[0];
    }
    virtual void Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const*) {
        if (syncMsg == k_RixSCRenderBegin) {
            s_diffLobe = RixBXLookupLobeByName(ctx, false, false, true, false, 0, "Diffuse");
            s_diffTraits = RixBXLobeTraits(s_diffLobe);
        }
    }
    virtual void CreateInstanceData(RixContext&, RtUString const, RixParameterList const*, InstanceData*) {}
    virtual void SynchronizeInstanceData(RixContext&, RtUString const, RixParameterList const*, uint32_t, InstanceData*) {}
    virtual int GetInstanceHints(RtPointer) const { return k_TriviallyOpaque; }
    virtual RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const&, RixSCShadingMode, void*,
                                  RtPointer) {
        RtColorRGB const* diff;
        sCtx->EvalParam(k_diffuseColor, -1, &diff, &m_diffuseColor, true);
        RixShadingContext::Allocator pool(sCtx);
        void* mem = pool.AllocForBxdf<TextDiffuse>(1);
        return new (mem) TextDiffuse(sCtx, this, diff);
    }
    virtual void EndScatter(RixBxdf*) {}
    virtual RixOpacity* BeginOpacity(RixShadingContext const*, RixSCShadingMode, void*, RtPointer) { return NULL; }
    virtual void EndOpacity(RixOpacity*) {}
    virtual RixVolumeIntegrator* BeginInterior(RixShadingContext const*, RixSCShadingMode, void*, RtPointer) {
        return NULL;
    }
    virtual RixVolumeIntegrator* BeginSubsurface(RixShadingContext const*, RixSCShadingMode, void*, RtPointer) {
        return NULL;
    }
    virtual void EndInterior(RixVolumeIntegrator*) {}
    virtual void EndSubsurface(RixVolumeIntegrator*) {}
    virtual void RegisterTemporalVolumeParams(RtPointer, std::vector<RtInt>&) const {}

private:
    RtColorRGB m_diffuseColor;
};

extern "C" PRMANEXPORT RixBxdfFactory* CreateRixBxdfFactory(const char* hint) {
    PIXAR_ARGUSED(hint);
    return new TextDiffuseFactory();
}

extern "C" PRMANEXPORT void DestroyRixBxdfFactory(RixBxdfFactory* bxdf) { delete (TextDiffuseFactory*)bxdf; }
