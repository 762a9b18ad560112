// Copied work, for the instructor: every pair of submissions, and each
// submission against the reference solutions, compared with a real
// similarity tester (sim_c++ from Debian's similarity-tester), which finds
// runs of tokens that match up to layout, comments, names and literals.
// What every student got from the starter is taken out first: each file is
// compared by the lines its author wrote (the lines not in the starter's
// file of the same name), so shared skeletons do not look like copying.
#pragma once

#include <string>
#include <vector>

#include "exercise/Exercise.h"

namespace rixgrade {

struct SimilarMatch {
    std::string student, other;  ///< other: a student, or "reference solution"
    std::string file, otherFile;
    int percent = 0;             ///< of `file`'s own text found in `otherFile`
    std::string regions;         ///< the matching regions, side by side (for flagged pairs)
};

struct SimilarityReport {
    std::vector<SimilarMatch> matches;  ///< at or above the reporting threshold, highest first
    std::string note;                   ///< what could not be done, if anything
    int flagThreshold = 60;             ///< matches at or above this are flagged in the class report
};

struct Submission {
    std::string name, folder;
};

SimilarityReport compareSubmissions(std::vector<Submission> const& submissions, std::string const& courseRoot,
                                    std::vector<bxdflab::Exercise> const& exercises, int reportThreshold = 30);

/// similarity.csv's text.
std::string similarityCsv(SimilarityReport const& report);

}  // namespace rixgrade
