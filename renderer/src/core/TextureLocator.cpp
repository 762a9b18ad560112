#include "core/TextureLocator.h"

#include <filesystem>

namespace bxdflab {
namespace {

namespace fs = std::filesystem;

/// A name as the file system finds it: as written, then below each folder.
std::optional<std::string> onDisk(std::string const& name, std::vector<std::string> const& folders) {
    std::error_code error;  // a name the file system rejects (too long, ...) is not there either
    if (name.empty()) return std::nullopt;
    if (fs::exists(name, error)) return name;
    if (fs::path(name).is_absolute()) return std::nullopt;
    for (std::string const& folder : folders) {
        fs::path candidate = fs::path(folder) / name;
        if (fs::exists(candidate, error)) return candidate.string();
    }
    return std::nullopt;
}

}  // namespace

std::optional<std::string> TextureLocator::find(std::string const& name) const {
    // "grid.tex" and "./grid.tex" name the same made texture.
    auto made = madeFrom.find(fs::path(name).lexically_normal().string());
    if (made != madeFrom.end())
        if (auto picture = onDisk(made->second.picture, folders)) return picture;
    return onDisk(name, folders);
}

std::string TextureLocator::searchedPlaces() const {
    std::string places = "the current folder";
    for (std::string const& folder : folders) places += ", " + folder;
    return places;
}

}  // namespace bxdflab
