#include "core/GitLfs.h"

#include <fstream>

namespace bxdflab {

bool fileIsGitLfsPointer(std::string const& path) {
    char start[64] = {};
    std::ifstream file(path, std::ios::binary);
    file.read(start, sizeof start);
    return isGitLfsPointer(std::string_view(start, static_cast<size_t>(file.gcount())));
}

}  // namespace bxdflab
