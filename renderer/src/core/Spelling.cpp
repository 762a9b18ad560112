#include "core/Spelling.h"

#include <algorithm>
#include <cctype>

namespace bxdflab {

std::string lowered(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

namespace {

/// Levenshtein distance, one row at a time.
size_t editDistance(std::string const& a, std::string const& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            size_t const above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string closestSpelling(std::string const& name, std::vector<std::string> const& candidates) {
    std::string const wanted = lowered(name);
    std::string best;
    // More than two letters off is no longer a slip; nor is one letter in a name
    // of two (Kr is not a mistyped Ka): a third of the letters at most.
    size_t bestDistance = std::min<size_t>(2, name.size() / 3) + 1;
    for (std::string const& candidate : candidates) {
        size_t const distance = editDistance(wanted, lowered(candidate));
        if (distance < bestDistance) {
            bestDistance = distance;
            best = candidate;
        }
    }
    return best;
}

}  // namespace bxdflab
