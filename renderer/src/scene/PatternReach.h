// Which pattern nodes a set of materials reaches through its connections,
// and which of their outputs those connections read.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "scene/Scene.h"

namespace bxdflab {

/// reached[i] is 1 when some material is connected to patterns[i], directly
/// or through other patterns; a node nothing reaches need not be loaded.
std::vector<char> patternsReached(std::vector<MaterialDesc> const& materials, std::vector<PatternDesc> const& patterns);

/// read[i] holds the names of the outputs of patterns[i] that the materials'
/// connections read, directly or through other patterns (a pattern may skip
/// computing the others: GetParamInfo tells it which are connected).
std::vector<std::set<std::string>> outputsRead(std::vector<MaterialDesc> const& materials,
                                               std::vector<PatternDesc> const& patterns);

}  // namespace bxdflab
