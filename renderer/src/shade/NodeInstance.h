// What a live shading node -- one `Bxdf` or `Pattern` statement -- holds:
// its plugin, handle and RIB location, the RIB values matched against the
// plugin's parameter table (with the pattern outputs its connections read),
// and the instance data the plugin made for it in CreateInstanceData (freed
// with the node).
#pragma once

#include <map>
#include <set>
#include <string>

#include "core/Diagnostics.h"
#include "shade/NodeParams.h"
#include "shade/PluginLoader.h"

namespace bxdflab {

class NodeInstance {
public:
    ShadingPlugin& plugin() const { return m_plugin; }
    std::string const& handle() const { return m_handle; }
    /// The statement in the RIB.
    SourceLocation const& where() const { return m_where; }
    NodeParams const& params() const { return m_params; }
    RtPointer instanceData() const { return m_instance.data; }

    NodeInstance(NodeInstance const&) = delete;
    NodeInstance& operator=(NodeInstance const&) = delete;

protected:
    /// kind: "Bxdf" or "Pattern", for messages. Matches the parameters (located
    /// errors on a type mismatch, warnings for unknown names) and calls the
    /// plugin's CreateInstanceData. `outputsRead`: the outputs connections read (a pattern's).
    NodeInstance(char const* kind, std::string const& handle, SourceLocation const& where, ParamList const& params,
                 std::map<std::string, Connection> const& connections, std::set<std::string> const& outputsRead,
                 ShadingPlugin& plugin, NodeParams::PatternLookup const& patternOf, Diagnostics& diagnostics);
    ~NodeInstance();

private:
    ShadingPlugin& m_plugin;
    std::string m_handle;
    SourceLocation m_where;
    NodeParams m_params;
    RixShadingPlugin::InstanceData m_instance;
};

}  // namespace bxdflab
