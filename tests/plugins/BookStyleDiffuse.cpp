// A diffuse Bxdf written exactly the way the course text writes its plugins:
// one file, raw static lobe variables, the create/destroy pair spelled out
// with extern "C" PRMANEXPORT, EvalParam with promotion, RixAlloca for the
// random numbers, a 6-argument RixCosDirectionalDistribution with a shading
// basis built from Tn. The test suite renders with it to prove that
// book-style code compiles and behaves against this renderer's API.
#include <new>

#include "RixBxdf.h"
#include "RixShadingUtils.h"

static RixBXLobeSampled s_lobe;
static RixBXLobeTraits s_traits;

class BookDiffuse : public RixBxdf {
public:
    BookDiffuse(RixShadingContext const* sc, RixBxdfFactory* bx, RixBXLobeTraits const& lobesWanted,
                RtColorRGB const* diff, RtColorRGB const* emit)
        : RixBxdf(sc, bx), m_lobesWanted(lobesWanted), m_diff(diff), m_emit(emit) {
        sc->GetBuiltinVar(RixShadingContext::k_P, &m_P);
        sc->GetBuiltinVar(RixShadingContext::k_Nn, &m_Nn);
        sc->GetBuiltinVar(RixShadingContext::k_Tn, &m_Tn);
        sc->GetBuiltinVar(RixShadingContext::k_Vn, &m_Vn);
    }

    virtual RixBXEvaluateDomain GetEvaluateDomain() { return k_RixBXReflect; }
    virtual void GetAggregateLobeTraits(RixBXLobeTraits* t) { *t = s_traits; }

    virtual bool EmitLocal(RtColorRGB* result) {
        bool any = false;
        for (int i = 0; i < shadingCtx->numPts; i++) {
            result[i] = m_emit[i];
            any = any || !m_emit[i].IsBlack();
        }
        return any;
    }

    virtual void GenerateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG* rng,
                                RixBXLobeSampled* lobeSampled, RtVector3* Ln, RixBXLobeWeights& W, float* FPdf,
                                float* RPdf, RtColorRGB* compTrans) {
        PIXAR_ARGUSED(compTrans);
        RtInt nPts = shadingCtx->numPts;
        RixBXLobeTraits all = GetAllLobeTraits();
        RtColorRGB* w = W.AddActiveLobe(s_lobe);
        RtFloat2* xi = (RtFloat2*)RixAlloca(sizeof(RtFloat2) * nPts);
        rng->DrawSamples2D(xi);
        for (int i = 0; i < nPts; i++) {
            bool on = (all & lobesWanted[i] & s_traits).HasAny();
            if (!on) {
                lobeSampled[i].SetValid(false);
                continue;
            }
            RtNormal3 Nn = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i]);
            RtVector3 TX, TY;
            RixComputeShadingBasis(Nn, m_Tn[i], TX, TY);
            float NdL;
            RixCosDirectionalDistribution(xi[i], Nn, TX, TY, Ln[i], NdL);
            float NdV = Nn.Dot(m_Vn[i]);
            FPdf[i] = NdL * F_INVPI;
            RPdf[i] = NdV * F_INVPI;
            w[i] = m_diff[i] * FPdf[i];
            lobeSampled[i] = s_lobe;
#ifndef BOOK_ASSIGNS_ONLY  // RenderMan's examples stop at the assignment: the looked-up lobe is valid
            lobeSampled[i].SetValid(true);
#endif
        }
    }

    virtual void EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const* lobesWanted, RixRNG*,
                                RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln, RixBXLobeWeights& W,
                                float* FPdf, float* RPdf) {
        RtInt nPts = shadingCtx->numPts;
        RixBXLobeTraits all = GetAllLobeTraits();
        RtColorRGB* w = W.AddActiveLobe(s_lobe);
        for (int i = 0; i < nPts; i++) {
            lobesEvaluated[i].SetNone();
            FPdf[i] = RPdf[i] = 0.0f;
            if (!(all & lobesWanted[i] & s_traits).HasAny()) continue;
            RtNormal3 Nn = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i]);
            float NdL = Nn.Dot(Ln[i]);
            if (NdL <= 0.0f) continue;
            FPdf[i] = NdL * F_INVPI;
            RPdf[i] = Nn.Dot(m_Vn[i]) * F_INVPI;
            w[i] = m_diff[i] * FPdf[i];
            lobesEvaluated[i] |= s_traits;
            lobesEvaluated[i].SetValid(true);
        }
    }

    virtual void EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const&, RixRNG*, int index,
                                        int numSamples, RixBXLobeTraits* lobesEvaluated, RtVector3 const* Ln,
                                        RixBXLobeWeights& W, float* FPdf, float* RPdf) {
        RtColorRGB* w = W.AddActiveLobe(s_lobe);
        RtNormal3 Nn = RixGetForwardFacingNormal(m_Vn[index], m_Nn[index]);
        for (int s = 0; s < numSamples; s++) {
            float NdL = Nn.Dot(Ln[s]);
            lobesEvaluated[s].SetNone();
            FPdf[s] = RPdf[s] = 0.0f;
            if (NdL <= 0.0f) continue;
            FPdf[s] = NdL * F_INVPI;
            RPdf[s] = Nn.Dot(m_Vn[index]) * F_INVPI;
            w[s] = m_diff[index] * FPdf[s];
            lobesEvaluated[s] |= s_traits;
            lobesEvaluated[s].SetValid(true);
        }
    }

private:
    RixBXLobeTraits m_lobesWanted;
    RtColorRGB const* m_diff;
    RtColorRGB const* m_emit;
    RtPoint3 const* m_P;
    RtNormal3 const* m_Nn;
    RtVector3 const* m_Tn;
    RtVector3 const* m_Vn;
};

class BookDiffuseFactory : public RixBxdfFactory {
public:
    enum paramIds { k_emissiveColor = 0, k_diffuseColor, k_numParams };

    BookDiffuseFactory() : m_emissive_color(0.0f, 0.0f, 0.0f), m_diffuse_color(0.5f, 0.5f, 0.5f) {}

    virtual int Init(RixContext&, RtUString const) { return 0; }
    virtual void Finalize(RixContext&) {}
    virtual RixSCParamInfo const* GetParamTable() {
        static RixSCParamInfo s_ptable[] = {
            RixSCParamInfo(RtUString("emissive_color"), k_RixSCColor, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("diffuse_color"), k_RixSCColor, k_RixSCScatterInput),
            RixSCParamInfo()};
        return &s_ptable[0];
    }
    virtual void Synchronize(RixContext& ctx, RixSCSyncMsg syncMsg, RixParameterList const*) {
        if (syncMsg == k_RixSCRenderBegin) {
            s_lobe = RixBXLookupLobeByName(ctx, false, false, true, false, 0, "Diffuse");
            s_traits = RixBXLobeTraits(s_lobe);
        }
    }
    virtual void CreateInstanceData(RixContext& ctx, RtUString const handle, RixParameterList const* plist,
                                    InstanceData* idata) {
        PIXAR_ARGUSED(ctx);
        PIXAR_ARGUSED(handle);
        PIXAR_ARGUSED(plist);
        static int req = 1;
        idata->data = (void*)&req;
        idata->datalen = 1;
        idata->freefunc = NULL;
    }
    virtual int GetInstanceHints(RtPointer instanceData) const {
        PIXAR_ARGUSED(instanceData);
        return k_TriviallyOpaque;
    }
    virtual RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const& lobesWanted,
                                  RixSCShadingMode, void*, RtPointer) {
        RtColorRGB const* emissive;
        RtColorRGB const* diff;
        sCtx->EvalParam(k_emissiveColor, -1, &emissive, &m_emissive_color, true);
        sCtx->EvalParam(k_diffuseColor, -1, &diff, &m_diffuse_color, true);
        RixShadingContext::Allocator pool(sCtx);
        void* mem = pool.AllocForBxdf<BookDiffuse>(1);
        BookDiffuse* eval = new (mem) BookDiffuse(sCtx, this, lobesWanted, diff, emissive);
        return eval;
    }
    virtual void EndScatter(RixBxdf*) {}
    virtual RixOpacity* BeginOpacity(RixShadingContext const*, RixSCShadingMode, void*, RtPointer) { return NULL; }
    virtual void EndOpacity(RixOpacity*) {}
    virtual RixVolumeIntegrator* BeginInterior(RixShadingContext const*, RixSCShadingMode, void*, RtPointer) {
        return NULL;
    }

private:
    RtColorRGB m_emissive_color;
    RtColorRGB m_diffuse_color;
};

extern "C" PRMANEXPORT RixBxdfFactory* CreateRixBxdfFactory(const char* hint) {
    PIXAR_ARGUSED(hint);
    return new BookDiffuseFactory();
}

extern "C" PRMANEXPORT void DestroyRixBxdfFactory(RixBxdfFactory* bxdf) { delete (BookDiffuseFactory*)bxdf; }
