#include "shade/RibParameterList.h"

namespace bxdflab {
namespace {

RixSCType typeOf(ParamType type) {
    switch (type) {
        case ParamType::Float: return k_RixSCFloat;
        case ParamType::Int: return k_RixSCInteger;
        case ParamType::Color: return k_RixSCColor;
        case ParamType::Point: return k_RixSCPoint;
        case ParamType::Vector: return k_RixSCVector;
        case ParamType::Normal: return k_RixSCNormal;
        case ParamType::String: return k_RixSCString;
        default: return k_RixSCInvalidType;
    }
}

}  // namespace

int RibParameterList::GetParamId(RtUString name, int* id) const {
    auto const& all = m_params.all();
    for (size_t i = 0; i < all.size(); ++i)
        if (all[i].name() == name.CStr()) {
            all[i].used = true;
            *id = static_cast<int>(i);
            return 0;
        }
    m_params.noteAbsent(name.CStr());  // for a "did you mean" on a parameter spelled nearly so
    return 1;
}

int RibParameterList::GetParamInfo(int id, RtUString* name, RixSCType* type) const {
    auto const& all = m_params.all();
    if (id < 0 || static_cast<size_t>(id) >= all.size()) return 1;
    if (name) *name = RtUString(all[static_cast<size_t>(id)].name().c_str());
    if (type) *type = typeOf(all[static_cast<size_t>(id)].decl.type);
    return 0;
}

RixSCDetail RibParameterList::Eval(int id, int arrayIndex, RixSCType wanted, void* result) const {
    auto const& all = m_params.all();
    if (id < 0 || static_cast<size_t>(id) >= all.size()) return k_RixSCInvalidDetail;
    Param const& p = all[static_cast<size_t>(id)];
    size_t index = arrayIndex > 0 ? static_cast<size_t>(arrayIndex) : 0;
    RixSCType type = typeOf(p.decl.type);
    bool triple = type == k_RixSCColor || type == k_RixSCPoint || type == k_RixSCVector || type == k_RixSCNormal;
    if (wanted == k_RixSCFloat && (type == k_RixSCFloat || type == k_RixSCInteger) && index < p.floats.size()) {
        *static_cast<float*>(result) = p.floats[index];
    } else if (wanted == k_RixSCInteger && (type == k_RixSCInteger || type == k_RixSCFloat) && index < p.floats.size()) {
        *static_cast<int*>(result) = static_cast<int>(p.floats[index]);
    } else if ((wanted == k_RixSCColor || wanted == k_RixSCVector) && triple && 3 * index + 2 < p.floats.size()) {
        for (size_t c = 0; c < 3; ++c) static_cast<float*>(result)[c] = p.floats[3 * index + c];
    } else if (wanted == k_RixSCString && type == k_RixSCString && index < p.strings.size()) {
        *static_cast<RtUString*>(result) = RtUString(p.strings[index].c_str());
    } else {
        return k_RixSCInvalidDetail;
    }
    return k_RixSCUniform;
}

}  // namespace bxdflab
