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

std::vector<std::set<std::string>> outputsRead(std::vector<MaterialDesc> const& materials,
                                               std::vector<PatternDesc> const& patterns) {
    std::vector<char> const reached = patternsReached(materials, patterns);
    std::vector<std::set<std::string>> read(patterns.size());
    auto note = [&read](std::map<std::string, Connection> const& connections) {
        for (auto const& [name, link] : connections) read[static_cast<size_t>(link.pattern)].insert(link.output);
    };
    for (MaterialDesc const& material : materials) note(material.connections);
    for (size_t i = 0; i < patterns.size(); ++i)
        if (reached[i]) note(patterns[i].connections);
    return read;
}

}  // namespace bxdflab
