// Reading an integrator's RIB parameters, with range checks that refuse bad
// values through RixMessages (the renderer reports them with the RIB location).
#pragma once

#include <string>

#include "RixIntegrator.h"

namespace bxdflab {

/// Whether the RIB gave the parameter `name` at all.
inline bool HasParam(RixParameterList const* params, const char* name) {
    int id;
    return params->GetParamId(RtUString(name), &id) == 0;
}

/// The integer parameter `name` (or dflt); false after reporting an error if outside [lo, hi].
inline bool ReadInt(RixParameterList const* params, RixMessages* messages, const char* name, int dflt, int lo, int hi,
                    int& out) {
    out = dflt;
    int id;
    if (params->GetParamId(RtUString(name), &id) == 0 && params->EvalParam(id, -1, &out) == k_RixSCInvalidDetail) {
        messages->Error("parameter \"%s\" must be an int", name);
        return false;
    }
    if (out < lo || out > hi) {
        messages->Error("%s must be between %d and %d, got %d", name, lo, hi, out);
        return false;
    }
    return true;
}

inline float ReadFloat(RixParameterList const* params, const char* name, float dflt) {
    float value = dflt;
    int id;
    if (params->GetParamId(RtUString(name), &id) == 0) params->EvalParam(id, -1, &value);
    return value;
}

inline std::string ReadString(RixParameterList const* params, const char* name, const char* dflt) {
    RtUString value(dflt);
    int id;
    if (params->GetParamId(RtUString(name), &id) == 0) params->EvalParam(id, -1, &value);
    return value.CStr();
}

}  // namespace bxdflab
