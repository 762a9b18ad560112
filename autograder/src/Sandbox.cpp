#include "Sandbox.h"

#include <fcntl.h>
#include <linux/landlock.h>
#include <linux/seccomp.h>
#include <sched.h>
#include <seccomp.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>

// Landlock rights newer than Debian 12's kernel headers (the running kernel may have them).
#ifndef LANDLOCK_ACCESS_FS_TRUNCATE
#define LANDLOCK_ACCESS_FS_TRUNCATE (1ULL << 14)
#endif

namespace rixgrade {
namespace {

int landlockAbi() {
    long abi = syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
    return abi < 0 ? 0 : static_cast<int>(abi);
}

/// Every right that changes the file system, as far as this kernel can restrict it.
__u64 writeRights(int abi) {
    __u64 rights = LANDLOCK_ACCESS_FS_WRITE_FILE | LANDLOCK_ACCESS_FS_REMOVE_DIR | LANDLOCK_ACCESS_FS_REMOVE_FILE |
                   LANDLOCK_ACCESS_FS_MAKE_CHAR | LANDLOCK_ACCESS_FS_MAKE_DIR | LANDLOCK_ACCESS_FS_MAKE_REG |
                   LANDLOCK_ACCESS_FS_MAKE_SOCK | LANDLOCK_ACCESS_FS_MAKE_FIFO | LANDLOCK_ACCESS_FS_MAKE_BLOCK |
                   LANDLOCK_ACCESS_FS_MAKE_SYM;
    if (abi >= 2) rights |= LANDLOCK_ACCESS_FS_REFER;     // moving files between folders
    if (abi >= 3) rights |= LANDLOCK_ACCESS_FS_TRUNCATE;  // truncate() and O_TRUNC
    return rights;
}

void allowBeneath(int ruleset, std::string const& path, __u64 rights) {
    int fd = open(path.c_str(), O_PATH | O_CLOEXEC);
    if (fd < 0) throw std::runtime_error("sandbox: cannot open \"" + path + "\" to allow writes beneath it");
    landlock_path_beneath_attr rule{rights, fd};
    long status = syscall(SYS_landlock_add_rule, ruleset, LANDLOCK_RULE_PATH_BENEATH, &rule, 0);
    close(fd);
    if (status != 0) throw std::runtime_error("sandbox: cannot allow writes beneath \"" + path + "\"");
}

int makeRuleset(std::vector<std::string> const& folders) {
    int abi = landlockAbi();
    if (abi < 1) return -1;
    __u64 const rights = writeRights(abi);
    landlock_ruleset_attr attributes{};
    attributes.handled_access_fs = rights;
    int ruleset = static_cast<int>(syscall(SYS_landlock_create_ruleset, &attributes, sizeof attributes, 0));
    if (ruleset < 0) return -1;
    fcntl(ruleset, F_SETFD, FD_CLOEXEC);
    try {
        for (std::string const& folder : folders) allowBeneath(ruleset, folder, rights);
        // Programs write to /dev/null freely; on a file only file rights apply.
        allowBeneath(ruleset, "/dev/null", rights & (LANDLOCK_ACCESS_FS_WRITE_FILE | LANDLOCK_ACCESS_FS_TRUNCATE));
    } catch (...) {
        close(ruleset);
        throw;
    }
    return ruleset;
}

/// A seccomp program that kills the process when it tries to start another
/// one, and refuses changes to file metadata.
std::vector<sock_filter> noNewProcessesFilter() {
    scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ALLOW);
    if (!ctx) throw std::runtime_error("sandbox: seccomp_init failed");
    int status = 0;
    status |= seccomp_rule_add(ctx, SCMP_ACT_KILL_PROCESS, SCMP_SYS(fork), 0);
    status |= seccomp_rule_add(ctx, SCMP_ACT_KILL_PROCESS, SCMP_SYS(vfork), 0);
    // clone without CLONE_THREAD makes a process; with it, a thread (TBB's workers).
    status |= seccomp_rule_add(ctx, SCMP_ACT_KILL_PROCESS, SCMP_SYS(clone), 1,
                               SCMP_A0_64(SCMP_CMP_MASKED_EQ, CLONE_THREAD, 0));
    // clone3 passes its flags in memory a filter cannot read: refuse it, and
    // the C library falls back to clone, which the rule above sees.
    status |= seccomp_rule_add(ctx, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3), 0);
    // Landlock guards contents and names; ownership, modes, times and extended
    // attributes are changed by calls plugins never need: refuse them anywhere.
    for (int call : {SCMP_SYS(chmod), SCMP_SYS(fchmod), SCMP_SYS(fchmodat), SCMP_SYS(chown), SCMP_SYS(fchown),
                     SCMP_SYS(lchown), SCMP_SYS(fchownat), SCMP_SYS(utime), SCMP_SYS(utimes), SCMP_SYS(futimesat),
                     SCMP_SYS(utimensat), SCMP_SYS(setxattr), SCMP_SYS(lsetxattr), SCMP_SYS(fsetxattr),
                     SCMP_SYS(removexattr), SCMP_SYS(lremovexattr), SCMP_SYS(fremovexattr)})
        status |= seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), call, 0);
    int memory = status == 0 ? memfd_create("rixgrade-seccomp", MFD_CLOEXEC) : -1;
    std::vector<sock_filter> program;
    if (memory >= 0 && seccomp_export_bpf(ctx, memory) == 0) {
        off_t size = lseek(memory, 0, SEEK_END);
        program.resize(static_cast<size_t>(size) / sizeof(sock_filter));
        if (pread(memory, program.data(), program.size() * sizeof(sock_filter), 0) != size) program.clear();
    }
    if (memory >= 0) close(memory);
    seccomp_release(ctx);
    if (program.empty()) throw std::runtime_error("sandbox: cannot build the seccomp filter");
    return program;
}

}  // namespace

Sandbox::Sandbox(SandboxPolicy const& policy) {
    if (!policy.writableFolders.empty()) m_ruleset = makeRuleset(policy.writableFolders);
    if (!policy.allowNewProcesses) m_filter = noNewProcessesFilter();
}

Sandbox::~Sandbox() {
    if (m_ruleset >= 0) close(m_ruleset);
}

bool Sandbox::enter() const noexcept {
    if (m_ruleset < 0 && m_filter.empty()) return true;
    // Both need it, and it makes sure no set-user-ID program can lift them.
    if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) return false;
    if (m_ruleset >= 0 && syscall(SYS_landlock_restrict_self, m_ruleset, 0) != 0) return false;
    if (!m_filter.empty()) {
        sock_fprog program{static_cast<unsigned short>(m_filter.size()), const_cast<sock_filter*>(m_filter.data())};
        if (prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &program) != 0) return false;
    }
    return true;
}

bool Sandbox::writeConfinementAvailable() { return landlockAbi() >= 1; }

}  // namespace rixgrade
