// One spelling per folder, so that a folder named twice ("assets", "./assets/",
// "/work/scene/assets") is searched, and listed in messages, once.
#pragma once

#include <filesystem>

namespace bxdflab {

/// `folder` as an absolute, normalised path without a trailing separator; a
/// relative folder is read from the working folder. Empty when the working
/// folder cannot be read (it was deleted under the renderer).
std::filesystem::path absoluteFolder(std::filesystem::path const& folder);

}  // namespace bxdflab
