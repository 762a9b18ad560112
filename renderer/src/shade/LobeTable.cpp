#include "shade/LobeTable.h"

#include "RixBxdfLobe.h"

namespace bxdflab {

LobeTable& LobeTable::instance() {
    static LobeTable table;
    return table;
}

unsigned char LobeTable::GetLpeIdByName(bool specular, bool user, const char* name) {
    std::string const key = name ? name : "";
    if (key == "Emission") return 0;
    int const kind = user ? 2 : specular ? 1 : 0;
    int const capacity = user ? k_RixBXMaxNumUserLobes : specular ? k_RixBXMaxNumSpecularLobes : k_RixBXMaxNumDiffuseLobes;
    std::lock_guard<std::mutex> lock(m_mutex);
    auto& ids = m_ids[kind];
    auto found = ids.find(key);
    if (found != ids.end()) return found->second;
    // 1, 2, ... in order of first lookup; past the capacity, names share ids (wrapping, never 0).
    unsigned char id = static_cast<unsigned char>(1 + static_cast<int>(ids.size()) % (capacity - 1));
    ids.emplace(key, id);
    return id;
}

}  // namespace bxdflab
