// Which pattern nodes a set of materials reaches through its connections.
#pragma once

#include <vector>

#include "scene/Scene.h"

namespace bxdflab {

/// reached[i] is 1 when some material is connected to patterns[i], directly
/// or through other patterns; a node nothing reaches need not be loaded.
std::vector<char> patternsReached(std::vector<MaterialDesc> const& materials, std::vector<PatternDesc> const& patterns);

}  // namespace bxdflab
