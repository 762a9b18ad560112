// PxrLightEmission — the Bxdf RenderMan scenes put on geometry that glows as a
// light: it emits intensity * 2^exposure * lightColor (the lights' own
// formula) in every direction and reflects nothing. The emission is the
// chapter 6 emissive solution's; only the factory differs.
#include <cmath>
#include <new>

#include "Emissive.h"
#include "StockBxdf.h"

namespace {

class PxrLightEmissionFactory : public stockbxdfs::StockBxdfFactory {
public:
    enum ParamId { k_lightColor, k_intensity, k_exposure };
    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("lightColor"), k_RixSCColor, k_RixSCScatterInput),
                                         RixSCParamInfo(RtUString("intensity"), k_RixSCFloat, k_RixSCScatterInput),
                                         RixSCParamInfo(RtUString("exposure"), k_RixSCFloat, k_RixSCScatterInput),
                                         RixSCParamInfo()};
        return table;
    }
    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const&, RixSCShadingMode, void*,
                          RtPointer) override {
        RtColorRGB const* color;
        float const *intensity, *exposure;
        sCtx->EvalParam(k_lightColor, -1, &color, &m_white, true);
        sCtx->EvalParam(k_intensity, -1, &intensity, &m_one, true);
        sCtx->EvalParam(k_exposure, -1, &exposure, &m_zero, true);
        RixShadingContext::Allocator pool(sCtx);
        RtColorRGB* emission = pool.AllocForBxdf<RtColorRGB>(sCtx->numPts);
        for (int i = 0; i < sCtx->numPts; ++i) emission[i] = color[i] * (intensity[i] * std::exp2(exposure[i]));
        return new (pool.AllocForBxdf<Emissive>(1)) Emissive(sCtx, this, emission);
    }

private:
    RtColorRGB const m_white{1.0f, 1.0f, 1.0f};
    float const m_one = 1.0f, m_zero = 0.0f;
};

}  // namespace

STOCK_BXDF_PLUGIN(PxrLightEmissionFactory)
