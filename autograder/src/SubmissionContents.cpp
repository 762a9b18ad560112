#include "SubmissionContents.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cstring>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <sstream>

namespace rixgrade {
namespace {

// A plugin is tens of kilobytes: as base64 at least ~8k characters, as a byte array
// tens of thousands of numbers. Honest exercise code (even with a lookup table of a
// thousand entries) stays far below both.
constexpr size_t kBlobCharacters = 8192;
constexpr size_t kMostNumbers = 16384;

bool isSource(std::string const& path) {
    for (char const* suffix : {".cpp", ".cc", ".cxx", ".c", ".h", ".hpp", ".hh", ".inl", ".cmake", "CMakeLists.txt"}) {
        size_t n = std::strlen(suffix);
        if (path.size() >= n && path.compare(path.size() - n, n, suffix) == 0) return true;
    }
    return false;
}

bool isBase64OrHex(unsigned char c) { return std::isalnum(c) || c == '+' || c == '/' || c == '='; }

}  // namespace

std::string compiledCode(std::string const& path) {
    int in = open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
    if (in < 0) return "";
    char head[8] = {};
    ssize_t got = read(in, head, sizeof head);
    close(in);
    if (got >= 4 && std::memcmp(head, "\x7f" "ELF", 4) == 0) return "compiled code (an ELF library, program or object file)";
    if (got >= 8 && std::memcmp(head, "!<arch>\n", 8) == 0) return "compiled code (a static library)";
    return "";
}

std::string embeddedData(std::string const& path) {
    if (!isSource(path)) return "";
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Blob text: lines that are nothing but base64 or hex (quotes, commas and
    // spaces aside), however the encoder wrapped them.
    size_t blob = 0, numbers = 0;
    size_t lineBlob = 0;
    bool lineIsBlob = true;
    unsigned char previous = ' ';
    auto endLine = [&] {
        if (lineIsBlob && lineBlob >= 40) blob += lineBlob;
        lineBlob = 0;
        lineIsBlob = true;
    };
    for (unsigned char c : text) {
        if (c == '\n') {
            endLine();
        } else if (isBase64OrHex(c)) {
            ++lineBlob;
        } else if (!std::isspace(c) && c != '"' && c != ',' && c != '\\') {
            lineIsBlob = false;
        }
        // A number starts with a digit that does not continue a name or another number.
        if (std::isdigit(c) && !std::isalnum(previous) && previous != '_' && previous != '.') ++numbers;
        previous = c;
    }
    endLine();
    if (blob >= kBlobCharacters) return std::to_string(blob) + " characters of base64 or hex text: data, not code?";
    if (numbers >= kMostNumbers) return std::to_string(numbers) + " numbers: a table large enough to hold a compiled plugin";
    return "";
}

namespace {

/// Reads root/relative into text when every folder on the way is a real one (not
/// a link) inside root and the file is a regular file. The grader reads with its
/// own rights: nothing may lead it outside the submission.
bool readInside(std::string const& root, std::string const& relative, std::string& text) {
    std::string path = root;
    std::istringstream parts(relative);
    std::vector<std::string> names;
    for (std::string part; std::getline(parts, part, '/');) {
        if (part.empty() || part == ".") continue;
        if (part == "..") {
            if (names.empty()) return false;
            names.pop_back();
        } else {
            names.push_back(part);
        }
    }
    if (names.empty()) return false;
    for (size_t k = 0; k < names.size(); ++k) {
        path += "/" + names[k];
        struct stat st;
        if (lstat(path.c_str(), &st) != 0) return false;
        if (k + 1 < names.size() ? !S_ISDIR(st.st_mode) : !S_ISREG(st.st_mode)) return false;
    }
    std::ifstream in(path, std::ios::binary);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return true;
}

/// The code of a C++ source without its comments, strings and character literals
/// (each replaced by a space), and the names it #includes with quotes.
std::string codeOnly(std::string const& text, std::vector<std::string>& includes) {
    static std::regex const include(R"re(^\s*#\s*include\s*"([^"]+)")re");
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        if (std::regex_search(line, m, include)) includes.push_back(m[1]);
    }
    std::string code;
    code.reserve(text.size());
    for (size_t i = 0; i < text.size();) {
        char c = text[i];
        if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
            while (i < text.size() && text[i] != '\n') ++i;
        } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            size_t end = text.find("*/", i + 2);
            i = end == std::string::npos ? text.size() : end + 2;
        } else if (c == '"' || c == '\'') {
            for (++i; i < text.size() && text[i] != c && text[i] != '\n'; ++i)
                if (text[i] == '\\') ++i;
            ++i;
        } else {
            code += c;
            ++i;
            continue;
        }
        code += ' ';
    }
    return code;
}

}  // namespace

std::string callsWhatItShouldWrite(std::string const& root, std::string const& folder,
                                   std::vector<std::string> const& sources, std::vector<std::string> const& names) {
    if (names.empty()) return "";
    std::set<std::string> const wanted(names.begin(), names.end());
    std::vector<std::string> toRead;
    for (auto const& source : sources) toRead.push_back(folder + "/" + source);
    std::set<std::string> seen;
    static std::regex const identifier("[A-Za-z_][A-Za-z0-9_]*");
    while (!toRead.empty()) {
        std::string const relative = toRead.back();
        toRead.pop_back();
        if (!seen.insert(relative).second) continue;
        std::string text;
        if (!readInside(root, relative, text)) continue;
        std::vector<std::string> includes;
        std::string const code = codeOnly(text, includes);
        std::string const shown = relative.substr(relative.rfind('/') + 1);
        if (code.find("##") != std::string::npos) return shown + " pastes tokens together (##), which can hide a call";
        for (std::sregex_iterator it(code.begin(), code.end(), identifier), end; it != end; ++it)
            if (wanted.count(it->str())) return shown + " calls " + it->str();
        // Quoted includes resolve beside the file, then in the exercise's folder and common/ (the starter's build).
        std::string const here = relative.substr(0, relative.rfind('/'));
        for (auto const& name : includes)
            for (std::string const& base : {here, folder, std::string("common")}) toRead.push_back(base + "/" + name);
    }
    return "";
}

}  // namespace rixgrade
