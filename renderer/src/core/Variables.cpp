#include "core/Variables.h"

#include <cctype>
#include <cstdlib>

namespace bxdflab {

namespace {
bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
}  // namespace

std::optional<std::string> environmentVariable(std::string const& name) {
    if (name.empty()) return std::nullopt;
    if (char const* value = std::getenv(name.c_str())) return std::string(value);
    return std::nullopt;
}

size_t variableNameEnd(std::string const& text, size_t start) {
    size_t end = start;
    while (end < text.size() && isNameChar(text[end])) ++end;
    // "$user:pass" is one name; "$RMANTREE:/other" (a path list) is two items.
    bool const userClass = text.compare(start, end - start, "user") == 0;
    if (userClass && end + 1 < text.size() && text[end] == ':' && isNameChar(text[end + 1]))
        for (++end; end < text.size() && isNameChar(text[end]);) ++end;
    return end;
}

std::string expandVariables(std::string const& text, VariableLookup const& lookup) {
    std::string out;
    for (size_t i = 0; i < text.size();) {
        if (text[i] != '$' || i + 1 >= text.size()) {
            out += text[i++];
            continue;
        }
        bool const braced = text[i + 1] == '{';
        size_t const start = i + (braced ? 2 : 1);
        size_t end = braced ? text.find('}', start) : variableNameEnd(text, start);
        if (end == std::string::npos) {  // "${" never closed: the rest is text
            out += text.substr(i);
            break;
        }
        size_t const next = braced ? end + 1 : end;
        std::optional<std::string> value;
        if (end > start) value = lookup(text.substr(start, end - start));
        out += value ? *value : text.substr(i, next - i);
        i = next;
    }
    return out;
}

}  // namespace bxdflab
