#include "SubmissionContents.h"

#include <fcntl.h>
#include <unistd.h>

#include <cctype>
#include <cstring>
#include <fstream>
#include <iterator>

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

}  // namespace rixgrade
