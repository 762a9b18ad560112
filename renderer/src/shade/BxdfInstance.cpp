#include "shade/BxdfInstance.h"

namespace bxdflab {
namespace {

NodeParams::PatternLookup orNone(NodeParams::PatternLookup const& patternOf) {
    if (patternOf) return patternOf;
    return [](int) -> PatternInstance const* { return nullptr; };
}

}  // namespace

BxdfInstance::BxdfInstance(MaterialDesc const& material, ShadingPlugin& plugin, Diagnostics& diagnostics,
                           NodeParams::PatternLookup const& patternOf)
    : m_plugin(plugin),
      m_handle(material.handle),
      m_where(material.where),
      m_params("Bxdf", plugin, material.params, material.connections, orNone(patternOf), diagnostics) {
    NodeParameterList list(plugin.paramTable(), m_params);
    plugin.factory()->CreateInstanceData(plugin.context(), RtUString(m_handle.c_str()), &list, &m_instance);
    m_hints = plugin.factory()->GetInstanceHints(m_instance.data);
}

BxdfInstance::~BxdfInstance() {
    if (m_instance.freefunc && m_instance.data) m_instance.freefunc(m_instance.data);
}

}  // namespace bxdflab
