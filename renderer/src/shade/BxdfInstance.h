// One `Bxdf "plugin" "handle" ...` statement made live: the plugin, the RIB
// values matched against the plugin's parameter table, and the instance data
// the plugin created for it.
#pragma once

#include <string>
#include <vector>

#include "RixBxdf.h"
#include "core/Diagnostics.h"
#include "scene/Scene.h"
#include "shade/PluginLoader.h"

namespace bxdflab {

/// A parameter value from the RIB, in the plugin's declared type.
struct ParamValue {
    bool set = false;
    RixSCType type = k_RixSCInvalidType;
    std::vector<float> floats;      ///< float, color, vector/point/normal, float2
    std::vector<int> ints;          ///< int
    std::vector<RtUString> strings; ///< string
};

class BxdfInstance {
public:
    /// Matches the RIB parameters to the plugin's table (located errors on a
    /// type mismatch, warnings for unknown names) and calls CreateInstanceData.
    BxdfInstance(MaterialDesc const& material, BxdfPlugin& plugin, Diagnostics& diagnostics);
    ~BxdfInstance();
    BxdfInstance(BxdfInstance const&) = delete;
    BxdfInstance& operator=(BxdfInstance const&) = delete;

    BxdfPlugin& plugin() const { return m_plugin; }
    std::string const& handle() const { return m_handle; }
    /// The Bxdf statement in the RIB.
    SourceLocation const& where() const { return m_where; }
    RtPointer instanceData() const { return m_instance.data; }
    int hints() const { return m_hints; }
    /// Value of parameter `id` (table order); nullptr for an out-of-range id.
    ParamValue const* value(int id) const {
        return id >= 0 && static_cast<size_t>(id) < m_values.size() ? &m_values[static_cast<size_t>(id)] : nullptr;
    }

private:
    BxdfPlugin& m_plugin;
    std::string m_handle;
    SourceLocation m_where;
    std::vector<ParamValue> m_values;
    RixShadingPlugin::InstanceData m_instance;
    int m_hints = RixBxdfFactory::k_TriviallyOpaque;
};

}  // namespace bxdflab
