// A test Bxdf that shows a primvar: it emits the color primvar named by
// "string colorPrimvar" (default "Cs"), or, failing that, the float primvar
// "string floatPrimvar" as a grey, and reflects nothing. Black where neither exists.
// Given "color fill", it asks for the colour primvar in RenderMan's form with
// that fill value instead, and emits what that gives at every point. Given
// "string pairPrimvar" (a float[2] primvar such as Rix::k_st), it emits its
// two values as red and green, asked for as RenderMan's patterns ask for st.
#include <new>

#include "EmitOnlyBxdf.h"
#include "RixPredefinedStrings.hpp"

namespace {

class PrimvarFactory : public RixBxdfFactory {
public:
    int Init(RixContext&, RtUString const) override { return 0; }
    void Finalize(RixContext&) override {}
    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("colorPrimvar"), k_RixSCString, k_RixSCScatterInput),
                                         RixSCParamInfo(RtUString("floatPrimvar"), k_RixSCString, k_RixSCScatterInput),
                                         RixSCParamInfo(RtUString("fill"), k_RixSCColor, k_RixSCScatterInput),
                                         RixSCParamInfo(RtUString("pairPrimvar"), k_RixSCString, k_RixSCScatterInput),
                                         RixSCParamInfo()};
        return table;
    }
    void Synchronize(RixContext&, RixSCSyncMsg, RixParameterList const*) override {}
    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const&, RixSCShadingMode, void*,
                          RtPointer) override {
        RtUString const Cs("Cs"), none("");
        RtUString const *colorName, *floatName;
        sCtx->EvalParam(0, -1, &colorName, &Cs, false);
        sCtx->EvalParam(1, -1, &floatName, &none, false);
        RixShadingContext::Allocator pool(sCtx);
        RtColorRGB* emission = pool.AllocForBxdf<RtColorRGB>(sCtx->numPts);
        RtUString const* pairName;
        sCtx->EvalParam(3, -1, &pairName, &Rix::k_empty, false);
        if (*pairName) {
            RtFloat2 const* pair;
            RtFloat const* radius;
            sCtx->GetPrimVar(*pairName, RtFloat2(0.0f, 0.0f), &pair, &radius);
            for (int i = 0; i < sCtx->numPts; ++i) emission[i] = RtColorRGB(pair[i].x, pair[i].y, radius[i]);
            return new (pool.AllocForBxdf<ColourEmitter>(1)) ColourEmitter(sCtx, this, emission);
        }
        RixSCType type;
        RixSCConnectionInfo fillGiven;
        sCtx->GetParamInfo(2, &type, &fillGiven);
        if (fillGiven == k_RixSCParameterListValue) {
            RtColorRGB const* fill;
            RtColorRGB const* filled;
            sCtx->EvalParam(2, -1, &fill);
            sCtx->GetPrimVar(*colorName, *fill, &filled);
            for (int i = 0; i < sCtx->numPts; ++i) emission[i] = filled[i];
            return new (pool.AllocForBxdf<ColourEmitter>(1)) ColourEmitter(sCtx, this, emission);
        }
        RtColorRGB const* color = nullptr;
        RtFloat const* grey = nullptr;
        if (sCtx->GetPrimVar(*colorName, &color) == k_RixSCInvalidDetail) color = nullptr;
        if (!floatName->Empty() && sCtx->GetPrimVar(*floatName, &grey) == k_RixSCInvalidDetail) grey = nullptr;
        for (int i = 0; i < sCtx->numPts; ++i)
            emission[i] = color ? color[i] : grey ? RtColorRGB(grey[i]) : RtColorRGB(0.0f);
        return new (pool.AllocForBxdf<ColourEmitter>(1)) ColourEmitter(sCtx, this, emission);
    }
    void EndScatter(RixBxdf*) override {}
};

}  // namespace

RIX_BXDFPLUGINCREATE {
    PIXAR_ARGUSED(hint);
    return new PrimvarFactory();
}
RIX_BXDFPLUGINDESTROY { delete static_cast<PrimvarFactory*>(bxdf); }
