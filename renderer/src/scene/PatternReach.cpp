#include "scene/PatternReach.h"

namespace bxdflab {

std::vector<char> patternsReached(std::vector<MaterialDesc> const& materials, std::vector<PatternDesc> const& patterns) {
    // Connections only point at earlier patterns, so one sweep from the last
    // pattern to the first finds everything reachable.
    std::vector<char> reached(patterns.size(), 0);
    auto reach = [&reached](std::map<std::string, Connection> const& connections) {
        for (auto const& [name, link] : connections) reached[static_cast<size_t>(link.pattern)] = 1;
    };
    for (MaterialDesc const& material : materials) reach(material.connections);
    for (size_t i = reached.size(); i-- > 0;)
        if (reached[i]) reach(patterns[i].connections);
    return reached;
}

}  // namespace bxdflab
