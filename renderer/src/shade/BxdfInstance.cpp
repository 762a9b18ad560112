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
    : NodeInstance("Bxdf", material.handle, material.where, material.params, material.connections, {}, plugin,
                   orNone(patternOf), diagnostics),
      m_hints(plugin.factory()->GetInstanceHints(instanceData())) {}

}  // namespace bxdflab
