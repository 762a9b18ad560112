// One `Pattern "plugin" "handle" ...` statement made live: the plugin, its
// parameters and connections, and the instance data the plugin made for it.
// Patterns are run by the shading contexts that need their outputs
// (ShadingContextImpl::patternOutput), at most once per context.
#pragma once

#include <atomic>
#include <set>
#include <string>

#include "RixPattern.h"
#include "shade/NodeInstance.h"
#include "shade/NodeParams.h"

namespace bxdflab {

/// What the stats report about shading networks.
struct PatternCounters {
    std::atomic<uint64_t> evaluations{0};  ///< ComputeOutputParams calls
    std::atomic<uint64_t> points{0};       ///< points they computed
};

class PatternInstance : public NodeInstance {
public:
    /// `outputsRead`: the names of its outputs that connections read.
    PatternInstance(PatternDesc const& desc, std::set<std::string> const& outputsRead, ShadingPlugin& plugin,
                    NodeParams::PatternLookup const& patternOf, PatternCounters& counters, Diagnostics& diagnostics);

    PatternCounters& counters() const { return m_counters; }

private:
    PatternCounters& m_counters;
};

}  // namespace bxdflab
