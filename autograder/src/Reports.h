// The grade, written for its readers: a terminal summary for the student,
// results.json in the Gradescope autograder schema, and an HTML report with
// the renders, the difference heatmaps and every check's numbers. Whatever
// student code printed is quoted capped and escaped.
#pragma once

#include <iosfwd>
#include <string>

#include "Grader.h"
#include "OutputFolder.h"

namespace rixgrade {

void printSummary(Grade const& grade, std::ostream& out);
std::string resultsJson(Grade const& grade);
std::string htmlReport(Grade const& grade);
/// results.json and report.html into `out`.
void writeReports(Grade const& grade, OutputFolder const& out);

/// Text safe inside HTML, cut to `cap` characters (valid UTF-8 kept, other bytes shown as '?').
std::string escapeHtml(std::string const& text, size_t cap = 100000);

}  // namespace rixgrade
