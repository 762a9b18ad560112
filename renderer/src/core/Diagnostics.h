// Warnings and informational messages collected during a render.
//
// Warnings are printed once per (kind, text) and counted, so a scene with a
// thousand unsupported attributes prints a short list instead of a flood.
// Thread-safe: plugins report through it from render threads.
#pragma once

#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "core/Error.h"

namespace bxdflab {

class Diagnostics {
public:
    enum class Severity { Info, Warning, Error };

    /// quiet = true keeps messages for the stats but prints nothing.
    explicit Diagnostics(bool print = true) : m_print(print) {}

    void warn(SourceLocation const& where, std::string const& message) {
        report(Severity::Warning, where.known() ? where.str() + ": " + message : message);
    }
    void warn(std::string const& message) { report(Severity::Warning, message); }
    void info(std::string const& message) { report(Severity::Info, message); }
    void error(std::string const& message) { report(Severity::Error, message); }
    void report(Severity severity, std::string const& message);

    struct Entry {
        Severity severity;
        std::string text;
        int count;
    };
    /// Every distinct message, in the order first seen, with its repeat count.
    std::vector<Entry> entries() const;
    int warningCount() const;
    void setPrinting(bool print) { m_print = print; }

private:
    mutable std::mutex m_lock;
    std::vector<Entry> m_entries;
    std::map<std::string, size_t> m_index;
    bool m_print;
};

}  // namespace bxdflab
