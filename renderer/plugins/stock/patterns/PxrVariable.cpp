// PxrVariable — hands a geometric quantity of the shade points (one of the
// builtins named in kBuiltins below) to the network, e.g. to colour a surface
// by its normal while debugging:
//
//   Pattern "PxrVariable" "normal" "string variable" ["Nn"]
//   Bxdf "PxrDiffuse" "d" "reference color diffuseColor" ["normal:resultRGB"]
#include <cstring>
#include <string>

#include "PatternHelpers.h"

namespace {

struct NamedBuiltin {
    char const* name;
    RixShadingContext::BuiltinId id;
    bool scalar;
};

NamedBuiltin const kBuiltins[] = {
    {"P", RixShadingContext::k_P, false},         {"Nn", RixShadingContext::k_Nn, false},
    {"Ngn", RixShadingContext::k_Ngn, false},     {"Tn", RixShadingContext::k_Tn, false},
    {"Vn", RixShadingContext::k_Vn, false},       {"dPdu", RixShadingContext::k_dPdu, false},
    {"dPdv", RixShadingContext::k_dPdv, false},   {"u", RixShadingContext::k_u, true},
    {"v", RixShadingContext::k_v, true},          {"s", RixShadingContext::k_s, true},
    {"t", RixShadingContext::k_t, true},          {"du", RixShadingContext::k_du, true},
    {"dv", RixShadingContext::k_dv, true},        {"VLen", RixShadingContext::k_VLen, true},
    {"Po", RixShadingContext::k_Po, false},       {"Non", RixShadingContext::k_Non, false},
    {"PRadius", RixShadingContext::k_PRadius, true}, {"dPdtime", RixShadingContext::k_dPdtime, false},
    {"time", RixShadingContext::k_time, true},
};

class PxrVariable : public stockpatterns::StockPattern {
public:
    enum { k_variable, k_type, k_resultF, k_resultRGB, k_resultP };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("variable"), k_RixSCString),
                                         // RenderMan's output type; here every output is given whatever it is.
                                         RixSCParamInfo(RtUString("type"), k_RixSCString),
                                         STOCK_PATTERN_OUTPUTS_OF_EVERY_TYPE,
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtUString const normal("Nn");
        RtUString const* variable;
        sCtx->EvalParam(k_variable, -1, &variable, &normal);
        NamedBuiltin const* chosen = nullptr;
        for (NamedBuiltin const& b : kBuiltins)
            if (std::strcmp(b.name, variable->CStr()) == 0) chosen = &b;
        if (!chosen) {
            auto* msg = static_cast<RixMessages*>(sCtx->GetRixInterface(k_RixMessages));
            std::string known;
            for (NamedBuiltin const& b : kBuiltins) known += (known.empty() ? "" : ", ") + std::string(b.name);
            msg->Warning("PxrVariable: no variable \"%s\" (%s); using Nn", variable->CStr(), known.c_str());
            chosen = &kBuiltins[1];
        }
        float const* values;
        if (chosen->scalar) {
            RtFloat const* f;
            sCtx->GetBuiltinVar(chosen->id, &f);
            values = f;
        } else {
            RtVector3 const* v;
            sCtx->GetBuiltinVar(chosen->id, &v);
            values = &v[0].x;
        }
        stockpatterns::outputAsEveryType(sCtx, values, chosen->scalar ? 1 : 3, k_resultF, k_resultRGB, k_resultP,
                                         numOutputs, outputs);
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrVariable)
