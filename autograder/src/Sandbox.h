// Runs student code (the build, every check, every render of a student
// plugin) in one kind of sandbox, and trusted reference code beside it.
//
// The sandbox is bubblewrap: new user, PID, IPC, UTS, cgroup and network
// namespaces (no network at all), no capabilities, --die-with-parent and
// --new-session; it sees the system read-only, the course parts it needs
// read-only under /course, its scratch folder read-write at /scratch, its
// built plugins read-only at /plugins and a small private /tmp -- nothing else of the machine (no home folders, no
// other submission, no reference solution). Its environment is built from
// scratch. Inside, rixjail adds the second wall (Landlock, seccomp) and the
// limits (CPU, address space, file size, processes). When the wall-clock
// limit passes, the whole sandbox is killed: its PID namespace ends with it,
// so no process of the submission survives. A grader running as root runs
// sandboxes as "nobody" (MountStaging lets nobody reach what they bind).
#pragma once

#include <sys/types.h>

#include "MountStaging.h"

#include <chrono>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace rixgrade {

using Clock = std::chrono::steady_clock;

struct Limits {
    double wallSeconds = 120.0;
    unsigned long long cpuSeconds = 300;
    unsigned long long memoryBytes = 4ull << 30;   ///< address space (0: unlimited)
    unsigned long long fileBytes = 64ull << 20;    ///< largest file it may write
    unsigned long long processes = 256;            ///< processes and threads
    unsigned long long scratchBytes = 1ull << 30;  ///< what its scratch folder may hold (checked while it runs)
    size_t outputBytes = 64 * 1024;                ///< kept of stdout and of stderr each
};

enum class Confinement {
    Sandbox,     ///< bubblewrap + rixjail: for student code
    JailOnly,    ///< rixjail alone (rixgrade --unsafe-no-sandbox, where namespaces are unavailable)
    Trusted,     ///< no confinement: the course's reference code
};

/// The folders a sandbox sees. Paths in a Launch are written as the sandbox
/// sees them (/scratch/..., /course/...); outside a sandbox they are mapped
/// back to the real folders.
struct SandboxLayout {
    std::string scratch;  ///< real folder, seen read-write as /scratch
    /// The submission's plugins as built, frozen in a folder outside the scratch
    /// one and seen read-only as /plugins (empty: none yet, during the build), so
    /// that no check or render can change what a later one loads.
    std::string plugins;
    std::vector<std::pair<std::string, std::string>> courseMounts;  ///< real path -> path under /course, read-only
    std::string jail;     ///< the real rixjail binary
    std::string courseRoot;  ///< the real course folder ("/course" itself, outside a sandbox)
    Confinement confinement = Confinement::Sandbox;
    /// The real path for a path as the sandbox sees it.
    std::string realPath(std::string const& inside) const;
};

struct Launch {
    std::vector<std::string> argv;
    std::string workdir = "/scratch";
    std::map<std::string, std::string> env;  ///< added to PATH, HOME, TMPDIR, LANG
    bool allowProcesses = false;             ///< builds start compilers; checks and renders may not
    Limits limits;
    std::vector<int> inputs;   ///< descriptors the child reads (the parent writes them)
    std::vector<int> outputs;  ///< descriptors the child writes (the parent reads them)
};

struct ExitStatus {
    int code = -1;        ///< when it exited
    int signal = 0;       ///< when a signal ended it (also reported by bubblewrap as 128 + signal)
    bool timedOut = false;
    bool scratchFull = false;  ///< stopped because its scratch folder grew past the limit
    /// "exited with status 2", "crashed with SIGSEGV", "did not finish within 120 s", ...
    std::string describe(Limits const& limits) const;
    bool ok() const { return !timedOut && !scratchFull && signal == 0 && code == 0; }
};

/// A started child. Reading from and writing to it never blocks past a
/// deadline, and keeps draining its stdout and stderr (capped) meanwhile.
class Child {
public:
    Child(SandboxLayout const& layout, Launch const& launch);
    ~Child();  ///< kills the child (and its sandbox) if it still runs
    Child(Child const&) = delete;
    Child& operator=(Child const&) = delete;

    enum class Io { Done, Ended, TimedOut };
    /// Writes all of `bytes` to the child's descriptor `fd`.
    Io write(int fd, void const* bytes, size_t size, Clock::time_point deadline);
    /// Reads exactly `size` bytes from the child's descriptor `fd`.
    Io read(int fd, void* bytes, size_t size, Clock::time_point deadline);
    /// Reads what the child writes to `fd` until it closes it, keeping at most `cap` bytes.
    Io readAll(int fd, std::string& sink, size_t cap, Clock::time_point deadline);
    /// Closes the parent's end of one of the child's input descriptors (it sees end of file).
    void closeInput(int fd);

    /// Waits for the child to end (killing it at the deadline).
    ExitStatus wait(Clock::time_point deadline);
    void kill();
    std::string const& out() const { return m_out; }
    std::string const& err() const { return m_err; }
    Limits const& limits() const { return m_limits; }
    double seconds() const;

private:
    int parentEnd(int childFd) const;
    /// One round of waiting: drains stdout/stderr, watches the scratch size;
    /// returns when `fd` is ready for `events` or the timeout passes.
    bool pump(int fd, short events, int timeoutMs);
    void reap(bool block);

    pid_t m_pid = -1;
    std::map<int, int> m_fds;  ///< child descriptor -> parent end
    int m_stdout = -1, m_stderr = -1;
    std::string m_out, m_err;
    Limits m_limits;
    std::string m_scratch;
    Clock::time_point m_start, m_lastScratchCheck;
    bool m_exited = false, m_scratchFull = false;
    int m_status = 0;
    MountStaging m_staging;  ///< what bubblewrap binds, reachable by nobody (a grader running as root)
};

/// Runs a launch to completion (no extra descriptors): builds, renders.
struct Finished {
    ExitStatus status;
    std::string out, err;
    double seconds = 0.0;
};
Finished runToEnd(SandboxLayout const& layout, Launch const& launch);

/// Whether bubblewrap can create its namespaces here and bind everything `layout`
/// names (its scratch field is the folder scratch folders go in); `why` says what failed.
bool sandboxAvailable(SandboxLayout layout, std::string& why);

/// Without the sandbox, a grader running as root runs student code as nobody
/// straight from the real folders. Returns the first of `paths` (with the
/// access(2) mode it needs) that nobody cannot use -- a folder above it closed to
/// other users -- or "" when all are usable (or the grader is not root).
std::string unusableByNobody(std::vector<std::pair<std::string, int>> const& paths);

/// Bytes held by a folder's files (symbolic links not followed).
unsigned long long folderBytes(std::string const& folder);

}  // namespace rixgrade
