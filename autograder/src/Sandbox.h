// Confines a child process that runs student code, beyond the resource limits:
//   - files: it may write only beneath the folders it is given (and to
//     /dev/null); anything else fails with EACCES. Linux Landlock, which needs
//     no privileges (kernel 5.13 or later; Debian 12's kernel has it).
//   - processes: it may start threads but no process (fork, vfork, clone
//     without CLONE_THREAD); trying kills it with SIGSYS, so a fork bomb ends
//     at its first fork. Nor may it change any file's mode, owner, times or
//     extended attributes (EPERM). A seccomp filter (libseccomp).
// Both are prepared in the parent (they allocate); the child only applies them
// between fork and exec, where nothing but system calls is safe.
#pragma once

#include <linux/filter.h>

#include <string>
#include <vector>

namespace rixgrade {

struct SandboxPolicy {
    std::vector<std::string> writableFolders;  ///< empty: no write confinement
    bool allowNewProcesses = true;             ///< false: the seccomp filter (no processes, no metadata changes)
};

class Sandbox {
public:
    explicit Sandbox(SandboxPolicy const& policy);
    ~Sandbox();
    Sandbox(Sandbox const&) = delete;
    Sandbox& operator=(Sandbox const&) = delete;

    /// In the child, after fork and before exec. Returns false if a restriction
    /// that was prepared could not be applied (the child must then not run).
    bool enter() const noexcept;

    /// Whether writes are confined (false when the kernel lacks Landlock).
    bool confinesWrites() const { return m_ruleset >= 0; }

    /// Whether this kernel offers Landlock at all.
    static bool writeConfinementAvailable();

private:
    int m_ruleset = -1;                   ///< Landlock ruleset, or -1
    std::vector<sock_filter> m_filter;    ///< seccomp program, empty when processes are allowed
};

}  // namespace rixgrade
