#include "core/Diagnostics.h"

#include <iostream>

namespace bxdflab {

void Diagnostics::report(Severity severity, std::string const& message) {
    std::lock_guard<std::mutex> guard(m_lock);
    std::string key = std::to_string(static_cast<int>(severity)) + message;
    auto found = m_index.find(key);
    if (found != m_index.end()) {
        ++m_entries[found->second].count;
        return;
    }
    m_index.emplace(key, m_entries.size());
    m_entries.push_back({severity, message, 1});
    if (m_print) {
        const char* label = severity == Severity::Error ? "error: " : severity == Severity::Warning ? "warning: " : "note: ";
        std::cerr << label << message << '\n';
    }
}

std::vector<Diagnostics::Entry> Diagnostics::entries() const {
    std::lock_guard<std::mutex> guard(m_lock);
    return m_entries;
}

int Diagnostics::warningCount() const {
    std::lock_guard<std::mutex> guard(m_lock);
    int count = 0;
    for (auto const& e : m_entries)
        if (e.severity == Severity::Warning) count += e.count;
    return count;
}

}  // namespace bxdflab
