// RenderMan's own materials that this renderer does not have (PxrSurface,
// PxrLM*, PxrGlass, ...): when a scene names one and no plugin of that name
// is on the search path, a stock plugin stands in for it, keeping the colour
// and what it can of the look, with one warning per material name.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/Scene.h"

namespace bxdflab {

struct StandIn {
    MaterialDesc material;  ///< the stock plugin and the parameters carried over
    std::string note;       ///< what is lost, for the warning
    bool cutOut = false;    ///< a cut-out (presence below 1 or textured) the stand-in renders opaque (glass)
};

/// The stand-in for `material`, or nothing when its plugin is not one of
/// RenderMan's (then a missing plugin stays an error). A stand-in may add
/// patterns of its own to `patterns` (the scene's): a gain on a textured colour.
std::optional<StandIn> standInFor(MaterialDesc const& material, std::vector<PatternDesc>& patterns);

}  // namespace bxdflab
