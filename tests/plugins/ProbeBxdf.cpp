// A configurable test Bxdf: a constant-albedo diffuse whose misbehaviour is
// chosen at compile time, so the tests can check how the renderer copes.
//   PROBE_NAN        GenerateSample and EvaluateSample return NaN weights on odd points
//   PROBE_TANGENTS   asks for Tn and dPdu (to test the on-demand tangent frames)
//   PROBE_NULL_TABLE GetParamTable returns null
//   PROBE_NO_CREATE  the create entry point is missing
//   PROBE_NEGATIVE_PDF  GenerateSample and EvaluateSample return negative pdfs on odd points
//   PROBE_UNTERMINATED_TABLE  GetParamTable's table has lost its end marker
//   PROBE_BAD_TABLE_ENTRY     GetParamTable's table has an entry with no name
//   PROBE_UNCLOSED_STRUCT     GetParamTable's table begins a struct and never ends it
//   PROBE_INSTANCE_TABLE      CreateInstanceData hands an instance a table of its own (with data to free)
//   PROBE_THROWS     GenerateSample throws a std::runtime_error
//   PROBE_SEGFAULT   GenerateSample writes through a null pointer
//   PROBE_WILD_JUMP  GenerateSample calls a function pointer that points at no code (as a
//                    return address written over sends a function back to)
//   PROBE_RECURSES   GenerateSample calls itself without end on the renderer's worker threads
//                    (one of their stacks overflows)
//   PROBE_FORWARD_RPDF  RPdf is the density of L (the forward one) instead of V's
//                    (bidirectional integrators then weigh their strategies wrongly)
#include <cmath>
#include <cstdint>
#include <sys/syscall.h>
#include <unistd.h>
#include <limits>
#include <stdexcept>
#include <new>
#include <vector>

#include "RixBxdf.h"
#include "RixShadingUtils.h"

namespace {

RixBXLobeSampled g_lobe;
RixBXLobeTraits g_traits;

class Probe : public RixBxdf {
public:
    explicit Probe(RixShadingContext const* sc, RixBxdfFactory* f) : RixBxdf(sc, f) {
        sc->GetBuiltinVar(RixShadingContext::k_Nn, &m_Nn);
        sc->GetBuiltinVar(RixShadingContext::k_Vn, &m_Vn);
#ifdef PROBE_TANGENTS
        RtVector3 const* dPdu;
        sc->GetBuiltinVar(RixShadingContext::k_Tn, &m_Tn);
        sc->GetBuiltinVar(RixShadingContext::k_dPdu, &dPdu);
#endif
    }
    RixBXEvaluateDomain GetEvaluateDomain() override { return k_RixBXReflect; }
    void GetAggregateLobeTraits(RixBXLobeTraits* t) override { *t = g_traits; }

    void GenerateSample(RixBXTransportTrait, RixBXLobeTraits const*, RixRNG* rng, RixBXLobeSampled* sampled,
                        RtVector3* Ln, RixBXLobeWeights& W, float* FPdf, float* RPdf, RtColorRGB*) override {
#ifdef PROBE_THROWS
        throw std::runtime_error("probe: GenerateSample gave up");
#endif
#ifdef PROBE_SEGFAULT
        *static_cast<int volatile*>(nullptr) = 1;
#endif
#ifdef PROBE_WILD_JUMP
        void (*volatile nowhere)() = reinterpret_cast<void (*)()>(uintptr_t{0x40});
        nowhere();
#endif
#ifdef PROBE_RECURSES
        // Only on a thread the renderer started (not the one main() runs on), each call
        // taking stack the optimiser cannot fold away. The main thread dawdles, so that
        // on a busy machine it cannot finish every tile before a worker takes one.
        volatile char frame[256];
        frame[0] = 1;
        bool const onMainThread = syscall(SYS_gettid) == getpid();
        if (onMainThread) usleep(2000);
        if (frame[0] && !onMainThread) GenerateSample(k_RixBXDirectLighting, nullptr, rng, sampled, Ln, W, FPdf, RPdf, nullptr);
#endif
        RtColorRGB* w = W.AddActiveLobe(g_lobe);
        for (int i = 0; i < shadingCtx->numPts; ++i) {
            RtNormal3 N = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i]);
            RtVector3 TX, TY;
            RixComputeShadingBasis(N, tangent(i), TX, TY);
            float cosTheta;
            RixCosDirectionalDistribution(rng->DrawSample2D(i), N, TX, TY, Ln[i], cosTheta);
            FPdf[i] = cosTheta * F_INVPI;
            RPdf[i] = reverse(N, i, FPdf[i]);
            w[i] = RtColorRGB(poison(i, 0.5f * FPdf[i]));
            FPdf[i] = negate(i, FPdf[i]);
            sampled[i] = g_lobe;
            sampled[i].SetValid(true);
        }
    }
    void EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const*, RixRNG*, RixBXLobeTraits* evaluated,
                        RtVector3 const* Ln, RixBXLobeWeights& W, float* FPdf, float* RPdf) override {
        RtColorRGB* w = W.AddActiveLobe(g_lobe);
        for (int i = 0; i < shadingCtx->numPts; ++i) {
            RtNormal3 N = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i]);
            float cosTheta = RixMax(0.0f, N.Dot(Ln[i]));
            FPdf[i] = cosTheta * F_INVPI;
            RPdf[i] = reverse(N, i, FPdf[i]);
            w[i] = RtColorRGB(poison(i, 0.5f * FPdf[i]));
            FPdf[i] = negate(i, FPdf[i]);
            evaluated[i] = g_traits;
        }
    }
    void EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const&, RixRNG*, int, int numSamples,
                                RixBXLobeTraits* evaluated, RtVector3 const*, RixBXLobeWeights& W, float* FPdf,
                                float* RPdf) override {
        W.AddActiveLobe(g_lobe);
        for (int s = 0; s < numSamples; ++s) {
            evaluated[s].SetNone();
            FPdf[s] = RPdf[s] = 0.0f;
        }
    }

private:
    RtVector3 tangent(int i) const {
#ifdef PROBE_TANGENTS
        return m_Tn[i];
#else
        PIXAR_ARGUSED(i);
        return RtVector3(0.0f, 0.0f, 0.0f);
#endif
    }
    /// The density of sampling V given L: cos(theta_V) / pi (or, mistakenly, forwardPdf).
    float reverse(RtNormal3 const& N, int i, float forwardPdf) const {
#ifdef PROBE_FORWARD_RPDF
        PIXAR_ARGUSED(N);
        PIXAR_ARGUSED(i);
        return forwardPdf;
#else
        PIXAR_ARGUSED(forwardPdf);
        return RixMax(0.0f, N.Dot(m_Vn[i])) * F_INVPI;
#endif
    }
    static float poison(int i, float value) {
#ifdef PROBE_NAN
        if (i % 2) return std::numeric_limits<float>::quiet_NaN();
#else
        PIXAR_ARGUSED(i);
#endif
        return value;
    }
    static float negate(int i, float pdf) {
#ifdef PROBE_NEGATIVE_PDF
        if (i % 2) return -pdf - 0.1f;
#else
        PIXAR_ARGUSED(i);
#endif
        return pdf;
    }
    RtNormal3 const* m_Nn;
    RtVector3 const* m_Vn;
#ifdef PROBE_TANGENTS
    RtVector3 const* m_Tn;
#endif
};

class ProbeFactory : public RixBxdfFactory {
public:
    int Init(RixContext&, RtUString const) override { return 0; }
    void Finalize(RixContext&) override {}
    RixSCParamInfo const* GetParamTable() override {
#if defined(PROBE_NULL_TABLE)
        return nullptr;
#elif defined(PROBE_UNTERMINATED_TABLE)
        // Far more entries than any plugin has, and no RixSCParamInfo() at the end.
        static std::vector<RixSCParamInfo> table(5000, RixSCParamInfo(RtUString("gain"), k_RixSCFloat, k_RixSCScatterInput));
        return table.data();
#elif defined(PROBE_UNCLOSED_STRUCT)
        static RixSCParamInfo table[] = {
            RixSCParamInfo(RtUString("PxrManifold"), RtUString("manifold"), k_RixSCStructBegin),
            RixSCParamInfo(RtUString("Q"), k_RixSCPoint), RixSCParamInfo()};
        return table;
#elif defined(PROBE_BAD_TABLE_ENTRY)
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("gain"), k_RixSCFloat, k_RixSCScatterInput),
                                         RixSCParamInfo(RtUString(""), k_RixSCFloat, k_RixSCScatterInput),
                                         RixSCParamInfo()};
        return table;
#else
        static RixSCParamInfo table[] = {RixSCParamInfo()};
        return table;
#endif
    }
    void Synchronize(RixContext& ctx, RixSCSyncMsg msg, RixParameterList const*) override {
        if (msg == k_RixSCRenderBegin) {
            g_lobe = RixBXLookupLobeByName(ctx, false, false, true, false, 0, "Diffuse");
            g_traits = RixBXLobeTraits(g_lobe);
        }
    }
    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const&, RixSCShadingMode, void*,
                          RtPointer) override {
        RixShadingContext::Allocator pool(sCtx);
        return new (pool.AllocForBxdf<Probe>(1)) Probe(sCtx, this);
    }
    void EndScatter(RixBxdf*) override {}
#ifdef PROBE_INSTANCE_TABLE
    void CreateInstanceData(RixContext&, RtUString const, RixParameterList const*, InstanceData* instance) override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("gain"), k_RixSCFloat), RixSCParamInfo()};
        instance->paramtable = table;
        instance->data = new int(1);
        instance->freefunc = [](void* data) { delete static_cast<int*>(data); };
    }
#endif
};

}  // namespace

#ifndef PROBE_NO_CREATE
RIX_BXDFPLUGINCREATE {
    PIXAR_ARGUSED(hint);
    return new ProbeFactory();
}
#endif
RIX_BXDFPLUGINDESTROY { delete static_cast<ProbeFactory*>(bxdf); }
