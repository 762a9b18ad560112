#include "ChildProcess.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <stdexcept>

namespace rixgrade {

std::string Outcome::describe(Limits const& limits) const {
    if (timedOut) return "did not finish within " + std::to_string(static_cast<int>(limits.seconds)) + " s (an endless loop?)";
    if (signal) {
        const char* name = signal == SIGSEGV ? "SIGSEGV" : signal == SIGABRT ? "SIGABRT" : signal == SIGFPE ? "SIGFPE"
                           : signal == SIGKILL ? "SIGKILL (a resource limit?)" : signal == SIGXCPU ? "SIGXCPU (CPU limit)"
                           : signal == SIGBUS ? "SIGBUS" : "a signal";
        if (signal == SIGSYS) return "was stopped (SIGSYS): it tried to start a process, which plugins may not do";
        return std::string("crashed with ") + name + " (signal " + std::to_string(signal) + ")";
    }
    if (exitCode == 125) return "could not be confined to its scratch folder (exit status 125)";
    return "exited with status " + std::to_string(exitCode);
}

namespace {

/// This process's environment with `extra` added, as KEY=VALUE strings.
std::vector<std::string> childEnvironment(std::map<std::string, std::string> const& extra, Limits const& limits) {
    std::map<std::string, std::string> merged;
    for (char** entry = environ; *entry; ++entry) {
        std::string const text = *entry;
        size_t const equals = text.find('=');
        if (equals != std::string::npos) merged[text.substr(0, equals)] = text.substr(equals + 1);
    }
    for (auto const& [key, value] : extra) merged[key] = value;
#ifdef BXDFLAB_SANITIZE
    // Children built with AddressSanitizer: ASan enforces the memory limit (it reserves terabytes of
    // address space, so RLIMIT_AS cannot), and leak checking is off (LeakSanitizer inspects the
    // process from a helper process, which the sandbox refuses). A segfault is left to kill the child,
    // so it is reported as the same signal as in a regular build.
    merged["ASAN_OPTIONS"] +=
        ":detect_leaks=0:handle_segv=0:max_allocation_size_mb=" + std::to_string(limits.memoryBytes >> 20);
#else
    (void)limits;
#endif
    std::vector<std::string> strings;
    for (auto const& [key, value] : merged) strings.push_back(key + "=" + value);
    return strings;
}

#ifdef BXDFLAB_SANITIZE
constexpr bool kLimitAddressSpace = false;  // see childEnvironment
#else
constexpr bool kLimitAddressSpace = true;
#endif

}  // namespace

Outcome run(std::vector<std::string> const& argv, std::map<std::string, std::string> const& environment,
            std::string const& workingDirectory, Limits const& limits, SandboxPolicy const& sandboxPolicy) {
    // Everything that allocates happens before fork: between fork and exec the
    // child of a multi-threaded grader may only make system calls.
    Sandbox const sandbox(sandboxPolicy);
    std::vector<std::string> envStrings = childEnvironment(environment, limits);
    std::vector<char*> envp, args;
    for (auto& e : envStrings) envp.push_back(e.data());
    envp.push_back(nullptr);
    for (auto const& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);

    int outPipe[2], errPipe[2];
    // Close-on-exec: another check started at the same moment (class mode) must not inherit them.
    if (pipe2(outPipe, O_CLOEXEC) != 0 || pipe2(errPipe, O_CLOEXEC) != 0) throw std::runtime_error("cannot create pipes");
    auto start = std::chrono::steady_clock::now();
    pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("cannot fork");
    if (pid == 0) {
        // The child: its own process group (so a timeout kills everything it
        // started), limits, no core files, then the program.
        setpgid(0, 0);
        rlimit memory{limits.memoryBytes, limits.memoryBytes}, cpu{limits.cpuSeconds, limits.cpuSeconds + 5},
            core{0, 0};
        if (kLimitAddressSpace) setrlimit(RLIMIT_AS, &memory);
        setrlimit(RLIMIT_CPU, &cpu);
        setrlimit(RLIMIT_CORE, &core);
        dup2(outPipe[1], STDOUT_FILENO);
        dup2(errPipe[1], STDERR_FILENO);
        close(outPipe[0]);
        close(errPipe[0]);
        int devnull = open("/dev/null", O_RDONLY);
        if (devnull >= 0) dup2(devnull, STDIN_FILENO);
        if (!workingDirectory.empty() && chdir(workingDirectory.c_str()) != 0) _exit(126);
        if (!sandbox.enter()) _exit(125);
        execvpe(args[0], args.data(), envp.data());
        _exit(127);
    }
    setpgid(pid, pid);
    close(outPipe[1]);
    close(errPipe[1]);

    Outcome outcome;
    std::string* sinks[2] = {&outcome.out, &outcome.err};
    pollfd fds[2] = {{outPipe[0], POLLIN, 0}, {errPipe[0], POLLIN, 0}};
    int open = 2, status = 0;
    bool exited = false;
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    while (open > 0 || !exited) {
        if (elapsed() > limits.seconds) {
            kill(-pid, SIGKILL);
            outcome.timedOut = true;
            break;
        }
        if (open > 0) {
            int ready = poll(fds, 2, 100);
            for (int k = 0; k < 2 && ready > 0; ++k) {
                if (fds[k].fd < 0 || !(fds[k].revents & (POLLIN | POLLHUP))) continue;
                char buffer[8192];
                ssize_t n = read(fds[k].fd, buffer, sizeof buffer);
                if (n <= 0) {
                    close(fds[k].fd);
                    fds[k].fd = -1;
                    --open;
                } else if (sinks[k]->size() < limits.outputBytes) {
                    sinks[k]->append(buffer, static_cast<size_t>(std::min<ssize_t>(n, static_cast<ssize_t>(limits.outputBytes - sinks[k]->size()))));
                }
            }
        } else {
            usleep(2000);
        }
        if (!exited && waitpid(pid, &status, WNOHANG) == pid) exited = true;
    }
    for (auto& fd : fds)
        if (fd.fd >= 0) close(fd.fd);
    if (!exited) waitpid(pid, &status, 0);
    kill(-pid, SIGKILL);  // anything the child left behind
    outcome.seconds = elapsed();
    if (!outcome.timedOut) {
        if (WIFEXITED(status)) outcome.exitCode = WEXITSTATUS(status);
        if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
    }
    return outcome;
}

}  // namespace rixgrade
