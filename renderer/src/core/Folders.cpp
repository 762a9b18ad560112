#include "core/Folders.h"

namespace bxdflab {

std::filesystem::path absoluteFolder(std::filesystem::path const& folder) {
    std::error_code noWorkingFolder;
    std::filesystem::path full = std::filesystem::absolute(folder, noWorkingFolder);
    if (noWorkingFolder) return {};
    full = full.lexically_normal();
    // "a/b/" normalises to "a/b/" (an empty last name): drop it, so that it equals "a/b".
    if (!full.has_filename() && full.has_relative_path()) full = full.parent_path();
    return full;
}

}  // namespace bxdflab
