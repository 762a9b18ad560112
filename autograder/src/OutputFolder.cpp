#include "OutputFolder.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <random>
#include <stdexcept>

namespace fs = std::filesystem;

namespace rixgrade {
namespace {

/// Creates one folder level; an existing symbolic link or file there is an error.
void makeFolder(std::string const& path) {
    struct stat st;
    if (lstat(path.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) return;
        throw std::runtime_error("\"" + path + "\" exists and is not a folder (a file or link was put there)");
    }
    if (mkdir(path.c_str(), 0755) != 0 && errno != EEXIST)
        throw std::runtime_error("cannot create the folder \"" + path + "\": " + std::strerror(errno));
    if (lstat(path.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
        throw std::runtime_error("\"" + path + "\" is not a folder");
}

}  // namespace

std::string safeName(std::string const& name) {
    std::string out;
    for (unsigned char c : name) out += (std::isalnum(c) || c == '.' || c == '_' || c == '-') ? static_cast<char>(c) : '_';
    if (out.size() > 80) out.resize(80);
    if (out.empty() || out[0] == '.') out = "_" + out;
    return out;
}

OutputFolder::OutputFolder(std::string path) : m_path(fs::absolute(path).lexically_normal().string()) {
    while (m_path.size() > 1 && m_path.back() == '/') m_path.pop_back();
    fs::path p(m_path);
    std::string built;
    for (auto const& part : p) {
        built = built.empty() ? part.string() : (built == "/" ? "/" + part.string() : built + "/" + part.string());
        if (built == "/") continue;
        struct stat st;
        if (lstat(built.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) continue;
        // The last component must be a real folder; earlier ones may be links the user set up.
        if (built != m_path && lstat(built.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) continue;
        makeFolder(built);
    }
}

std::string OutputFolder::prepare(std::string const& name, std::string& leaf) const {
    fs::path relative(name);
    std::string folder = m_path;
    for (auto it = relative.begin(); it != relative.end(); ++it) {
        std::string part = it->string();
        if (part.empty() || part == "." || part == ".." || part.find('/') != std::string::npos)
            throw std::runtime_error("unsafe output name \"" + name + "\"");
        if (std::next(it) == relative.end()) {
            leaf = part;
        } else {
            folder += "/" + part;
            makeFolder(folder);
        }
    }
    return folder;
}

std::string OutputFolder::temporary(std::string const& folder) {
    static thread_local std::mt19937_64 random(std::random_device{}());
    for (int attempt = 0; attempt < 100; ++attempt) {
        char name[64];
        std::snprintf(name, sizeof name, "/.rixgrade-%016llx.tmp", static_cast<unsigned long long>(random()));
        std::string path = folder + name;
        int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
        if (fd >= 0) {
            close(fd);
            return path;
        }
    }
    throw std::runtime_error("cannot create a temporary file in \"" + folder + "\"");
}

void OutputFolder::write(std::string const& name, std::string const& contents) const {
    std::string leaf;
    std::string folder = prepare(name, leaf);
    std::string tmp = temporary(folder);
    int fd = open(tmp.c_str(), O_WRONLY | O_TRUNC | O_NOFOLLOW | O_CLOEXEC);
    bool ok = fd >= 0;
    for (size_t done = 0; ok && done < contents.size();) {
        ssize_t n = ::write(fd, contents.data() + done, contents.size() - done);
        if (n <= 0) ok = false;
        else done += static_cast<size_t>(n);
    }
    if (fd >= 0 && close(fd) != 0) ok = false;
    if (!ok || rename(tmp.c_str(), (folder + "/" + leaf).c_str()) != 0) {
        unlink(tmp.c_str());
        throw std::runtime_error("cannot write \"" + folder + "/" + leaf + "\": " + std::strerror(errno));
    }
}

void OutputFolder::writePng(std::string const& name, std::vector<float> const& rgb, int width, int height) const {
    std::string leaf;
    std::string folder = prepare(name, leaf);
    std::string tmp = temporary(folder) ;
    std::string png = tmp + ".png";  // OpenImageIO picks the format from the extension
    if (rename(tmp.c_str(), png.c_str()) != 0) throw std::runtime_error("cannot prepare " + png);
    OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
    image.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, rgb.data());
    OIIO::ImageBuf display;
    OIIO::ImageBufAlgo::colorconvert(display, image, "linear", "sRGB", false);
    display.set_write_format(OIIO::TypeDesc::UINT8);
    if (!display.write(png) || rename(png.c_str(), (folder + "/" + leaf).c_str()) != 0) {
        unlink(png.c_str());
        throw std::runtime_error("cannot write \"" + folder + "/" + leaf + "\"");
    }
}

OutputFolder OutputFolder::sub(std::string const& name) const {
    std::string leaf;
    std::string folder = prepare(name + "/x", leaf);
    return OutputFolder(folder);
}

}  // namespace rixgrade
