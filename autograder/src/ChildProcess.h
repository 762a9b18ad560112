// Runs untrusted work (a student's plugin, through rixcheck or rixrender) in
// a child process with a wall-clock timeout and resource limits, so a crash,
// a hang or a memory blow-up fails one check instead of the grader.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "Sandbox.h"

namespace rixgrade {

struct Limits {
    double seconds = 120.0;                ///< wall clock; the process group is killed after it
    unsigned long long memoryBytes = 4ull << 30;  ///< address space
    unsigned long long cpuSeconds = 300;
    size_t outputBytes = 1 << 20;          ///< kept of stdout and of stderr each
};

struct Outcome {
    int exitCode = -1;     ///< when it exited normally
    int signal = 0;        ///< when a signal ended it
    bool timedOut = false;
    std::string out, err;
    double seconds = 0.0;
    bool ok() const { return !timedOut && signal == 0 && exitCode == 0; }
    /// "exited with status 2", "crashed with SIGSEGV", "did not finish within 120 s",
    /// "was stopped: it tried to start a process".
    std::string describe(Limits const& limits) const;
};

/// Runs argv (searched in PATH) with `environment` added to this process's,
/// in `workingDirectory`, under `limits` and confined by `sandbox`.
Outcome run(std::vector<std::string> const& argv, std::map<std::string, std::string> const& environment,
            std::string const& workingDirectory, Limits const& limits, SandboxPolicy const& sandbox = {});

}  // namespace rixgrade
