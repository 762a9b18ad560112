// The parameters of one node of a shading network -- a Bxdf or a pattern
// statement -- matched against its plugin's table: a value from the RIB for
// each parameter it gives, and for each "reference" parameter the pattern
// output it is connected to.
#pragma once

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "RixShading.h"
#include "core/Diagnostics.h"
#include "scene/Scene.h"
#include "shade/ParamTypes.h"
#include "shade/PluginLoader.h"

namespace bxdflab {

class PatternInstance;

/// A parameter value from the RIB, in the plugin's declared type.
struct ParamValue {
    bool set = false;
    RixSCType type = k_RixSCInvalidType;
    std::vector<float> floats;      ///< float, color, vector/point/normal, float2
    std::vector<int> ints;          ///< int
    std::vector<RtUString> strings; ///< string
};

/// Where a connected parameter takes its values from.
struct ParamConnection {
    PatternInstance const* pattern = nullptr;
    int output = -1;  ///< the output's row in the pattern's table
};

class NodeParams {
public:
    /// The live pattern made for Scene::patterns[index], or null when that
    /// pattern could not be loaded (its connections then fall back to values).
    using PatternLookup = std::function<PatternInstance const*(int index)>;

    /// `kind` is "Bxdf" or "Pattern" (for messages). Throws a located RibError
    /// on a type mismatch or a connection to an output the pattern lacks;
    /// warns about names the plugin does not have. `outputsRead` names the
    /// node's outputs that connections read (a pattern's; GetParamInfo says so).
    NodeParams(std::string const& kind, ShadingPlugin const& plugin, ParamList const& params,
               std::map<std::string, Connection> const& connections, std::set<std::string> const& outputsRead,
               PatternLookup const& patternOf, Diagnostics& diagnostics);

    /// Value of parameter `id` (table order); nullptr for an out-of-range id.
    ParamValue const* value(int id) const {
        return id >= 0 && static_cast<size_t>(id) < m_values.size() ? &m_values[static_cast<size_t>(id)] : nullptr;
    }
    /// The connection of parameter `id`, or nullptr when it is not connected.
    ParamConnection const* connection(int id) const {
        if (id < 0 || static_cast<size_t>(id) >= m_connections.size()) return nullptr;
        ParamConnection const& c = m_connections[static_cast<size_t>(id)];
        return c.pattern ? &c : nullptr;
    }
    std::vector<ParamValue> const& values() const { return m_values; }
    /// GetParamInfo's answer for parameter `id` (any pointer may be null):
    /// its declared type, connected / given / left to the default (for an
    /// output: connected when a connection reads it), and the element count
    /// of an array parameter (-1 for one that is not).
    int describe(int id, RixSCType* type, RixSCConnectionInfo* cinfo, int* arrayLength) const;
    /// The name of parameter `id` in the plugin's table ("" for an out-of-range id).
    char const* name(int id) const {
        return id >= 0 && static_cast<size_t>(id) < m_table->size() ? (*m_table)[static_cast<size_t>(id)].name.CStr() : "";
    }

private:
    std::vector<RixSCParamInfo> const* m_table;
    std::vector<ParamValue> m_values;
    std::vector<ParamConnection> m_connections;
    std::vector<char> m_outputRead;  ///< per row: an output some connection reads
};

/// The RIB parameters of a node as a RixParameterList (for CreateInstanceData).
class NodeParameterList final : public RixParameterList {
public:
    NodeParameterList(std::vector<RixSCParamInfo> const& table, NodeParams const& params)
        : m_table(table), m_params(params) {}
    int GetNumParams() const override { return static_cast<int>(m_table.size()); }
    int GetParamId(RtUString name, int* id) const override;
    int GetParamInfo(int id, RtUString* name, RixSCType* type) const override;

protected:
    RixSCDetail Eval(int id, int arrayIndex, RixSCType wanted, void* result) const override;
    int ParamInfo(int id, RixSCType* type, RixSCConnectionInfo* cinfo, int* arrayLength) const override {
        return m_params.describe(id, type, cinfo, arrayLength);
    }

private:
    std::vector<RixSCParamInfo> const& m_table;
    NodeParams const& m_params;
};

}  // namespace bxdflab
