#include "core/ImageFiles.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <filesystem>

#include "core/Error.h"
#include "core/GitLfs.h"

namespace bxdflab {
namespace {
std::atomic<ImageFiles const*> g_files{nullptr};
}  // namespace

void installImageFiles(ImageFiles const* files) { g_files = files; }

ImageFiles const& imageFiles() {
    ImageFiles const* files = g_files;
    if (!files) throw RenderError("this program does not read or write image files (it is built without OpenImageIO)");
    return *files;
}

std::unique_ptr<TextureService> openTextures(Diagnostics& diagnostics) {
    ImageFiles const* files = g_files;
    return files ? files->openTextures(diagnostics) : nullptr;
}

namespace {
std::string lowerExtension(std::string const& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}
}  // namespace

bool isEightBitImageName(std::string const& path) {
    std::string const extension = lowerExtension(path);
    return extension == ".png" || extension == ".jpg" || extension == ".jpeg";
}

bool isWritableImageName(std::string const& path) {
    std::string const extension = lowerExtension(path);
    return isEightBitImageName(path) || extension == ".exr" || extension == ".tif" || extension == ".tiff";
}

void writeImage(std::string const& path, std::vector<float> const& pixels, int width, int height, int channels,
                std::vector<std::string> const& names) {
    imageFiles().write(path, pixels, width, height, channels, names);
}

std::string notAnImageBecause(std::string const& path) {
    if (fileIsGitLfsPointer(path)) return "it is " + gitLfsPointerNote("image");
    std::error_code error;
    if (std::filesystem::is_regular_file(path, error) && std::filesystem::file_size(path, error) == 0 && !error)
        return "it is empty (0 bytes): the file was not copied or downloaded whole";
    return {};
}

}  // namespace bxdflab
