#include "Scratch.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "SubmissionContents.h"

namespace fs = std::filesystem;

namespace rixgrade {
namespace {

constexpr unsigned long long kMaxFileBytes = 16ull << 20;
constexpr unsigned long long kMaxTotalBytes = 64ull << 20;
constexpr int kMaxFiles = 4000;
constexpr uid_t kNobody = 65534;

bool copyRegular(std::string const& from, std::string const& to, unsigned long long size) {
    int in = open(from.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
    if (in < 0) return false;
    struct stat st;
    // Check the opened file, not the name: it may have been swapped since it was listed.
    if (fstat(in, &st) != 0 || !S_ISREG(st.st_mode) || static_cast<unsigned long long>(st.st_size) != size) {
        close(in);
        return false;
    }
    int out = open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (out < 0) {
        close(in);
        return false;
    }
    char buffer[65536];
    bool ok = true;
    for (;;) {
        ssize_t n = read(in, buffer, sizeof buffer);
        if (n == 0) break;
        if (n < 0 || write(out, buffer, static_cast<size_t>(n)) != n) {
            ok = false;
            break;
        }
    }
    close(in);
    close(out);
    return ok;
}

}  // namespace

std::string Scratch::parentFolder(std::string const& parent) {
    if (!parent.empty()) return parent;
    char const* tmp = std::getenv("TMPDIR");
    return tmp && *tmp ? tmp : "/tmp";
}

Scratch::Scratch(std::string const& parent) {
    std::string const base = parentFolder(parent);
    std::string pattern = base + "/rixgrade-XXXXXX";
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a scratch folder in " + base);
    m_path = pattern;
    // The sandbox's home and (outside a sandbox) temporary folders.
    fs::create_directories(m_path + "/home");
    fs::create_directories(m_path + "/tmp");
}

Scratch::~Scratch() {
    if (m_keep || m_path.empty()) return;
    // Student code may have left folders without write permission: open them up first.
    std::error_code error;
    for (fs::recursive_directory_iterator it(m_path, fs::directory_options::skip_permission_denied, error), end;
         !error && it != end; it.increment(error)) {
        struct stat st;
        if (lstat(it->path().c_str(), &st) == 0 && S_ISDIR(st.st_mode)) chmod(it->path().c_str(), 0700);
    }
    fs::remove_all(m_path, error);
    if (!m_frozen.empty()) fs::remove_all(m_frozen, error);
    if (!m_grader.empty()) fs::remove_all(m_grader, error);
}

Scratch::CopyReport Scratch::copySubmission(std::string const& source, std::string const& name) const {
    CopyReport report;
    std::string const root = m_path + "/" + name;
    fs::create_directories(root);
    std::error_code error;
    fs::recursive_directory_iterator it(source, fs::directory_options::skip_permission_denied, error), end;
    if (error) throw std::runtime_error("cannot read the submission folder \"" + source + "\": " + error.message());
    for (; !error && it != end; it.increment(error)) {
        fs::path relative = fs::relative(it->path(), source, error);
        std::string target = root + "/" + relative.string();
        std::string shown = relative.string();
        struct stat st;
        if (lstat(it->path().c_str(), &st) != 0) continue;
        if (S_ISDIR(st.st_mode)) {
            std::string leaf = it->path().filename().string();
            if (it.depth() == 0 && (leaf.rfind("build", 0) == 0 || leaf.rfind("grade", 0) == 0 || leaf == ".git")) {
                report.skipped.push_back(shown + "/ (a build, grading or version-control folder)");
                it.disable_recursion_pending();
                continue;
            }
            mkdir(target.c_str(), 0755);
        } else if (S_ISLNK(st.st_mode)) {
            fs::path link = fs::read_symlink(it->path(), error);
            if (!error && symlink(link.c_str(), target.c_str()) == 0) ++report.files;
        } else if (S_ISREG(st.st_mode)) {
            auto size = static_cast<unsigned long long>(st.st_size);
            if (size > kMaxFileBytes) {
                report.skipped.push_back(shown + " (larger than " + std::to_string(kMaxFileBytes >> 20) + " MB)");
            } else if (report.bytes + size > kMaxTotalBytes || report.files >= kMaxFiles) {
                report.skipped.push_back(shown + " (the submission is larger than " +
                                         std::to_string(kMaxTotalBytes >> 20) + " MB or " +
                                         std::to_string(kMaxFiles) + " files)");
            } else if (std::string code = compiledCode(it->path().string()); !code.empty()) {
                report.skipped.push_back(shown + " (" + code + ": submissions are built from their sources)");
                report.lookAt.push_back(shown + " (" + code + ", left out of its build)");
            } else if (copyRegular(it->path().string(), target, size)) {
                if (std::string data = embeddedData(target); !data.empty()) report.lookAt.push_back(shown + " (" + data + ")");
                report.bytes += size;
                ++report.files;
            }
        } else {
            report.skipped.push_back(shown + " (not a regular file, folder or link)");
        }
    }
    return report;
}

Scratch::CopyReport Scratch::copyPlugins(std::string const& source, std::string const& name) const {
    CopyReport report;
    std::string const root = m_path + "/" + name;
    fs::create_directories(root);
    std::error_code error;
    for (auto const& entry : fs::directory_iterator(source, error)) {
        struct stat st;
        if (entry.path().extension() != ".so" || lstat(entry.path().c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
        if (copyRegular(entry.path().string(), root + "/" + entry.path().filename().string(),
                        static_cast<unsigned long long>(st.st_size)))
            ++report.files;
    }
    if (error) throw std::runtime_error("cannot read the plugin folder \"" + source + "\": " + error.message());
    return report;
}

void Scratch::handOver() const {
    if (geteuid() != 0) return;
    std::error_code error;
    lchown(m_path.c_str(), kNobody, kNobody);
    for (fs::recursive_directory_iterator it(m_path, error), end; !error && it != end; it.increment(error))
        lchown(it->path().c_str(), kNobody, kNobody);
}

namespace {

/// Makes the folder `path` (0755, failing if anything is there); throws with `what` it is for.
void makeOwnFolder(std::string const& path, char const* what) {
    if (mkdir(path.c_str(), 0755) != 0)
        throw std::runtime_error(std::string("cannot create the folder for ") + what + ", " + path + ": " + std::strerror(errno));
}

/// The file type (S_IFREG, S_IFDIR, ...) of root/relative when every folder on the
/// way is a real one (not a link) and no part is "." or ".."; 0 otherwise. The
/// grader reads there with its own rights: a link made by the build could
/// otherwise point it at files of this machine.
mode_t typeThroughRealFolders(std::string const& root, std::string const& relative) {
    std::string path = root;
    std::istringstream parts(relative);
    mode_t type = 0;
    for (std::string part; std::getline(parts, part, '/');) {
        if (part.empty()) continue;
        if (part == "." || part == ".." || (type != 0 && type != S_IFDIR)) return 0;
        path += "/" + part;
        struct stat st;
        if (lstat(path.c_str(), &st) != 0) return 0;
        type = st.st_mode & S_IFMT;
    }
    return type;
}

}  // namespace

std::string const& Scratch::graderFolder() {
    if (m_grader.empty()) {
        makeOwnFolder(m_path + ".grader", "the grader's own files");
        m_grader = m_path + ".grader";
    }
    return m_grader;
}

bool Scratch::freezeAs(std::string const& relative, std::string const& name) {
    if (m_frozen.empty()) throw std::logic_error("freeze the plugins first");
    if (name.find('/') != std::string::npos || typeThroughRealFolders(m_path, relative) != S_IFREG) return false;
    std::string const to = m_frozen + "/" + name;
    unlink(to.c_str());
    struct stat st;
    std::string const from = m_path + "/" + relative;
    return lstat(from.c_str(), &st) == 0 && copyRegular(from, to, static_cast<unsigned long long>(st.st_size));
}

std::string Scratch::freezePlugins(std::string const& name) {
    if (!m_frozen.empty()) throw std::logic_error("the plugins are frozen once");
    makeOwnFolder(m_path + ".plugins", "the built plugins");
    m_frozen = m_path + ".plugins";
    if (typeThroughRealFolders(m_path, name) != S_IFDIR) return m_frozen;  // nothing built there
    std::string const folder = m_path + "/" + name;
    std::error_code error;
    for (auto const& entry : fs::directory_iterator(folder, error)) {
        struct stat st;
        if (entry.path().extension() != ".so" || lstat(entry.path().c_str(), &st) != 0 || !S_ISREG(st.st_mode)) continue;
        copyRegular(entry.path().string(), m_frozen + "/" + entry.path().filename().string(),
                    static_cast<unsigned long long>(st.st_size));
    }
    return m_frozen;
}

}  // namespace rixgrade
