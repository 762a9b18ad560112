// Files that are not what their names say: a repository cloned without Git
// LFS holds small text pointers in place of its large files (textures, baked
// RIB archives). Readers check for one before reporting a file as damaged.
#pragma once

#include <string>
#include <string_view>

namespace bxdflab {

/// True when `start` (the first bytes of a file, or all of it) is a Git LFS pointer.
inline bool isGitLfsPointer(std::string_view start) {
    constexpr std::string_view kPointer = "version https://git-lfs.github.com/spec/";
    return start.substr(0, kPointer.size()) == kPointer;
}

/// True when the file at `path` is one (false when it cannot be read).
bool fileIsGitLfsPointer(std::string const& path);

/// What to say of such a file, after "it is" or "... is".
inline std::string gitLfsPointerNote(std::string const& kind) {
    return "a Git LFS pointer, not the " + kind + ": fetch it with `git lfs pull` where it was cloned";
}

}  // namespace bxdflab
