#include "shade/PatternInstance.h"

namespace bxdflab {

PatternInstance::PatternInstance(PatternDesc const& desc, ShadingPlugin& plugin,
                                 NodeParams::PatternLookup const& patternOf, PatternCounters& counters,
                                 Diagnostics& diagnostics)
    : m_plugin(plugin),
      m_handle(desc.handle),
      m_where(desc.where),
      m_params("Pattern", plugin, desc.params, desc.connections, patternOf, diagnostics),
      m_counters(counters) {
    NodeParameterList list(plugin.paramTable(), m_params);
    plugin.pattern()->CreateInstanceData(plugin.context(), RtUString(m_handle.c_str()), &list, &m_instance);
}

PatternInstance::~PatternInstance() {
    if (m_instance.freefunc && m_instance.data) m_instance.freefunc(m_instance.data);
}

}  // namespace bxdflab
