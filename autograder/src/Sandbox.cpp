#include "Sandbox.h"

#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace rixgrade {
namespace {

constexpr uid_t kNobody = 65534;
constexpr char const* kScratch = "/scratch";
constexpr char const* kCourse = "/course";
constexpr char const* kPlugins = "/plugins";

bool startsWith(std::string const& s, std::string const& prefix) {
    return s.compare(0, prefix.size(), prefix) == 0 && (s.size() == prefix.size() || s[prefix.size()] == '/');
}

std::string signalName(int signal) {
    switch (signal) {
        case SIGSEGV: return "SIGSEGV";
        case SIGABRT: return "SIGABRT";
        case SIGFPE: return "SIGFPE";
        case SIGBUS: return "SIGBUS";
        case SIGILL: return "SIGILL";
        case SIGKILL: return "SIGKILL";
        case SIGXCPU: return "SIGXCPU";
        case SIGXFSZ: return "SIGXFSZ";
        case SIGSYS: return "SIGSYS";
        case SIGTERM: return "SIGTERM";
        default: return "signal " + std::to_string(signal);
    }
}

/// The system folders student code sees (merged /usr: the others are mostly links into it).
constexpr char const* kSystemFolders[] = {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"};
/// What the dynamic loader and the compiler drivers need of /etc, and nothing else of it.
constexpr char const* kSystemFiles[] = {"/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/alternatives"};

/// The system every sandbox sees read-only.
void addSystem(std::vector<std::string>& args) {
    args.insert(args.end(), {"--ro-bind", "/usr", "/usr"});
    for (char const* top : kSystemFolders) {
        std::error_code error;
        if (fs::is_symlink(top, error)) {
            args.insert(args.end(), {"--symlink", fs::read_symlink(top, error).string(), top});
        } else if (fs::is_directory(top, error)) {
            args.insert(args.end(), {"--ro-bind", top, top});
        }
    }
    for (char const* file : kSystemFiles) args.insert(args.end(), {"--ro-bind-try", file, file});
    args.insert(args.end(), {"--proc", "/proc", "--dev", "/dev", "--size", std::to_string(64 << 20), "--tmpfs", "/tmp"});
}

}  // namespace

std::string SandboxLayout::realPath(std::string const& inside) const {
    if (confinement == Confinement::Sandbox) return inside;
    if (startsWith(inside, kScratch)) return scratch + inside.substr(std::strlen(kScratch));
    if (!plugins.empty() && startsWith(inside, kPlugins))
        return plugins + inside.substr(std::strlen(kPlugins));
    for (auto const& [real, under] : courseMounts) {
        std::string mounted = std::string(kCourse) + "/" + under;
        if (startsWith(inside, mounted)) return real + inside.substr(mounted.size());
    }
    if (inside == std::string(kCourse) + "/bin/rixjail") return jail;
    if (inside == kCourse) return courseRoot;
    return inside;
}

std::string ExitStatus::describe(Limits const& limits) const {
    if (timedOut) return "did not finish within " + std::to_string(static_cast<int>(limits.wallSeconds)) + " s";
    if (scratchFull)
        return "was stopped: its scratch folder grew past " + std::to_string(limits.scratchBytes >> 20) + " MB";
    if (signal == SIGSYS) return "was stopped (SIGSYS): it tried to start a process, which plugins may not do";
    if (signal == SIGXCPU) return "was stopped (SIGXCPU): it used more than " + std::to_string(limits.cpuSeconds) + " s of CPU";
    if (signal == SIGXFSZ)
        return "was stopped (SIGXFSZ): it wrote a file larger than " + std::to_string(limits.fileBytes >> 20) + " MB";
    if (signal == SIGKILL) return "was killed (SIGKILL), most likely for using too much memory";
    if (signal) return "crashed with " + signalName(signal);
    if (code == 125) return "could not be confined (exit status 125)";
    if (code == 127) return "could not be started (exit status 127)";
    return "exited with status " + std::to_string(code);
}

Child::Child(SandboxLayout const& layout, Launch const& launch) : m_limits(launch.limits) {
    m_scratch = layout.scratch;
    bool const sandboxed = layout.confinement == Confinement::Sandbox;
    bool const dropToNobody = geteuid() == 0 && layout.confinement != Confinement::Trusted;
    std::string const scratchInside = sandboxed ? kScratch : layout.scratch;
    std::string const tmpInside = sandboxed ? "/tmp" : layout.scratch + "/tmp";

    // Everything that allocates happens before fork: a multi-threaded parent's
    // child may only make system calls until it execs.
    std::vector<std::string> args;
    std::vector<size_t> sources;  // where in args the folders bubblewrap binds are
    if (sandboxed) {
        args = {"bwrap",         "--unshare-all",  "--unshare-user", "--disable-userns", "--die-with-parent",
                "--new-session", "--cap-drop",     "ALL",            "--uid",            std::to_string(kNobody),
                "--gid",         std::to_string(kNobody), "--hostname", "sandbox"};
        addSystem(args);
        auto bind = [&](char const* how, std::string const& real, std::string const& inside) {
            sources.push_back(args.size() + 1);
            args.insert(args.end(), {how, real, inside});
        };
        bind("--bind", layout.scratch, kScratch);
        if (!layout.plugins.empty()) bind("--ro-bind", layout.plugins, kPlugins);
        for (auto const& [real, under] : layout.courseMounts) bind("--ro-bind", real, std::string(kCourse) + "/" + under);
        if (!layout.jail.empty()) bind("--ro-bind", layout.jail, std::string(kCourse) + "/bin/rixjail");
        args.insert(args.end(), {"--chdir", launch.workdir, "--clearenv"});
    }
    std::map<std::string, std::string> env = {{"PATH", "/usr/bin:/bin"},
                                              {"HOME", scratchInside + "/home"},
                                              {"TMPDIR", tmpInside},
                                              {"LANG", "C.UTF-8"}};
    for (auto const& [key, value] : launch.env) env[key] = layout.realPath(value);
#ifdef BXDFLAB_SANITIZE
    // Sanitizer-built children: ASan enforces the memory limit (it reserves terabytes of address
    // space, so RLIMIT_AS cannot), LeakSanitizer's helper process is refused by the jail, and a
    // segfault is left to kill the child so it is reported as the same signal as in a regular build.
    env["ASAN_OPTIONS"] = "detect_leaks=0:handle_segv=0:max_allocation_size_mb=" + std::to_string(m_limits.memoryBytes >> 20);
    unsigned long long const memory = 0;
#else
    unsigned long long const memory = m_limits.memoryBytes;
#endif
    if (sandboxed)
        for (auto const& [key, value] : env) args.insert(args.end(), {"--setenv", key, value});
    if (layout.confinement != Confinement::Trusted && !layout.jail.empty()) {
        args.insert(args.end(), {sandboxed ? std::string(kCourse) + "/bin/rixjail" : layout.jail});
        if (!launch.allowProcesses) args.push_back("--no-processes");
        args.insert(args.end(), {"--cpu", std::to_string(m_limits.cpuSeconds), "--memory", std::to_string(memory),
                                 "--file-size", std::to_string(m_limits.fileBytes), "--processes",
                                 std::to_string(m_limits.processes)});
        if (!layout.scratch.empty()) args.insert(args.end(), {"--writable", scratchInside, "--writable", tmpInside});
        if (!sandboxed) {
            // Without the sandbox's mounts, Landlock keeps reads to what a sandbox would
            // see: the system, the course's mounts, the scratch folder -- not the
            // reference solutions, not other submissions, not the grader's output.
            for (char const* system : {"/usr", "/proc", "/dev"}) args.insert(args.end(), {"--readable", system});
            for (char const* top : kSystemFolders) args.insert(args.end(), {"--readable", top});
            for (char const* file : kSystemFiles) args.insert(args.end(), {"--readable", file});
            for (auto const& [real, under] : layout.courseMounts) args.insert(args.end(), {"--readable", real});
            if (!layout.plugins.empty()) args.insert(args.end(), {"--readable", layout.plugins});
            args.insert(args.end(), {"--readable", layout.jail});
        }
        args.push_back("--");
    }
    for (auto const& a : launch.argv) {
        // "-DNAME=/course/..." maps its value like a plain path; "/a:/b:/c" (a plugin
        // path) maps each folder -- left as it was, the student's folder would not be
        // searched and rixrender would fall back to its own folders, the solutions'.
        size_t equals = a.find("=/");
        if (sandboxed)
            args.push_back(a);
        else if (equals != std::string::npos && a.rfind("-D", 0) == 0)
            args.push_back(a.substr(0, equals + 1) + layout.realPath(a.substr(equals + 1)));
        else if (a.rfind("/", 0) == 0 && a.find(':') != std::string::npos) {
            std::string mapped, folder;
            std::istringstream folders(a);
            while (std::getline(folders, folder, ':')) mapped += (mapped.empty() ? "" : ":") + layout.realPath(folder);
            args.push_back(mapped);
        } else
            args.push_back(layout.realPath(a));
    }
    std::string const workdir = layout.realPath(launch.workdir);

    std::vector<std::string> envStrings;
    for (auto const& [key, value] : env) envStrings.push_back(key + "=" + value);
    // Running as nobody, bubblewrap binds the staged paths; where the child cannot
    // stage them (no CAP_SYS_ADMIN in a container), it binds the real ones.
    std::vector<std::string> stagedArgs;
    if (dropToNobody && sandboxed) {
        stagedArgs = args;
        for (size_t at : sources) stagedArgs[at] = m_staging.stage(args[at]);
    }
    std::vector<char*> argv, stagedArgv, envp;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    for (auto& a : stagedArgs) stagedArgv.push_back(a.data());
    stagedArgv.push_back(nullptr);
    for (auto& e : envStrings) envp.push_back(e.data());
    envp.push_back(nullptr);
    std::string program = sandboxed ? "/usr/bin/bwrap" : args[0];

    // Pipes: child descriptor -> {child end, parent end}.
    std::vector<std::pair<int, int>> childEnds;  // (target descriptor, child end)
    auto makePipe = [&](int target, bool childReads) {
        int p[2];
        if (pipe2(p, O_CLOEXEC) != 0) throw std::runtime_error("cannot create a pipe");
        int childEnd = childReads ? p[0] : p[1], parentEnd = childReads ? p[1] : p[0];
        // Measurements move megabytes at a time: a 1 MiB pipe (the unprivileged
        // limit) saves the two processes a switch every 64 KiB. Best effort.
        fcntl(p[0], F_SETPIPE_SZ, 1 << 20);
        childEnds.emplace_back(target, childEnd);
        fcntl(parentEnd, F_SETFL, O_NONBLOCK);
        return parentEnd;
    };
    m_stdout = makePipe(STDOUT_FILENO, false);
    m_stderr = makePipe(STDERR_FILENO, false);
    for (int fd : launch.inputs) m_fds[fd] = makePipe(fd, true);
    for (int fd : launch.outputs) m_fds[fd] = makePipe(fd, false);
    int highest = 2;
    for (auto const& [target, end] : childEnds) highest = std::max(highest, target);

    m_start = m_lastScratchCheck = Clock::now();
    m_pid = fork();
    if (m_pid < 0) throw std::runtime_error("cannot fork");
    if (m_pid == 0) {
        // Move every child end above the targets first, so no dup2 overwrites another.
        for (auto& [target, end] : childEnds) end = fcntl(end, F_DUPFD_CLOEXEC, highest + 1);
        for (auto const& [target, end] : childEnds) dup2(end, target);
        bool stdinTaken = false;
        for (auto const& [target, end] : childEnds) stdinTaken = stdinTaken || target == STDIN_FILENO;
        int devnull = stdinTaken ? -1 : open("/dev/null", O_RDONLY);
        if (devnull >= 0) dup2(devnull, STDIN_FILENO);
        syscall(SYS_close_range, highest + 1, ~0u, 0);
        setpgid(0, 0);
        char* const* chosen = !stagedArgs.empty() && m_staging.mountAll() ? stagedArgv.data() : argv.data();
        if (dropToNobody && (setgroups(0, nullptr) != 0 || setgid(kNobody) != 0 || setuid(kNobody) != 0)) _exit(125);
        if (!sandboxed && chdir(workdir.c_str()) != 0) _exit(126);
        execve(program.c_str(), chosen, envp.data());
        _exit(127);
    }
    setpgid(m_pid, m_pid);
    for (auto const& [target, end] : childEnds) close(end);
}

Child::~Child() {
    if (!m_exited) kill();
    for (int fd : {m_stdout, m_stderr})
        if (fd >= 0) close(fd);
    for (auto const& [target, fd] : m_fds)
        if (fd >= 0) close(fd);
}

double Child::seconds() const { return std::chrono::duration<double>(Clock::now() - m_start).count(); }

int Child::parentEnd(int childFd) const {
    auto found = m_fds.find(childFd);
    if (found == m_fds.end()) throw std::logic_error("the child has no descriptor " + std::to_string(childFd));
    return found->second;
}

void Child::reap(bool block) {
    if (m_exited || m_pid < 0) return;
    if (waitpid(m_pid, &m_status, block ? 0 : WNOHANG) == m_pid) m_exited = true;
}

bool Child::pump(int fd, short events, int timeoutMs) {
    pollfd fds[3];
    int n = 0;
    if (fd >= 0) fds[n++] = {fd, events, 0};
    int firstOutput = n;
    if (m_stdout >= 0) fds[n++] = {m_stdout, POLLIN, 0};
    if (m_stderr >= 0) fds[n++] = {m_stderr, POLLIN, 0};
    int ready = poll(fds, static_cast<nfds_t>(n), timeoutMs);
    bool target = false;
    if (ready > 0) {
        if (fd >= 0 && fds[0].revents) target = true;
        for (int k = firstOutput; k < n; ++k) {
            if (!fds[k].revents) continue;
            bool isOut = fds[k].fd == m_stdout;
            std::string& sink = isOut ? m_out : m_err;
            char buffer[16384];
            ssize_t got = ::read(fds[k].fd, buffer, sizeof buffer);
            if (got > 0) {
                size_t keep = std::min(static_cast<size_t>(got), m_limits.outputBytes - std::min(m_limits.outputBytes, sink.size()));
                sink.append(buffer, keep);
            } else if (got == 0 || (errno != EAGAIN && errno != EINTR)) {
                close(fds[k].fd);
                (isOut ? m_stdout : m_stderr) = -1;
            }
        }
    }
    reap(false);
    // A build may fill the disk faster than any single file limit catches: watch the whole folder.
    if (!m_exited && !m_scratch.empty() && m_limits.scratchBytes &&
        Clock::now() - m_lastScratchCheck > std::chrono::milliseconds(500)) {
        m_lastScratchCheck = Clock::now();
        if (folderBytes(m_scratch) > m_limits.scratchBytes) {
            m_scratchFull = true;
            kill();
        }
    }
    return target;
}

Child::Io Child::write(int childFd, void const* bytes, size_t size, Clock::time_point deadline) {
    int fd = parentEnd(childFd);
    char const* p = static_cast<char const*>(bytes);
    while (size > 0) {
        ssize_t n = ::write(fd, p, size);
        if (n > 0) {
            p += n;
            size -= static_cast<size_t>(n);
            continue;
        }
        if (n < 0 && errno != EAGAIN && errno != EINTR) return Io::Ended;  // EPIPE: it closed or died
        if (m_exited) return Io::Ended;
        if (Clock::now() > deadline) return Io::TimedOut;
        pump(fd, POLLOUT, 100);
    }
    return Io::Done;
}

Child::Io Child::read(int childFd, void* bytes, size_t size, Clock::time_point deadline) {
    int fd = parentEnd(childFd);
    char* p = static_cast<char*>(bytes);
    while (size > 0) {
        ssize_t n = ::read(fd, p, size);
        if (n > 0) {
            p += n;
            size -= static_cast<size_t>(n);
            continue;
        }
        if (n == 0) return Io::Ended;
        if (errno != EAGAIN && errno != EINTR) return Io::Ended;
        if (Clock::now() > deadline) return Io::TimedOut;
        pump(fd, POLLIN, 100);
    }
    return Io::Done;
}

Child::Io Child::readAll(int childFd, std::string& sink, size_t cap, Clock::time_point deadline) {
    int fd = parentEnd(childFd);
    for (;;) {
        char buffer[65536];
        ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n > 0) {
            size_t keep = std::min(static_cast<size_t>(n), cap - std::min(cap, sink.size()));
            sink.append(buffer, keep);
            continue;
        }
        if (n == 0) return Io::Ended;
        if (errno != EAGAIN && errno != EINTR) return Io::Ended;
        if (Clock::now() > deadline) return Io::TimedOut;
        pump(fd, POLLIN, 100);
    }
}

void Child::closeInput(int childFd) {
    auto found = m_fds.find(childFd);
    if (found != m_fds.end() && found->second >= 0) {
        close(found->second);
        found->second = -1;
    }
}

void Child::kill() {
    if (m_pid > 0 && !m_exited) {
        // bubblewrap dies, and with it (--die-with-parent) the sandbox's PID
        // namespace and every process in it.
        ::kill(-m_pid, SIGKILL);
        ::kill(m_pid, SIGKILL);
    }
    reap(true);
}

ExitStatus Child::wait(Clock::time_point deadline) {
    ExitStatus status;
    while (!m_exited && Clock::now() < deadline && !m_scratchFull) pump(-1, 0, 100);
    if (!m_exited) {
        status.timedOut = !m_scratchFull;
        kill();
    }
    // What it wrote just before it ended (a grandchild may hold the pipes: give up after a moment).
    for (auto until = Clock::now() + std::chrono::seconds(2); (m_stdout >= 0 || m_stderr >= 0) && Clock::now() < until;)
        pump(-1, 0, 50);
    status.scratchFull = m_scratchFull;
    if (status.timedOut || status.scratchFull) return status;
    if (WIFEXITED(m_status)) status.code = WEXITSTATUS(m_status);
    if (WIFSIGNALED(m_status)) status.signal = WTERMSIG(m_status);
    // bubblewrap reports a program killed by a signal as 128 + the signal.
    if (status.code > 128 && status.code < 128 + 65) {
        status.signal = status.code - 128;
        status.code = -1;
    }
    return status;
}

Finished runToEnd(SandboxLayout const& layout, Launch const& launch) {
    Child child(layout, launch);
    Finished f;
    f.status = child.wait(Clock::now() + std::chrono::milliseconds(static_cast<long>(launch.limits.wallSeconds * 1000)));
    f.out = child.out();
    f.err = child.err();
    f.seconds = child.seconds();
    return f;
}

bool sandboxAvailable(SandboxLayout layout, std::string& why) {
    std::string folder = layout.scratch + "/rixgrade-probe-XXXXXX";
    if (!mkdtemp(folder.data())) {
        why = "cannot create a temporary folder in " + layout.scratch;
        return false;
    }
    if (geteuid() == 0 && chown(folder.c_str(), kNobody, kNobody) != 0) {
        why = "cannot hand a folder to nobody";
        return false;
    }
    // The grading's own mounts, so that a folder bubblewrap cannot bind stops grading
    // here, with bubblewrap's words, rather than failing every student's checks.
    layout.scratch = folder;
    layout.confinement = Confinement::Sandbox;
    Launch launch;
    launch.argv = {"/bin/true"};
    launch.workdir = "/";
    launch.limits.wallSeconds = 20;
    Finished f = runToEnd(layout, launch);
    std::error_code error;
    fs::remove_all(folder, error);
    if (f.status.ok()) return true;
    why = "bubblewrap (/usr/bin/bwrap) could not start a sandbox: " + f.status.describe(launch.limits) +
          (f.err.empty() ? "" : ": " + f.err.substr(0, 300));
    if (geteuid() == 0 && f.err.find("Permission denied") != std::string::npos)
        why += "\n  Student code runs as the user nobody, who cannot enter a folder above that path (and this "
               "machine does not let rixgrade remount it): move the course or TMPDIR where every user may enter.";
    return false;
}

std::string unusableByNobody(std::vector<std::pair<std::string, int>> const& paths) {
    if (geteuid() != 0 || paths.empty()) return "";
    int answer[2];
    if (pipe2(answer, O_CLOEXEC) != 0) throw std::runtime_error("cannot create a pipe");
    pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("cannot fork");
    if (pid == 0) {
        // access(2) checks the real user: after setuid, nobody's own view of each path.
        if (setgroups(0, nullptr) != 0 || setgid(kNobody) != 0 || setuid(kNobody) != 0) _exit(1);
        uint32_t first = 0;
        while (first < paths.size() && access(paths[first].first.c_str(), paths[first].second) == 0) ++first;
        ssize_t written = ::write(answer[1], &first, sizeof first);
        _exit(written == sizeof first ? 0 : 1);
    }
    close(answer[1]);
    uint32_t first = 0;
    ssize_t got = ::read(answer[0], &first, sizeof first);
    close(answer[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (got != sizeof first) throw std::runtime_error("cannot check what the user nobody can reach");
    return first < paths.size() ? paths[first].first : "";
}

unsigned long long folderBytes(std::string const& folder) {
    unsigned long long total = 0;
    std::error_code error;
    for (fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, error), end;
         !error && it != end; it.increment(error)) {
        struct stat st;
        if (lstat(it->path().c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
            total += static_cast<unsigned long long>(st.st_blocks) * 512ull;
    }
    return total;
}

}  // namespace rixgrade
