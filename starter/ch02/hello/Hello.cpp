// hello — your first plugin: a surface of one constant colour.
//
// It is complete: chapter 2 is about building a plugin as a shared object and
// making the renderer find it, not about light. Build it, point the renderer
// at the folder it lands in, and render scenes/ch02/hello.rib.
//
// Parameters
//   color color [1 1 1]   the colour the surface shows
#include <new>

#include "RixBxdf.h"

namespace {

/// Shows `color` as emitted light: no lobes, so nothing else is computed.
class Hello : public RixBxdf {
public:
    Hello(RixShadingContext const* sc, RixBxdfFactory* factory, RtColorRGB const* color)
        : RixBxdf(sc, factory), m_color(color) {}
    RixBXEvaluateDomain GetEvaluateDomain() override { return k_RixBXEmptyDomain; }
    void GetAggregateLobeTraits(RixBXLobeTraits* lobes) override { lobes->SetNone(); }
    bool EmitLocal(RtColorRGB* result) override {
        for (int i = 0; i < shadingCtx->numPts; ++i) result[i] = m_color[i];
        return true;
    }
    void GenerateSample(RixBXTransportTrait, RixBXLobeTraits const*, RixRNG*, RixBXLobeSampled* lobeSampled,
                        RtVector3*, RixBXLobeWeights&, float* FPdf, float* RPdf, RtColorRGB*) override {
        for (int i = 0; i < shadingCtx->numPts; ++i) {
            lobeSampled[i].SetValid(false);
            FPdf[i] = RPdf[i] = 0.0f;
        }
    }
    void EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const*, RixRNG*, RixBXLobeTraits* lobesEvaluated,
                        RtVector3 const*, RixBXLobeWeights&, float* FPdf, float* RPdf) override {
        for (int i = 0; i < shadingCtx->numPts; ++i) {
            lobesEvaluated[i].SetNone();
            FPdf[i] = RPdf[i] = 0.0f;
        }
    }
    void EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const&, RixRNG*, int, int numSamples,
                                RixBXLobeTraits* lobesEvaluated, RtVector3 const*, RixBXLobeWeights&, float* FPdf,
                                float* RPdf) override {
        for (int s = 0; s < numSamples; ++s) {
            lobesEvaluated[s].SetNone();
            FPdf[s] = RPdf[s] = 0.0f;
        }
    }

private:
    RtColorRGB const* m_color;
};

class HelloFactory : public RixBxdfFactory {
public:
    int Init(RixContext& ctx, RtUString const pluginPath) override {
        // Plugins speak through RixMessages: this line proves hello.so was found and loaded.
        if (auto* messages = static_cast<RixMessages*>(ctx.GetRixInterface(k_RixMessages)))
            messages->Info("hello from %s", pluginPath.CStr());
        return 0;
    }
    void Finalize(RixContext&) override {}
    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("color"), k_RixSCColor, k_RixSCScatterInput),
                                         RixSCParamInfo()};
        return table;
    }
    void Synchronize(RixContext&, RixSCSyncMsg, RixParameterList const*) override {}
    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const&, RixSCShadingMode, void*,
                          RtPointer) override {
        RtColorRGB const* color;
        sCtx->EvalParam(0, -1, &color, &m_default, true);
        RixShadingContext::Allocator pool(sCtx);
        return new (pool.AllocForBxdf<Hello>(1)) Hello(sCtx, this, color);
    }
    void EndScatter(RixBxdf*) override {}

private:
    RtColorRGB m_default{1.0f, 1.0f, 1.0f};
};

}  // namespace

RIX_BXDFPLUGINCREATE {
    PIXAR_ARGUSED(hint);
    return new HelloFactory();
}

RIX_BXDFPLUGINDESTROY { delete static_cast<HelloFactory*>(bxdf); }
