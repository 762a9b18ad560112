#include "MountStaging.h"

#include <fcntl.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>

namespace rixgrade {

MountStaging::~MountStaging() {
    if (!m_folder.empty()) rmdir(m_folder.c_str());
}

std::string MountStaging::stage(std::string const& real) {
    struct stat st;
    if (stat(real.c_str(), &st) != 0) return real;
    if (m_folder.empty()) {
        // /tmp, not TMPDIR: TMPDIR may be the very folder nobody cannot enter.
        char folder[] = "/tmp/rixgrade-mounts-XXXXXX";
        if (!mkdtemp(folder)) throw std::runtime_error("cannot create a staging folder in /tmp");
        m_folder = folder;
    }
    m_entries.push_back({real, m_folder + "/" + std::to_string(m_entries.size()), S_ISDIR(st.st_mode)});
    return m_entries.back().staged;
}

bool MountStaging::mountAll() const noexcept {
    if (m_entries.empty()) return true;
    // Private first: nothing mounted below may propagate back to the machine's namespace.
    if (unshare(CLONE_NEWNS) != 0 || mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) return false;
    if (mount("tmpfs", m_folder.c_str(), "tmpfs", MS_NOSUID | MS_NODEV | MS_NOEXEC, "mode=0755,size=64k") != 0)
        return false;
    for (Entry const& entry : m_entries) {
        if (entry.folder) {
            if (mkdir(entry.staged.c_str(), 0755) != 0) return false;
        } else {
            int fd = open(entry.staged.c_str(), O_CREAT | O_WRONLY | O_CLOEXEC, 0644);
            if (fd < 0) return false;
            close(fd);
        }
        // A bind keeps the source's own mount flags: the tmpfs's noexec does not reach rixjail.
        if (mount(entry.real.c_str(), entry.staged.c_str(), nullptr, MS_BIND | MS_REC, nullptr) != 0) return false;
    }
    return true;
}

}  // namespace rixgrade
