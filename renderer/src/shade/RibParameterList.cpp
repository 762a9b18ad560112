#include "shade/RibParameterList.h"

#include "shade/ParamTypes.h"

namespace bxdflab {

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
    if (type) *type = rixTypeFor(all[static_cast<size_t>(id)].decl.type);
    return 0;
}

int RibParameterList::ParamInfo(int id, RixSCType* type, RixSCConnectionInfo* cinfo, int* arrayLength) const {
    auto const& all = m_params.all();
    if (id < 0 || static_cast<size_t>(id) >= all.size()) return 1;
    Param const& p = all[static_cast<size_t>(id)];
    if (type) *type = rixTypeFor(p.decl.type);
    if (cinfo) *cinfo = k_RixSCParameterListValue;  // the list holds only what the RIB wrote
    if (arrayLength) *arrayLength = p.decl.arraySize > 1 ? p.decl.arraySize : -1;
    return 0;
}

RixSCDetail RibParameterList::Eval(int id, int arrayIndex, RixSCType wanted, void* result) const {
    auto const& all = m_params.all();
    if (id < 0 || static_cast<size_t>(id) >= all.size()) return k_RixSCInvalidDetail;
    // A parameter written without a type takes the type its reader asks for, when its
    // values can be that: the integrator's request is its declaration, as a plugin's
    // .args file is RenderMan's.
    Param const& given = all[static_cast<size_t>(id)];
    Param typed;
    if (given.decl.untyped) {
        typed = given;
        giveType(typed, paramTypeFor(wanted));
    }
    Param const& p = given.decl.untyped ? typed : given;
    size_t index = arrayIndex > 0 ? static_cast<size_t>(arrayIndex) : 0;
    RixSCType type = rixTypeFor(p.decl.type);
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
