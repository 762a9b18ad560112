#include "shade/NodeInstance.h"

#include "core/Error.h"

namespace bxdflab {

NodeInstance::NodeInstance(char const* kind, std::string const& handle, SourceLocation const& where,
                           ParamList const& params, std::map<std::string, Connection> const& connections,
                           std::set<std::string> const& outputsRead, ShadingPlugin& plugin,
                           NodeParams::PatternLookup const& patternOf, Diagnostics& diagnostics)
    : m_plugin(plugin),
      m_handle(handle),
      m_where(where),
      m_params(kind, plugin, params, connections, outputsRead, patternOf, diagnostics) {
    NodeParameterList list(plugin.paramTable(), m_params);
    plugin.plugin()->CreateInstanceData(plugin.context(), RtUString(m_handle.c_str()), &list, &m_instance);
    if (m_instance.paramtable) {  // the destructor will not run: free what the plugin made first
        if (m_instance.freefunc && m_instance.data) m_instance.freefunc(m_instance.data);
        throw RibError(where, std::string(kind) + " \"" + handle + "\": plugin \"" + plugin.name() + "\" (" +
                                  plugin.path() + ") gave it a parameter table of its own in CreateInstanceData "
                                  "(InstanceData::paramtable), which this renderer does not support; every "
                                  "instance uses the table GetParamTable returns");
    }
}

NodeInstance::~NodeInstance() {
    if (m_instance.freefunc && m_instance.data) m_instance.freefunc(m_instance.data);
}

}  // namespace bxdflab
