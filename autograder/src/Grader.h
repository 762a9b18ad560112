// Grades one submission: builds it in a scratch folder, runs every check of
// the rubric in its own child process, and scores the results.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rixgrade {

struct CheckResult {
    std::string chapter, plugin, check;
    double score = 0.0, maxScore = 0.0;
    bool passed = false;
    std::string output;  ///< what failed and what to look at
    double seconds = 0.0;
};

struct Grade {
    std::string submission;
    std::vector<CheckResult> checks;
    std::string buildLog;
    int buildWarnings = 0;
    bool built = false;
    double seconds = 0.0;
    double score() const;
    double maxScore() const;
};

struct GradeOptions {
    std::string submission;     ///< the student's copy of starter/ (built with CMake)
    std::string plugins;        ///< or: a folder of already built plugins (skips the build)
    std::vector<std::string> chapters;  ///< empty: all in the rubric
    std::string out;            ///< scratch and reports; never inside the submission
    std::string root;           ///< the BxdfLab checkout
    std::string binDir;         ///< where rixcheck and rixrender are
    nlohmann::json rubric;
};

Grade grade(GradeOptions const& options);

}  // namespace rixgrade
