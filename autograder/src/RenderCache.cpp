#include "RenderCache.h"

#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

namespace rixgrade {
namespace {

/// "path size mtime;" for a file: what changes when it is rebuilt or edited.
void describeFile(fs::path const& file, std::string& out) {
    std::error_code error;
    auto size = fs::file_size(file, error);
    auto time = fs::last_write_time(file, error);
    out += file.string() + " " + std::to_string(error ? 0 : size) + " " +
           std::to_string(error ? 0 : time.time_since_epoch().count()) + ";";
}

fs::path entryPath(std::string const& folder, std::string const& key) {
    uLong crc = crc32(0L, reinterpret_cast<Bytef const*>(key.data()), static_cast<uInt>(key.size()));
    char name[32];
    std::snprintf(name, sizeof name, "%08lx.raw", static_cast<unsigned long>(crc));
    return fs::path(folder) / name;
}

/// What a key renders, without what it was rendered with: "scene ...; spp ...; seed ...;".
std::string subjectOf(std::string const& key) {
    size_t end = 0;
    for (int field = 0; field < 3 && end != std::string::npos; ++field) end = key.find(';', end == 0 ? 0 : end + 1);
    return end == std::string::npos ? key : key.substr(0, end + 1);
}

/// Removes the entries of the same render made with older inputs: one entry per scene, spp and seed.
void removeStale(std::string const& folder, std::string const& key) {
    std::string const subject = subjectOf(key);
    std::error_code error;
    for (auto const& entry : fs::directory_iterator(folder, error)) {
        if (entry.path().extension() != ".raw") continue;
        std::ifstream in(entry.path(), std::ios::binary);
        std::string storedKey;
        if (std::getline(in, storedKey) && storedKey != key && subjectOf(storedKey) == subject) {
            in.close();
            fs::remove(entry.path(), error);
        }
    }
}

}  // namespace

std::string renderCacheKey(std::string const& scene, int spp, int seed, std::vector<std::string> const& inputs) {
    std::string key = "scene " + scene + "; spp " + std::to_string(spp) + "; seed " + std::to_string(seed) + ";";
    for (auto const& input : inputs) {
        std::error_code error;
        if (fs::is_directory(input, error)) {
            std::vector<fs::path> files;
            for (auto const& entry : fs::recursive_directory_iterator(input, error))
                if (entry.is_regular_file(error)) files.push_back(entry.path());
            std::sort(files.begin(), files.end());
            for (auto const& file : files) describeFile(file, key);
        } else {
            describeFile(input, key);
        }
    }
    return key;
}

std::optional<std::string> loadCachedRender(std::string const& folder, std::string const& key) {
    std::ifstream in(entryPath(folder, key), std::ios::binary);
    if (!in) return std::nullopt;
    std::string storedKey;
    if (!std::getline(in, storedKey) || storedKey != key) return std::nullopt;
    return std::string(std::istreambuf_iterator<char>(in), {});
}

void storeCachedRender(std::string const& folder, std::string const& key, std::string const& bytes) {
    std::error_code error;
    fs::create_directories(folder, error);
    fs::path target = entryPath(folder, key);
    fs::path temporary = target;
    temporary += ".tmp" + std::to_string(getpid());
    {
        std::ofstream out(temporary, std::ios::binary);
        out << key << '\n';
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        if (!out) {
            fs::remove(temporary, error);
            return;
        }
    }
    removeStale(folder, key);
    fs::rename(temporary, target, error);
    if (error) fs::remove(temporary, error);
}

}  // namespace rixgrade
