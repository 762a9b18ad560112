// Reads no more of the Shading Language than a shader's parameter list (the
// declarations between "surface name (" and its closing parenthesis, each
// "[output] [uniform|varying] type name = default" and separated by ';'; names
// of one type may share a declaration, separated by ',') and, in its code, which
// words occur (Cs, diffuse, illuminance, ...), comments left out.
#include "scene/ShaderSource.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <regex>

namespace bxdflab {
namespace {

/// Longer than any plain default or declaration: left unread (and never given to a regular expression).
constexpr size_t kLongestDefault = 200;

/// `text` with its comments replaced by spaces; string literals are kept whole.
std::string withoutComments(std::string const& text) {
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size(); ++i) {
        if (text.compare(i, 2, "/*") == 0) {
            size_t const end = text.find("*/", i + 2);
            if (end == std::string::npos) break;
            out += ' ';
            i = end + 1;
        } else if (text.compare(i, 2, "//") == 0) {
            size_t const end = text.find('\n', i);
            if (end == std::string::npos) break;
            out += '\n';
            i = end;
        } else if (text[i] == '"') {
            size_t const end = text.find('"', i + 1);
            if (end == std::string::npos) break;
            out.append(text, i, end - i + 1);
            i = end;
        } else {
            out += text[i];
        }
    }
    return out;
}

std::string trimmed(std::string const& s) {
    size_t const first = s.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

/// `s` cut at every `separator` outside parentheses and string literals.
std::vector<std::string> splitOutsideParentheses(std::string const& s, char separator) {
    std::vector<std::string> pieces(1);
    int depth = 0;
    bool quoted = false;
    for (char c : s) {
        if (c == '"') quoted = !quoted;
        if (!quoted && c == '(') ++depth;
        if (!quoted && c == ')') --depth;
        if (!quoted && depth == 0 && c == separator)
            pieces.emplace_back();
        else
            pieces.back() += c;
    }
    return pieces;
}

/// The number `text` is, wholly (no expression), when it is one.
bool plainNumber(std::string const& text, float& value) {
    std::string const s = trimmed(text);
    if (s.empty()) return false;
    char* end = nullptr;
    value = std::strtof(s.c_str(), &end);
    return end == s.c_str() + s.size() && std::isfinite(value);
}

/// A colour default: a number (grey), or three in parentheses after "color" and an optional "rgb".
bool plainColour(std::string const& text, std::vector<float>& rgb) {
    float grey = 0.0f;
    if (plainNumber(text, grey)) {
        rgb = {grey, grey, grey};
        return true;
    }
    if (text.size() > kLongestDefault) return false;
    static std::regex const written(R"(^\s*(?:color\s*)?(?:"rgb"\s*)?\(([^()]*)\)\s*$)");
    std::smatch parts;
    if (!std::regex_match(text, parts, written)) return false;
    std::vector<std::string> const numbers = splitOutsideParentheses(parts[1].str(), ',');
    if (numbers.size() != 3) return false;
    rgb.assign(3, 0.0f);
    for (size_t k = 0; k < 3; ++k)
        if (!plainNumber(numbers[k], rgb[k])) return false;
    return true;
}

bool isWordCharacter(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// Where `text` has `word` as a whole word at `at`, the position after it and any white space; else npos.
size_t afterWord(std::string const& text, size_t at, std::string const& word) {
    if (text.compare(at, word.size(), word) != 0) return std::string::npos;
    size_t const end = at + word.size();
    if ((at > 0 && isWordCharacter(text[at - 1])) || (end < text.size() && isWordCharacter(text[end])))
        return std::string::npos;
    size_t const next = text.find_first_not_of(" \t\r\n", end);
    return next == std::string::npos ? text.size() : next;
}

/// The parameter list of `surface shader (...)` in `text`, without its parentheses; empty when absent.
/// (Scanned by hand: a regular expression over a whole file recurses as deep as its longest match.)
std::string parameterList(std::string const& text, std::string const& shader) {
    if (shader.empty() || !std::all_of(shader.begin(), shader.end(), isWordCharacter)) return {};
    size_t open = std::string::npos;
    for (size_t at = text.find("surface"); at != std::string::npos && open == std::string::npos;
         at = text.find("surface", at + 1)) {
        size_t const name = afterWord(text, at, "surface");
        if (name == std::string::npos || name == at + 7) continue;  // "surface" must be followed by space
        size_t const paren = afterWord(text, name, shader);
        if (paren != std::string::npos && paren < text.size() && text[paren] == '(') open = paren + 1;
    }
    if (open == std::string::npos) return {};
    int depth = 1;
    for (size_t i = open; i < text.size(); ++i) {
        if (text[i] == '(') ++depth;
        if (text[i] == ')' && --depth == 0) return text.substr(open, i - open);
    }
    return {};
}

/// One declared parameter: its type, name, default as written, and whether it is an output.
struct Declared {
    std::string type, name, value;
    bool output;
};

/// The parameters of `shader` in `text`, in the order they are declared.
std::vector<Declared> declaredParameters(std::string const& text, std::string const& shader) {
    std::vector<Declared> declared;
    static std::regex const typed(R"(^(output\s+)?(?:(?:uniform|varying)\s+)?(\w+)\s+(\w+)$)");
    for (std::string const& declaration : splitOutsideParentheses(parameterList(withoutComments(text), shader), ';')) {
        std::string type;
        bool output = false;
        for (std::string const& piece : splitOutsideParentheses(declaration, ',')) {
            size_t const equals = piece.find('=');
            if (equals == std::string::npos) continue;
            std::string name = trimmed(piece.substr(0, equals));
            if (name.size() > kLongestDefault) continue;
            std::smatch words;
            if (std::regex_match(name, words, typed)) {
                output = words[1].matched;
                type = words[2].str();
                name = words[3].str();
            }
            declared.push_back({type, name, piece.substr(equals + 1), output});
        }
    }
    return declared;
}

/// Whether `text` (without comments) has `word` as a whole word anywhere.
bool hasWord(std::string const& text, std::string const& word) {
    for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
        if (afterWord(text, at, word) != std::string::npos) return true;
    return false;
}

}  // namespace

ShaderDefaults surfaceShaderDefaults(std::string const& text, std::string const& shader) {
    ShaderDefaults defaults;
    for (Declared const& p : declaredParameters(text, shader)) {
        std::vector<float> parsed(1);
        if (p.type == "float" && plainNumber(p.value, parsed[0]))
            defaults[p.name] = parsed;
        else if (p.type == "color" && plainColour(p.value, parsed))
            defaults[p.name] = parsed;
    }
    return defaults;
}

bool readsNoLight(std::string const& text) {
    std::string const code = withoutComments(text);
    if (code.find("#include") != std::string::npos) return false;
    static char const* const gatherLight[] = {"diffuse",  "specular",     "specularbrdf", "phong",
                                              "ambient",  "illuminance",  "Cl",           "trace",
                                              "occlusion", "indirectdiffuse", "gather",   "caustic",
                                              "photonmap", "subsurface"};
    return hasWord(code, "Ci") && std::none_of(std::begin(gatherLight), std::end(gatherLight),
                                               [&](char const* word) { return hasWord(code, word); });
}

std::vector<std::string> ownSurfaceColours(std::string const& text, std::string const& shader) {
    if (hasWord(withoutComments(text), "Cs")) return {};
    static char const* const notTheSurface[] = {"spec", "highlight", "refl", "env", "shadow", "opac"};
    std::vector<std::string> candidates;
    for (Declared const& p : declaredParameters(text, shader)) {
        if (p.type != "color" || p.output) continue;
        std::string lower = p.name;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
        if (std::none_of(std::begin(notTheSurface), std::end(notTheSurface),
                         [&](char const* word) { return lower.find(word) != std::string::npos; }))
            candidates.push_back(p.name);
    }
    if (candidates.empty()) return {};
    // A set's members share the first one's stem and differ in a number or a capital letter at the end.
    auto stemOf = [](std::string const& name) {
        size_t end = name.find_last_not_of("0123456789");
        if (end + 1 < name.size()) return name.substr(0, end + 1);
        bool const lettered = name.size() >= 2 && std::isupper(static_cast<unsigned char>(name.back())) &&
                              std::islower(static_cast<unsigned char>(name[name.size() - 2]));
        return lettered ? name.substr(0, name.size() - 1) : std::string();
    };
    std::string const stem = stemOf(candidates.front());
    if (stem.empty()) return {candidates.front()};
    std::vector<std::string> set;
    for (std::string const& name : candidates)
        if (stemOf(name) == stem) set.push_back(name);
    return set;
}

}  // namespace bxdflab
