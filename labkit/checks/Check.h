// The property checks of a Bxdf exercise: what the autograder grades and a
// student's `ctest` self-check runs. Each check asks a plugin for
// measurements through a BxdfMeasurer (in this process, or from a sandboxed
// one), computes its statistic here, and states its verdict in words and
// numbers. A measurement that cannot be made (crash, hang) is thrown as a
// MeasurementError for the caller to report.
#pragma once

#include <string>
#include <vector>

#include "exercise/Exercise.h"
#include "measure/BxdfMeasurer.h"

namespace bxdflab {

struct CheckOutcome {
    enum class Status { Passed, Failed, NotApplicable };
    Status status = Status::Failed;
    std::string summary;  ///< one sentence: what was measured, what was expected (numbers and words)
    std::string details;  ///< further lines: every number the verdict rests on

    bool passed() const { return status != Status::Failed; }
    static CheckOutcome pass(std::string summary, std::string details = {}) {
        return {Status::Passed, std::move(summary), std::move(details)};
    }
    static CheckOutcome fail(std::string summary, std::string details = {}) {
        return {Status::Failed, std::move(summary), std::move(details)};
    }
    static CheckOutcome notApplicable(std::string because, std::string details = {}) {
        return {Status::NotApplicable, std::move(because), std::move(details)};
    }
};

struct CheckContext {
    Exercise const& exercise;
    BxdfMeasurer& plugin;     ///< the plugin under test
    BxdfMeasurer& reference;  ///< the reference solution (the oracle); may be the plugin itself
    uint32_t seed = 0;        ///< the grader's own random draws (directions, sample sequences)
    /// Family-wise significance of one statistical check (Sidak over its tests):
    /// a correct plugin fails it with at most this probability.
    double alpha = 1e-4;
    /// Samples per chi-squared test.
    int chiSquaredSamples = 1000000;
};

/// The checks rixgrade knows (besides "renders", which it runs itself).
std::vector<std::string> const& checkNames();
/// What to look at when `check` fails.
std::string const& checkHint(std::string const& check);
/// What to look at when the plugin crashed during a check (in place of the check's hint).
std::string const& crashHint();

/// Runs one check. Throws MeasurementError when the plugin crashes or hangs,
/// std::invalid_argument for an unknown check name.
CheckOutcome runCheck(std::string const& check, CheckContext& context);

// The checks themselves (one file each).
CheckOutcome checkLoads(CheckContext& context);
CheckOutcome checkValues(CheckContext& context);
CheckOutcome checkChiSquared(CheckContext& context);
CheckOutcome checkJacobian(CheckContext& context);
CheckOutcome checkConsistency(CheckContext& context);
CheckOutcome checkReciprocity(CheckContext& context);
CheckOutcome checkEnergy(CheckContext& context);
CheckOutcome checkHardCases(CheckContext& context);
CheckOutcome checkSmooth(CheckContext& context);
/// The ch08 sampling exercise (kind "sampling"): the same check names.
CheckOutcome checkSamplingFunctions(std::string const& check, CheckContext& context);

}  // namespace bxdflab
