#include "shade/BxdfInstance.h"

namespace bxdflab {
namespace {

bool compatible(RixSCType declared, ParamType given) {
    switch (declared) {
        case k_RixSCFloat: return given == ParamType::Float || given == ParamType::Int;
        case k_RixSCInteger: return given == ParamType::Int;
        case k_RixSCColor: return given == ParamType::Color;
        case k_RixSCNormal:
        case k_RixSCVector:
        case k_RixSCPoint: return given == ParamType::Vector || given == ParamType::Point || given == ParamType::Normal;
        case k_RixSCString: return given == ParamType::String;
        case k_RixSCFloat2: return given == ParamType::Float;
        default: return false;
    }
}

const char* ribTypeFor(RixSCType type) {
    switch (type) {
        case k_RixSCFloat: return "float";
        case k_RixSCInteger: return "int";
        case k_RixSCColor: return "color";
        case k_RixSCNormal: return "normal";
        case k_RixSCVector: return "vector";
        case k_RixSCPoint: return "point";
        case k_RixSCString: return "string";
        case k_RixSCFloat2: return "float[2]";
        default: return "?";
    }
}

/// The RIB parameters that matched the table, as a RixParameterList for CreateInstanceData.
class InstanceParameterList final : public RixParameterList {
public:
    InstanceParameterList(std::vector<RixSCParamInfo> const& table, std::vector<ParamValue> const& values)
        : m_table(table), m_values(values) {}
    int GetNumParams() const override { return static_cast<int>(m_table.size()); }
    int GetParamId(RtUString name, int* id) const override {
        for (size_t i = 0; i < m_table.size(); ++i)
            if (m_table[i].name == name && m_values[i].set) {
                *id = static_cast<int>(i);
                return 0;
            }
        return 1;
    }
    int GetParamInfo(int id, RtUString* name, RixSCType* type) const override {
        if (id < 0 || static_cast<size_t>(id) >= m_table.size()) return 1;
        if (name) *name = m_table[static_cast<size_t>(id)].name;
        if (type) *type = m_table[static_cast<size_t>(id)].type;
        return 0;
    }

protected:
    RixSCDetail Eval(int id, int arrayIndex, RixSCType wanted, void* result) const override {
        if (id < 0 || static_cast<size_t>(id) >= m_values.size()) return k_RixSCInvalidDetail;
        ParamValue const& v = m_values[static_cast<size_t>(id)];
        if (!v.set) return k_RixSCInvalidDetail;
        size_t index = arrayIndex > 0 ? static_cast<size_t>(arrayIndex) : 0;
        bool triple = v.type == k_RixSCColor || v.type == k_RixSCVector || v.type == k_RixSCPoint || v.type == k_RixSCNormal;
        if (wanted == k_RixSCFloat && v.type == k_RixSCFloat && index < v.floats.size()) {
            *static_cast<float*>(result) = v.floats[index];
        } else if (wanted == k_RixSCInteger && v.type == k_RixSCInteger && index < v.ints.size()) {
            *static_cast<int*>(result) = v.ints[index];
        } else if ((wanted == k_RixSCColor || wanted == k_RixSCVector) && triple && 3 * index + 2 < v.floats.size()) {
            float* out = static_cast<float*>(result);
            for (size_t c = 0; c < 3; ++c) out[c] = v.floats[3 * index + c];
        } else if (wanted == k_RixSCString && v.type == k_RixSCString && index < v.strings.size()) {
            *static_cast<RtUString*>(result) = v.strings[index];
        } else {
            return k_RixSCInvalidDetail;
        }
        return k_RixSCUniform;
    }

private:
    std::vector<RixSCParamInfo> const& m_table;
    std::vector<ParamValue> const& m_values;
};

}  // namespace

BxdfInstance::BxdfInstance(MaterialDesc const& material, BxdfPlugin& plugin, Diagnostics& diagnostics)
    : m_plugin(plugin), m_handle(material.handle), m_where(material.where) {
    auto const& table = plugin.paramTable();
    m_values.resize(table.size());
    for (size_t i = 0; i < table.size(); ++i) m_values[i].type = table[i].type;

    for (Param const& p : material.params.all()) {
        if (p.decl.reference) {
            // Connections to pattern outputs ("reference color baseColor" ["tex:Cout"]).
            diagnostics.warn(p.location, "Bxdf \"" + plugin.name() + "\" parameter \"" + p.name() + "\" is connected to " +
                                             (p.strings.empty() ? std::string("a pattern") : "\"" + p.strings[0] + "\"") +
                                             ", which is not evaluated; the plugin's default is used");
            continue;
        }
        int id = plugin.paramId(p.name());
        if (id < 0) {
            std::string known;
            for (auto const& entry : table) known += std::string(known.empty() ? "" : ", ") + entry.name.CStr();
            diagnostics.warn(p.location, "Bxdf \"" + plugin.name() + "\" has no parameter \"" + p.name() +
                                             "\"; ignored (its parameters: " + (known.empty() ? "none" : known) + ")");
            continue;
        }
        RixSCParamInfo const& info = table[static_cast<size_t>(id)];
        if (!compatible(info.type, p.decl.type))
            throw RibError(p.location, "Bxdf \"" + plugin.name() + "\" parameter \"" + p.name() + "\" is a " +
                                           ribTypeFor(info.type) + ", but the RIB gives a " + paramTypeName(p.decl.type) +
                                           " (write \"" + ribTypeFor(info.type) + " " + p.name() + "\")");
        ParamValue& value = m_values[static_cast<size_t>(id)];
        value.set = true;
        value.floats = p.floats;
        value.ints = p.ints;
        for (auto const& s : p.strings) value.strings.emplace_back(s.c_str());
        if (info.type == k_RixSCInteger && value.ints.empty())
            for (float f : p.floats) value.ints.push_back(static_cast<int>(f));
    }

    InstanceParameterList list(table, m_values);
    plugin.factory()->CreateInstanceData(plugin.context(), RtUString(m_handle.c_str()), &list, &m_instance);
    m_hints = plugin.factory()->GetInstanceHints(m_instance.data);
}

BxdfInstance::~BxdfInstance() {
    if (m_instance.freefunc && m_instance.data) m_instance.freefunc(m_instance.data);
}

}  // namespace bxdflab
