#include "Gradebook.h"

#include <sstream>

namespace rixgrade {

std::string csvField(std::string const& text) {
    std::string value = text;
    if (!value.empty() && (value[0] == '=' || value[0] == '+' || value[0] == '-' || value[0] == '@' || value[0] == '\t' ||
                           value[0] == '\r'))
        value = "'" + value;
    if (value.find_first_of(",\"\r\n") == std::string::npos) return value;
    std::string quoted = "\"";
    for (char c : value) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::vector<GradebookColumn> gradebookColumns(Course const& course, GradeOptions const& options) {
    std::vector<GradebookColumn> columns;
    for (auto const& e : course.exercises()) {
        if (!selected(e, options)) continue;
        for (auto const& [check, points] : course.pointsFor(e, options.rubric))
            columns.push_back({"ch" + e.chapter + " " + e.plugin + " " + check, points});
    }
    return columns;
}

std::string gradebookCsv(std::vector<Grade> const& grades, std::vector<GradebookColumn> const& columns) {
    std::ostringstream csv;
    auto number = [](double v) {
        std::ostringstream s;
        s << v;
        return s.str();
    };
    double maximum = 0.0;
    csv << "student,score,max_score,built,warnings";
    for (auto const& c : columns) {
        csv << ',' << csvField(c.name);
        maximum += c.points;
    }
    csv << ",notes\r\n";
    for (Grade const& g : grades) {
        std::vector<double> scores;
        double total = 0.0;
        for (auto const& column : columns) {
            double score = 0.0;
            for (auto const& c : g.checks)
                if ("ch" + c.chapter + " " + c.plugin + " " + c.check == column.name) score = c.score;
            scores.push_back(score);
            total += score;
        }
        csv << csvField(g.name) << ',' << number(total) << ',' << number(maximum) << ',' << (g.built ? "yes" : "no")
            << ',' << g.buildWarnings;
        for (double score : scores) csv << ',' << number(score);
        csv << ',' << csvField(g.error) << "\r\n";
    }
    return csv.str();
}

}  // namespace rixgrade
