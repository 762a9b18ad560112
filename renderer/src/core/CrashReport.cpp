#include "core/CrashReport.h"

#include <dlfcn.h>
#include <execinfo.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <mutex>
#include <vector>

namespace bxdflab::crashreport {
namespace {

char const* g_program = "";
Reporter g_reporter = nullptr;
int g_exitStatus = -1;
std::mutex g_pluginsLock;
// Written while plugins load, read by the handler; reserved up front so that
// loading a plugin never moves what the handler may be reading.
std::vector<std::string> g_plugins;
constexpr size_t kMaxPlugins = 1024;

char const* signalName(int signal) {
    switch (signal) {
        case SIGSEGV: return "SIGSEGV";
        case SIGBUS: return "SIGBUS";
        case SIGFPE: return "SIGFPE";
        case SIGILL: return "SIGILL";
        default: return "SIGABRT";
    }
}

/// The plugin file that holds `address`, or null.
char const* pluginAt(void* address, Dl_info& where) {
    if (!dladdr(address, &where) || !where.dli_fname) return nullptr;
    for (std::string const& plugin : g_plugins)
        if (plugin == where.dli_fname) return plugin.c_str();
    return nullptr;
}

void reportOnStderr(Crash const& crash) {
    say(g_program);
    say(": crashed (");
    say(crash.signal);
    if (crash.plugin) {
        say(") in the plugin ");
        say(crash.plugin);
        say(" at ");
        sayOffsets(crash);
        say(".\n  Most often a pointer never set or an index past numPts. `addr2line -f -C -e <plugin> <offsets>` "
            "names the functions and lines of a plugin built with -g; a plugin built with AddressSanitizer stops "
            "at the first bad access (chapter 7).\n");
    } else {
        say("), and no plugin's code is on the stack: this is a bug in ");
        say(g_program);
        say(" itself; please report it with the scene and command that show it.\n");
    }
}

// Only async-signal-safe calls from here on, as in every reporter.
void onCrash(int signal) {
    void* frames[64];
    int const depth = backtrace(frames, 64);
    // The innermost frame in a plugin: a plugin that hands the C library a bad pointer
    // crashes there, and it is still the plugin's doing.
    Crash crash{signalName(signal), nullptr, {}, 0};
    Dl_info where{};
    for (int frame = 0; frame < depth && crash.offsetCount < Crash::kMaxOffsets; ++frame) {
        char const* plugin = pluginAt(frames[frame], where);
        if (crash.plugin && plugin != crash.plugin) break;  // out of the plugin again
        if (!plugin) continue;
        crash.plugin = plugin;
        // A return address points after its call: one byte back lies inside the call.
        crash.offsets[crash.offsetCount++] = reinterpret_cast<uintptr_t>(frames[frame]) -
                                             reinterpret_cast<uintptr_t>(where.dli_fbase) - (frame > 0 ? 1 : 0);
    }
    (g_reporter ? g_reporter : reportOnStderr)(crash);
    if (g_exitStatus >= 0) _exit(g_exitStatus);
    std::signal(signal, SIG_DFL);  // and die of it, as without this report
    std::raise(signal);
}

}  // namespace

void say(char const* text, bool toStdout) {
    ssize_t written = write(toStdout ? STDOUT_FILENO : STDERR_FILENO, text, std::strlen(text));
    (void)written;  // nothing more can be done in a crash
}

void sayHex(uintptr_t value, bool toStdout) {
    char digits[2 + 2 * sizeof value + 1];
    char* p = digits + sizeof digits - 1;
    *p = '\0';
    do {
        *--p = "0123456789abcdef"[value & 0xF];
        value >>= 4;
    } while (value);
    *--p = 'x';
    *--p = '0';
    say(p, toStdout);
}

void sayOffsets(Crash const& crash, bool toStdout) {
    say(crash.offsetCount > 1 ? "offsets " : "offset ", toStdout);
    for (int k = 0; k < crash.offsetCount; ++k) {
        if (k) say(" ", toStdout);
        sayHex(crash.offsets[k], toStdout);
    }
}

void install(char const* program, Reporter reporter, int exitStatus) {
    g_program = program;
    g_reporter = reporter;
    g_exitStatus = exitStatus;
    g_plugins.reserve(kMaxPlugins);
    void* warmUp[1];
    backtrace(warmUp, 1);  // loads what backtrace needs now, not inside the handler
    static char alternate[64 * 1024];  // so that a plugin that overflows its stack is reported too
    stack_t stack{};
    stack.ss_sp = alternate;
    stack.ss_size = sizeof alternate;
    sigaltstack(&stack, nullptr);
    for (int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) {
        struct sigaction current {};
        if (sigaction(signal, nullptr, &current) != 0 || current.sa_handler != SIG_DFL) continue;
        struct sigaction action {};
        action.sa_handler = onCrash;
        action.sa_flags = SA_ONSTACK;
        sigaction(signal, &action, nullptr);
    }
}

void notePlugin(std::string const& loadedName) {
    std::lock_guard<std::mutex> lock(g_pluginsLock);
    if (g_plugins.size() < kMaxPlugins) g_plugins.push_back(loadedName);
}

}  // namespace bxdflab::crashreport
