// rixcheck: the autograder's checks on your own plugin, on your own machine.
//
//   rixcheck --plugin diffuse --plugin-dir my-bxdflab/build/plugins [--check chi2]
//
// Runs the checks of the exercise's manifest (or one of them) on the plugin
// in --plugin-dir, against the course's reference solution, and prints each
// verdict with its numbers. `ctest` in your exercise build runs it once per
// check. Exit status 0 when every check passed (or does not apply), 1 when
// one failed, 2 for a command-line mistake, 77 (ctest's "skipped") when the
// one check asked for is one rixgrade runs by rendering (it says how to run
// it). The grader runs the same checks, with your plugin in a sandbox
// (rixgrade), plus the renders.
#include <cstring>
#include <filesystem>
#include <iostream>

#include "CommandLine.h"
#include "checks/Check.h"
#include "core/CrashReport.h"
#include "measure/ProbeMeasurer.h"

using namespace bxdflab;

namespace {
/// The exit status ctest reports as "skipped" (SKIP_RETURN_CODE in starter/CMakeLists.txt).
constexpr int kSkipped = 77;

// What rixcheck is doing, for the report of a plugin that crashes: the plugin runs
// inside rixcheck, so a crash in it ends rixcheck too. Copies, not pointers into
// the stack, which a crashing plugin may have written over.
char g_plugin[64] = "";
char g_check[64] = "(loading)";
char const* volatile g_call = "loading the plugin";
char const* g_crashHint = "";  // set before the handler is installed: it may not build strings

void noteCall(char const* call) { g_call = call; }

/// Reports the crash as the failure of the check that was running (on stdout,
/// with the verdicts); rixcheck then exits with status 1.
void reportFailedCheck(crashreport::Crash const& crash) {
    using crashreport::say;
    say("FAIL ", true);
    say(g_plugin, true);
    say(" ", true);
    say(g_check, true);
    say(": the plugin crashed (", true);
    say(crash.signal, true);
    say(") in ", true);
    say(g_call, true);
    if (char const* cause = crashreport::causeOf(crash)) {
        say(", ", true);
        say(cause, true);
    }
    if (crash.plugin) {
        say(", at ", true);
        crashreport::sayOffsets(crash, true);
        say(" of ", true);
        say(crash.plugin, true);
    }
    say("\n  hint: ", true);
    say(g_crashHint, true);
    say("\n", true);
}
}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"rixcheck: the autograder's checks on your own plugin"};
    std::string plugin, pluginDir, only;
    uint32_t seed = 0;
    app.add_option("--plugin", plugin, "the exercise's plugin name (e.g. diffuse)")->required();
    app.add_option("--plugin-dir", pluginDir, "the folder holding your plugin (e.g. my-bxdflab/build/plugins)")
        ->required()
        ->check(CLI::ExistingDirectory);
    app.add_option("--check", only, "run only this check (loads, values, chi2, jacobian, consistency, ...)");
    app.add_option("--seed", seed, "seed of the checker's own random draws");
    BXDFLAB_PARSE_COMMAND_LINE(app, argc, argv);

    try {
        std::vector<Exercise> exercises = loadExercises(BXDFLAB_SOURCE_DIR);
        Exercise const* exercise = findExercise(exercises, plugin);
        if (!exercise) throw std::runtime_error("no exercise has a plugin named \"" + plugin + "\"");
        std::error_code noPath;  // rixgrade sits beside rixcheck
        std::filesystem::path const rixgrade = std::filesystem::read_symlink("/proc/self/exe", noPath).parent_path() / "rixgrade";
        std::string const gradeCommand = rixgrade.string() + " --plugins " + pluginDir + " --chapter " +
                                         exercise->chapter + " --only " + plugin;
        if (Exercise::isRenderCheck(only)) {
            std::cout << "SKIP " << plugin << " " << only << ": rixgrade runs this check by rendering the chapter's "
                      << "scene with your plugin and the solution's; rixcheck does not render:\n  " << gradeCommand << "\n";
            return kSkipped;
        }
        if (exercise->kind == "integrator") {
            std::cout << plugin << " is an integrator: it is graded by rendering, which rixgrade does:\n  " << gradeCommand
                      << "\n";
            return 0;
        }
        std::strncpy(g_plugin, plugin.c_str(), sizeof g_plugin - 1);
        g_crashHint = crashHint().c_str();
        crashreport::install("rixcheck", reportFailedCheck, 1);
        std::cout << std::unitbuf;  // each verdict out at once: a crash ends the process without flushing
        Diagnostics diagnostics;
        ProbeMeasurer mine(plugin, {pluginDir}, diagnostics, noteCall);
        Diagnostics quiet(false);
        ProbeMeasurer reference(plugin, {BXDFLAB_SOLUTION_PLUGINS}, quiet);
        CheckContext context{*exercise, mine, reference, seed};
        bool allPassed = true;
        for (auto const& [check, points] : exercise->checks) {
            if (Exercise::isRenderCheck(check) || (!only.empty() && check != only)) continue;
            std::strncpy(g_check, check.c_str(), sizeof g_check - 1);
            CheckOutcome outcome;
            try {
                outcome = runCheck(check, context);
            } catch (MeasurementError const& e) {
                outcome = CheckOutcome::fail(e.kind() == MeasurementError::Kind::Overran
                                                 ? std::string(e.what())
                                                 : "while running " + e.call() + ": " + e.what());
            }
            char const* verdict = outcome.status == CheckOutcome::Status::Passed   ? "PASS"
                                  : outcome.status == CheckOutcome::Status::Failed ? "FAIL"
                                                                                   : "N/A ";
            std::cout << verdict << " " << plugin << " " << check << ": " << outcome.summary << "\n";
            if (!outcome.passed()) {
                if (!outcome.details.empty()) std::cout << outcome.details;
                std::cout << "  hint: " << checkHint(check) << "\n";
                allPassed = false;
            }
            (void)points;
        }
        return allPassed ? 0 : 1;
    } catch (std::exception const& e) {
        std::cerr << "rixcheck: " << e.what() << '\n';
        return 1;
    }
}
