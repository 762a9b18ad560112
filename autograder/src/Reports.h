// The grade, written for its readers: a terminal summary for the student,
// results.json in the Gradescope autograder schema, and an HTML report with
// the renders, the difference heatmaps and every check's numbers.
#pragma once

#include <iosfwd>
#include <string>

#include "Grader.h"

namespace rixgrade {

void printSummary(Grade const& grade, std::ostream& out);
void writeResultsJson(Grade const& grade, std::string const& path);
void writeHtmlReport(Grade const& grade, std::string const& folder);

}  // namespace rixgrade
