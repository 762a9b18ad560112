#include "core/CrashReport.h"

#include <dlfcn.h>
#include <execinfo.h>
#include <sys/syscall.h>
#include <ucontext.h>
#include <unistd.h>

#include <atomic>
#include <csetjmp>
#include <csignal>
#include <cstring>
#include <memory>
#include <mutex>
#include <vector>

namespace bxdflab::crashreport {
namespace {

char const* g_program = "";
Reporter g_reporter = nullptr;
int g_exitStatus = -1;
std::atomic<bool> g_installed{false};
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
    say(")");
    if (crash.plugin) {
        say(" in the plugin ");
        say(crash.plugin);
        say(" at ");
        sayOffsets(crash);
    }
    char const* cause = causeOf(crash);
    if (cause && (crash.plugin || crash.jumpedOutOfCode)) {
        say(crash.plugin ? ", " : " ");
        say(cause);
        say(".");
    } else if (crash.plugin) {
        say(".\n  Most often a pointer never set or an index past numPts.");
    } else {
        say(", and no plugin's code is on the stack: this is a bug in ");
        say(g_program);
        say(" itself; please report it with the scene and command that show it.\n");
        return;
    }
    say(crash.plugin ? " `addr2line -f -C -e <plugin> <offsets>` names the functions and lines of a plugin built "
                       "with -g; a plugin"
                     : " A plugin");
    say(" built with AddressSanitizer stops at the first bad access (chapter 7).\n");
}

/// Two registers of the crashed thread, as the kernel saved them.
enum class Register { ProgramCounter, StackPointer };
uintptr_t registerAt(void* context, Register which) {
#if defined(__x86_64__)
    auto const& saved = static_cast<ucontext_t*>(context)->uc_mcontext.gregs;
    return static_cast<uintptr_t>(which == Register::ProgramCounter ? saved[REG_RIP] : saved[REG_RSP]);
#elif defined(__aarch64__)
    auto const& saved = static_cast<ucontext_t*>(context)->uc_mcontext;
    return static_cast<uintptr_t>(which == Register::ProgramCounter ? saved.pc : saved.sp);
#else
    (void)context;
    (void)which;
    return 0;
#endif
}

/// Whether the memory a SIGSEGV was about lies within reach of the stack
/// pointer: a page the stack would have grown into (its guard page).
bool besideStackPointer(siginfo_t const* info, void* context) {
    uintptr_t const address = reinterpret_cast<uintptr_t>(info->si_addr);
    uintptr_t const sp = registerAt(context, Register::StackPointer);
    uintptr_t const reach = 64 * 1024;  // a frame's worth either side
    return sp && address && address + reach > sp && address < sp + reach;
}

/// What a call to an address that is no code left on top of the stack: the
/// address it would have returned to, inside the code that called.
uintptr_t returnAddressOfCall(void* context) {
#if defined(__x86_64__)
    return *reinterpret_cast<uintptr_t const*>(registerAt(context, Register::StackPointer));
#elif defined(__aarch64__)
    return static_cast<uintptr_t>(static_cast<ucontext_t*>(context)->uc_mcontext.regs[30]);  // the link register
#else
    (void)context;
    return 0;
#endif
}

/// Adds `address` of `plugin` to the crash's offsets (the first names the plugin).
void addOffset(Crash& crash, char const* plugin, Dl_info const& where, uintptr_t address) {
    crash.plugin = plugin;
    crash.offsets[crash.offsetCount++] = address - reinterpret_cast<uintptr_t>(where.dli_fbase);
}

// Walking the stack reads it, and a plugin that wrote past a stack array has
// overwritten what the walk reads: it may crash again. The handler runs with
// the signal unblocked, so that second crash comes back here and jumps out of
// the walk, and the report is made from the faulting instruction alone. (A
// plugin that wrote on past the top of a thread's stack, into the thread's
// control block, leaves the kernel unable to run any handler on that thread:
// the process then dies of the signal without a report.)
sigjmp_buf g_walkFailed;
enum : int { kIdle, kStarting, kWalking, kReporting };
volatile sig_atomic_t g_stage = kIdle;

/// Dies of `signal`, as the program would have without a report.
void dieOf(int signal) {
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

// Only async-signal-safe calls from here on, as in every reporter.
void onCrash(int signal, siginfo_t* info, void* context) {
    // One report, by the first thread to crash; another that crashes meanwhile
    // waits for the process to end.
    static std::atomic<long> reportingThread{0};
    long const me = syscall(SYS_gettid);
    long expected = 0;
    if (!reportingThread.compare_exchange_strong(expected, me) && expected != me)
        for (;;) pause();
    if (g_stage == kWalking) siglongjmp(g_walkFailed, 1);
    if (g_stage != kIdle) dieOf(signal);  // making the report crashed
    g_stage = kStarting;
    Crash crash{signalName(signal), nullptr, {}, 0, false, false};
    crash.ranOutOfStack = signal == SIGSEGV && info && besideStackPointer(info, context);
    Dl_info where{};
    uintptr_t const faulted = registerAt(context, Register::ProgramCounter);  // the instruction that faulted
    crash.jumpedOutOfCode = faulted && signal == SIGSEGV && !dladdr(reinterpret_cast<void*>(faulted), &where);
    if (char const* plugin = faulted ? pluginAt(reinterpret_cast<void*>(faulted), where) : nullptr)
        addOffset(crash, plugin, where, faulted);
    // A call to no code stops the walk below at once; the call's return address
    // (read from a stack that may be gone) says who called. What is set between
    // a sigsetjmp and a jump back to it is static, so that it keeps its value.
    static uintptr_t caller = 0;
    if (sigsetjmp(g_walkFailed, 1) == 0) {
        g_stage = kWalking;
        if (crash.jumpedOutOfCode) caller = returnAddressOfCall(context);
    }
    if (char const* plugin = caller ? pluginAt(reinterpret_cast<void*>(caller), where) : nullptr)
        addOffset(crash, plugin, where, caller - 1);

    static void* frames[64];
    static int depth = 0;
    if (sigsetjmp(g_walkFailed, 1) == 0) depth = backtrace(frames, 64);
    g_stage = kReporting;
    // The frames of the walk that lie past the faulting instruction are its callers
    // (the ones before are this handler's); without it among them (a pointer called
    // that is no code, a walk that failed) they are all taken.
    int first = 0;
    for (int frame = 0; frame < depth; ++frame)
        if (reinterpret_cast<uintptr_t>(frames[frame]) == faulted) first = frame + 1;
    // The innermost frames in a plugin: a plugin that hands the C library a bad
    // pointer crashes there, and it is still the plugin's doing.
    for (int frame = first; frame < depth && crash.offsetCount < Crash::kMaxOffsets; ++frame) {
        char const* plugin = pluginAt(frames[frame], where);
        if (crash.plugin && plugin != crash.plugin) break;  // out of the plugin again
        if (!plugin) continue;
        // A return address points after its call: one byte back lies inside the call.
        addOffset(crash, plugin, where, reinterpret_cast<uintptr_t>(frames[frame]) - 1);
    }
    (g_reporter ? g_reporter : reportOnStderr)(crash);
    if (g_exitStatus >= 0) _exit(g_exitStatus);
    dieOf(signal);
}

}  // namespace

char const* causeOf(Crash const& crash) {
    if (crash.jumpedOutOfCode)
        return "jumping to an address that is no code: a return address or function pointer was written over, "
               "most often by a plugin writing past the end of an array on its stack (RixAlloca too small, an "
               "index past numPts)";
    if (crash.ranOutOfStack)
        return "having run out of stack: a function that calls itself without end, or a very large local array";
    return nullptr;
}

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
    g_installed = true;
    prepareThread();
    for (int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) {
        struct sigaction current {};
        if (sigaction(signal, nullptr, &current) != 0 || current.sa_handler != SIG_DFL) continue;
        struct sigaction action {};
        action.sa_sigaction = onCrash;
        action.sa_flags = SA_ONSTACK | SA_SIGINFO | SA_NODEFER;
        sigaction(signal, &action, nullptr);
    }
}

void prepareThread() {
    /// A thread's own stack for the handler, handed back to the kernel before it is freed.
    struct AlternateStack {
        std::unique_ptr<char[]> memory;
        ~AlternateStack() {
            if (!memory) return;
            stack_t off{};
            off.ss_flags = SS_DISABLE;
            sigaltstack(&off, nullptr);
        }
    };
    thread_local AlternateStack alternate;
    if (!g_installed || alternate.memory) return;
    size_t const size = 64 * 1024;
    alternate.memory = std::make_unique<char[]>(size);
    stack_t stack{};
    stack.ss_sp = alternate.memory.get();
    stack.ss_size = size;
    sigaltstack(&stack, nullptr);
}

void notePlugin(std::string const& loadedName) {
    std::lock_guard<std::mutex> lock(g_pluginsLock);
    if (g_plugins.size() < kMaxPlugins) g_plugins.push_back(loadedName);
}

}  // namespace bxdflab::crashreport
