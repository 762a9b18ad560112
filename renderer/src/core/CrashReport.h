// A plugin's code runs inside the program that loaded it, so a crash in it
// ends the program. Without a word, a student only sees "Segmentation fault";
// with this, the program first says which plugin the crash was in, and where.
#pragma once

#include <cstdint>
#include <string>

namespace bxdflab::crashreport {

/// Where a crash happened, for a program's own report of it.
struct Crash {
    static constexpr int kMaxOffsets = 4;
    char const* signal;  ///< "SIGSEGV", "SIGBUS", "SIGFPE", "SIGILL" or "SIGABRT"
    char const* plugin;  ///< the file of the innermost plugin on the stack, or null when there is none
    /// In that file, for addr2line: where it crashed (or called what crashed), then
    /// where the functions it was in were called from, as long as they are the plugin's.
    uintptr_t offsets[kMaxOffsets];
    int offsetCount;
    /// The crash was a jump to an address in no loaded file: a return address or
    /// function pointer written over (most often by a write past a stack array).
    bool jumpedOutOfCode;
    /// The crash touched memory right beside the stack pointer: the thread ran out
    /// of stack (a function calling itself without end, or a very large local array).
    bool ranOutOfStack;
};

/// What the circumstances of a crash say of its cause ("jumping to an address
/// that is no code: ...", "having run out of stack: ..."), or null when they
/// say nothing; for reporters.
char const* causeOf(Crash const& crash);

/// Writes the offsets of a crash ("0x1a2b 0x1c3d ..."), for reporters.
void sayOffsets(Crash const& crash, bool toStdout = false);

/// Writes a crash report line by line; it runs in a signal handler, so it may
/// only call say() and sayHex() (no allocation, no stdio).
using Reporter = void (*)(Crash const& crash);

/// Async-signal-safe output to stderr (or to stdout with `toStdout`), for reporters.
void say(char const* text, bool toStdout = false);
void sayHex(uintptr_t value, bool toStdout = false);

/// From now on a crash (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT) is
/// reported by `reporter` -- by default on stderr as "<program>: crashed
/// (SIGSEGV) in the plugin <file> at offset 0x...", or as a crash of the
/// program itself when no plugin's code is on the stack. The process then
/// dies of the signal as it would have (its exit status unchanged), or with
/// `exitStatus` >= 0 exits with that status instead. A handler already in
/// place (a sanitizer's) is left alone.
void install(char const* program, Reporter reporter = nullptr, int exitStatus = -1);

/// Gives the calling thread a stack of its own for the report (install() gives
/// one to the thread that calls it): a crash that leaves no room on the
/// thread's own stack, as a plugin writing past a stack array can, is reported
/// too. Call it on every thread that runs plugin code; after the first call on
/// a thread, or without install(), it does nothing.
void prepareThread();

/// Remembers a loaded plugin's file, by the name the dynamic loader gives it.
void notePlugin(std::string const& loadedName);

}  // namespace bxdflab::crashreport
