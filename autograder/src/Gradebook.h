// The class gradebook as CSV (RFC 4180): every student one row, whatever
// happened to their grading, in a file written whole or not at all.
#pragma once

#include <string>
#include <vector>

#include "Grader.h"

namespace rixgrade {

/// One CSV field: quoted when it holds a comma, quote or line break, and
/// neutralised (a leading ') when a spreadsheet would read it as a formula.
std::string csvField(std::string const& text);

struct GradebookColumn {
    std::string name;  ///< "chN plugin check"
    double points = 0.0;
};

/// The columns for the exercises and points in use (the same for every row).
std::vector<GradebookColumn> gradebookColumns(Course const& course, GradeOptions const& options);

/// The gradebook's text: a header, then one row per grade, in the given
/// order. A student whose grading failed gets 0 in every column, the full
/// maximum, and the reason in "notes".
std::string gradebookCsv(std::vector<Grade> const& grades, std::vector<GradebookColumn> const& columns);

}  // namespace rixgrade
