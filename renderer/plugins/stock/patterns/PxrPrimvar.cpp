// PxrPrimvar — hands a primitive variable of the geometry ("color Cs",
// "float density", "point Pref", ...) to the network as a pattern output:
//
//   Pattern "PxrPrimvar" "tint" "string varname" ["Cs"] "string type" ["color"]
//   Bxdf "PxrDiffuse" "d" "reference color diffuseColor" ["tint:resultRGB"]
//
// "type" is float, color, point, vector or normal. Points whose shape does
// not carry the primvar get the default (defaultFloat or defaultColor).
#include <cstring>

#include "PatternHelpers.h"

namespace {

class PxrPrimvar : public stockpatterns::StockPattern {
public:
    enum { k_varname, k_type, k_defaultFloat, k_defaultColor, k_resultF, k_resultRGB, k_resultP };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("varname"), k_RixSCString),
                                         RixSCParamInfo(RtUString("type"), k_RixSCString),
                                         RixSCParamInfo(RtUString("defaultFloat"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("defaultColor"), k_RixSCColor),
                                         STOCK_PATTERN_OUTPUTS_OF_EVERY_TYPE,
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        int const n = sCtx->numPts;
        RtUString const noName, colorType("color");
        RtFloat const zero = 0.0f;
        RtColorRGB const black(0.0f);
        RtUString const *varname, *type;
        RtFloat const* defaultFloat;
        RtColorRGB const* defaultColor;
        sCtx->EvalParam(k_varname, -1, &varname, &noName);
        sCtx->EvalParam(k_type, -1, &type, &colorType);
        sCtx->EvalParam(k_defaultFloat, -1, &defaultFloat, &zero);
        sCtx->EvalParam(k_defaultColor, -1, &defaultColor, &black);

        RixShadingContext::Allocator pool(sCtx);
        bool const scalar = std::strcmp(type->CStr(), "float") == 0;
        int const components = scalar ? 1 : 3;
        float* values = pool.AllocFor<float>(n * components);
        float const* found = nullptr;
        if (scalar) {
            RtFloat const* v;
            if (sCtx->GetPrimVar(*varname, &v) != k_RixSCInvalidDetail) found = v;
        } else if (std::strcmp(type->CStr(), "color") == 0) {
            RtColorRGB const* v;
            if (sCtx->GetPrimVar(*varname, &v) != k_RixSCInvalidDetail) found = &v[0].r;
        } else {
            RtPoint3 const* v;  // point, vector and normal primvars alike
            if (sCtx->GetPrimVar(*varname, &v) != k_RixSCInvalidDetail) found = &v[0].x;
        }
        for (int i = 0; i < n * components; ++i)
            values[i] = found ? found[i] : scalar ? *defaultFloat : (*defaultColor)[i % 3];
        stockpatterns::outputAsEveryType(sCtx, values, components, k_resultF, k_resultRGB, k_resultP, numOutputs,
                                         outputs);
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrPrimvar)
