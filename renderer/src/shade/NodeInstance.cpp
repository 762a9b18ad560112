#include "shade/NodeInstance.h"

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
}

NodeInstance::~NodeInstance() {
    if (m_instance.freefunc && m_instance.data) m_instance.freefunc(m_instance.data);
}

}  // namespace bxdflab
