// Grading a class: one folder per student, several at once. Each student's
// grading runs inside its own error boundary, so whatever one submission
// does -- crash, hang, odd layout, odd name -- costs only that student a
// row with 0 points and the reason; the gradebook always lists everyone and
// is written whole (a temporary file renamed into place). The instructor
// also gets the similarity report.
#pragma once

#include <string>

#include "Grader.h"

namespace rixgrade {

struct ClassOptions {
    std::string classFolder;
    std::string out;
    int jobs = 1;
    int similarityThreshold = 30;  ///< matches reported in similarity.csv (the class report flags 60% and up)
};

/// Grades the class; returns the number of students graded.
int gradeClass(ClassOptions const& options, GradeOptions const& base, Course& course, std::ostream& progress);

}  // namespace rixgrade
