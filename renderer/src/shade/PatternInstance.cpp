#include "shade/PatternInstance.h"

namespace bxdflab {

PatternInstance::PatternInstance(PatternDesc const& desc, std::set<std::string> const& outputsRead,
                                 ShadingPlugin& plugin, NodeParams::PatternLookup const& patternOf,
                                 PatternCounters& counters, Diagnostics& diagnostics)
    : NodeInstance("Pattern", desc.handle, desc.where, desc.params, desc.connections, outputsRead, plugin, patternOf,
                   diagnostics),
      m_counters(counters) {}

}  // namespace bxdflab
