// rixjail: the inner wall around student code, run inside the bubblewrap
// sandbox just before the student's program (or alone, under
// rixgrade --unsafe-no-sandbox):
//
//   rixjail [--no-processes] [--cpu S] [--memory B] [--file-size B]
//           [--processes N] [--writable DIR]... [--readable PATH]... -- PROGRAM ARGS...
//
//   limits     CPU seconds, address space, size of any file written, number
//              of processes/threads, open files, no core files;
//   files      writes only beneath the --writable folders and /dev/null
//              (Landlock, Linux 5.13+; skipped with a note when missing);
//              with --readable, reads and runs only beneath the --readable
//              and --writable paths too (without the bubblewrap sandbox, that
//              is what keeps the reference solutions and classmates' work
//              out of reach; a --readable path that does not exist is skipped);
//   processes  with --no-processes a seccomp filter kills the program when it
//              tries to start another one (threads stay allowed) and refuses
//              changes of file modes, owners, times and attributes.
// Exit status 125 when a restriction could not be applied.
#include <fcntl.h>
#include <linux/landlock.h>
#include <linux/seccomp.h>
#include <sched.h>
#include <seccomp.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#ifndef LANDLOCK_ACCESS_FS_TRUNCATE
#define LANDLOCK_ACCESS_FS_TRUNCATE (1ULL << 14)
#endif

namespace {

[[noreturn]] void fail(std::string const& why) {
    std::fprintf(stderr, "rixjail: %s\n", why.c_str());
    std::_Exit(125);
}

void limit(int resource, unsigned long long value, char const* name) {
    rlimit r{value, value};
    if (setrlimit(resource, &r) != 0) fail(std::string("cannot limit ") + name + ": " + std::strerror(errno));
}

int landlockAbi() {
    long abi = syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
    return abi < 0 ? 0 : static_cast<int>(abi);
}

void confineFiles(std::vector<std::string> const& folders, std::vector<std::string> const& readable) {
    int abi = landlockAbi();
    if (abi < 1) {
        std::fprintf(stderr, "rixjail: note: no Landlock in this kernel; writes are confined by the sandbox's mounts only\n");
        return;
    }
    __u64 rights = LANDLOCK_ACCESS_FS_WRITE_FILE | LANDLOCK_ACCESS_FS_REMOVE_DIR | LANDLOCK_ACCESS_FS_REMOVE_FILE |
                   LANDLOCK_ACCESS_FS_MAKE_CHAR | LANDLOCK_ACCESS_FS_MAKE_DIR | LANDLOCK_ACCESS_FS_MAKE_REG |
                   LANDLOCK_ACCESS_FS_MAKE_SOCK | LANDLOCK_ACCESS_FS_MAKE_FIFO | LANDLOCK_ACCESS_FS_MAKE_BLOCK |
                   LANDLOCK_ACCESS_FS_MAKE_SYM;
    if (abi >= 2) rights |= LANDLOCK_ACCESS_FS_REFER;
    if (abi >= 3) rights |= LANDLOCK_ACCESS_FS_TRUNCATE;
    __u64 const reads = readable.empty() ? 0 : LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_READ_DIR |
                                                   LANDLOCK_ACCESS_FS_EXECUTE;
    landlock_ruleset_attr attributes{};
    attributes.handled_access_fs = rights | reads;
    int ruleset = static_cast<int>(syscall(SYS_landlock_create_ruleset, &attributes, sizeof attributes, 0));
    if (ruleset < 0) fail("cannot create a Landlock ruleset");
    auto allow = [&](std::string const& path, __u64 allowed) {
        int fd = open(path.c_str(), O_PATH | O_CLOEXEC);
        if (fd < 0 && reads && allowed == reads && errno == ENOENT) return;  // a --readable path this machine lacks
        if (fd < 0) fail("cannot open \"" + path + "\" to allow access beneath it");
        struct stat info {};
        if (fstat(fd, &info) == 0 && !S_ISDIR(info.st_mode))
            allowed &= LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_EXECUTE | LANDLOCK_ACCESS_FS_WRITE_FILE |
                       LANDLOCK_ACCESS_FS_TRUNCATE;  // the rights a file (not a folder) can carry
        landlock_path_beneath_attr rule{allowed, fd};
        if (syscall(SYS_landlock_add_rule, ruleset, LANDLOCK_RULE_PATH_BENEATH, &rule, 0) != 0)
            fail("cannot allow access beneath \"" + path + "\"");
        close(fd);
    };
    for (auto const& folder : folders) allow(folder, rights | reads);
    for (auto const& path : readable) allow(path, reads);
    allow("/dev/null", (rights | reads) & (LANDLOCK_ACCESS_FS_WRITE_FILE | LANDLOCK_ACCESS_FS_TRUNCATE |
                                           LANDLOCK_ACCESS_FS_READ_FILE));
    if (syscall(SYS_landlock_restrict_self, ruleset, 0) != 0) fail("cannot enter the Landlock ruleset");
    close(ruleset);
}

void forbidProcesses() {
    scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ALLOW);
    if (!ctx) fail("seccomp_init failed");
    int status = 0;
    status |= seccomp_rule_add(ctx, SCMP_ACT_KILL_PROCESS, SCMP_SYS(fork), 0);
    status |= seccomp_rule_add(ctx, SCMP_ACT_KILL_PROCESS, SCMP_SYS(vfork), 0);
    // clone without CLONE_THREAD makes a process; with it, a thread (TBB's workers).
    status |= seccomp_rule_add(ctx, SCMP_ACT_KILL_PROCESS, SCMP_SYS(clone), 1,
                               SCMP_A0_64(SCMP_CMP_MASKED_EQ, CLONE_THREAD, 0));
    // clone3 passes its flags in memory a filter cannot read: refuse it, and
    // the C library falls back to clone, which the rule above sees.
    status |= seccomp_rule_add(ctx, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3), 0);
    for (int call : {SCMP_SYS(chmod), SCMP_SYS(fchmod), SCMP_SYS(fchmodat), SCMP_SYS(chown), SCMP_SYS(fchown),
                     SCMP_SYS(lchown), SCMP_SYS(fchownat), SCMP_SYS(utime), SCMP_SYS(utimes), SCMP_SYS(futimesat),
                     SCMP_SYS(utimensat), SCMP_SYS(setxattr), SCMP_SYS(lsetxattr), SCMP_SYS(fsetxattr),
                     SCMP_SYS(removexattr), SCMP_SYS(lremovexattr), SCMP_SYS(fremovexattr), SCMP_SYS(ptrace),
                     SCMP_SYS(process_vm_writev), SCMP_SYS(process_vm_readv)})
        status |= seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), call, 0);
    if (status != 0 || seccomp_load(ctx) != 0) fail("cannot load the seccomp filter");
    seccomp_release(ctx);
}

unsigned long long number(char const* text, char const* option) {
    char* end = nullptr;
    unsigned long long v = std::strtoull(text, &end, 10);
    if (!end || *end) fail(std::string("bad number for ") + option + ": " + text);
    return v;
}

}  // namespace

int main(int argc, char** argv) {
    bool noProcesses = false;
    unsigned long long cpu = 0, memory = 0, fileSize = 0, processes = 0;
    std::vector<std::string> writable, readable;
    int i = 1;
    for (; i < argc; ++i) {
        std::string arg = argv[i];
        auto value = [&]() -> char const* {
            if (i + 1 >= argc) fail("missing value after " + arg);
            return argv[++i];
        };
        if (arg == "--") {
            ++i;
            break;
        } else if (arg == "--no-processes") {
            noProcesses = true;
        } else if (arg == "--cpu") {
            cpu = number(value(), "--cpu");
        } else if (arg == "--memory") {
            memory = number(value(), "--memory");
        } else if (arg == "--file-size") {
            fileSize = number(value(), "--file-size");
        } else if (arg == "--processes") {
            processes = number(value(), "--processes");
        } else if (arg == "--writable") {
            writable.push_back(value());
        } else if (arg == "--readable") {
            readable.push_back(value());
        } else {
            fail("unknown option " + arg);
        }
    }
    if (i >= argc) fail("no program given after --");

    limit(RLIMIT_CORE, 0, "core files");
    limit(RLIMIT_NOFILE, 1024, "open files");
    if (cpu) limit(RLIMIT_CPU, cpu, "CPU time");
    if (memory) limit(RLIMIT_AS, memory, "address space");
    if (fileSize) limit(RLIMIT_FSIZE, fileSize, "file size");
    if (processes) limit(RLIMIT_NPROC, processes, "processes");
    if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) fail("cannot set no_new_privs");
    if (!writable.empty() || !readable.empty()) confineFiles(writable, readable);
    if (noProcesses) forbidProcesses();
    execvp(argv[i], argv + i);
    std::fprintf(stderr, "rixjail: cannot run %s: %s\n", argv[i], std::strerror(errno));
    return 127;
}
