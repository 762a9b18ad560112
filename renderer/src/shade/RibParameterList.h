// The parameters of an Integrator statement as a RixParameterList, for the
// integrator plugin's create function: every RIB parameter by name and type.
#pragma once

#include "RixShading.h"
#include "parse/ParamList.h"

namespace bxdflab {

class RibParameterList final : public RixParameterList {
public:
    explicit RibParameterList(ParamList const& params) : m_params(params) {}
    int GetNumParams() const override { return static_cast<int>(m_params.all().size()); }
    int GetParamId(RtUString name, int* id) const override;
    int GetParamInfo(int id, RtUString* name, RixSCType* type) const override;

protected:
    RixSCDetail Eval(int id, int arrayIndex, RixSCType wanted, void* result) const override;
    int ParamInfo(int id, RixSCType* type, RixSCConnectionInfo* cinfo, int* arrayLength) const override;

   private:
    ParamList const& m_params;
};

}  // namespace bxdflab
