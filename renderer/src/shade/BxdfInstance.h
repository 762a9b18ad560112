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
#include "shade/NodeInstance.h"
#include "shade/NodeParams.h"
#include "shade/PluginLoader.h"

namespace bxdflab {

class BxdfInstance : public NodeInstance {
public:
    /// `patternOf` gives the live patterns its connections name (none: no connections).
    BxdfInstance(MaterialDesc const& material, ShadingPlugin& plugin, Diagnostics& diagnostics,
                 NodeParams::PatternLookup const& patternOf = {});

    /// GetInstanceHints of the instance (e.g. k_TriviallyOpaque).
    int hints() const { return m_hints; }
    /// Value of parameter `id` (table order); nullptr for an out-of-range id.
    ParamValue const* value(int id) const { return params().value(id); }

private:
    int m_hints = RixBxdfFactory::k_TriviallyOpaque;
};

}  // namespace bxdflab
