// One `Bxdf "plugin" "handle" ...` statement made live: the plugin, the RIB
// values matched against the plugin's parameter table (and the pattern
// outputs its connected parameters read), and the instance data the plugin
// created for it.
#pragma once

#include <string>
#include <vector>

#include "RixBxdf.h"
#include "core/Diagnostics.h"
#include "scene/Scene.h"
#include "shade/NodeParams.h"
#include "shade/PluginLoader.h"

namespace bxdflab {

class BxdfInstance {
public:
    /// Matches the RIB parameters to the plugin's table (located errors on a
    /// type mismatch, warnings for unknown names) and calls CreateInstanceData.
    /// `patternOf` gives the live patterns its connections name (none: no connections).
    BxdfInstance(MaterialDesc const& material, ShadingPlugin& plugin, Diagnostics& diagnostics,
                 NodeParams::PatternLookup const& patternOf = {});
    ~BxdfInstance();
    BxdfInstance(BxdfInstance const&) = delete;
    BxdfInstance& operator=(BxdfInstance const&) = delete;

    ShadingPlugin& plugin() const { return m_plugin; }
    std::string const& handle() const { return m_handle; }
    /// The Bxdf statement in the RIB.
    SourceLocation const& where() const { return m_where; }
    RtPointer instanceData() const { return m_instance.data; }
    int hints() const { return m_hints; }
    NodeParams const& params() const { return m_params; }
    /// Value of parameter `id` (table order); nullptr for an out-of-range id.
    ParamValue const* value(int id) const { return m_params.value(id); }

private:
    ShadingPlugin& m_plugin;
    std::string m_handle;
    SourceLocation m_where;
    NodeParams m_params;
    RixShadingPlugin::InstanceData m_instance;
    int m_hints = RixBxdfFactory::k_TriviallyOpaque;
};

}  // namespace bxdflab
