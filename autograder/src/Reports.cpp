#include "Reports.h"

#include <filesystem>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace rixgrade {

using bxdflab::CheckOutcome;

namespace {

char const* verdict(CheckResult const& c) {
    switch (c.status) {
        case CheckOutcome::Status::Passed: return "PASS";
        case CheckOutcome::Status::NotApplicable: return "N/A ";
        default: return "FAIL";
    }
}

/// What to look at when c failed: its own hint (a crash's), else its check's.
std::string const& hintOf(CheckResult const& c) { return c.hint.empty() ? bxdflab::checkHint(c.check) : c.hint; }

std::string points(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

/// Printable text: control characters other than newline and tab become '?'.
std::string printable(std::string const& text, size_t cap) {
    std::string out;
    for (unsigned char c : text.substr(0, cap)) out += (c < 32 && c != '\n' && c != '\t') || c == 127 ? '?' : static_cast<char>(c);
    if (text.size() > cap) out += "\n[... " + std::to_string(text.size() - cap) + " more bytes cut]";
    return out;
}

}  // namespace

std::string escapeHtml(std::string const& text, size_t cap) {
    std::string out;
    for (char c : printable(text, cap)) {
        switch (c) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '&': out += "&amp;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += c;
        }
    }
    return out;
}

void printSummary(Grade const& grade, std::ostream& out) {
    out << "rixgrade: " << printable(grade.name, 200) << "\n";
    if (!grade.error.empty()) out << "  grading stopped: " << printable(grade.error, 500) << "\n";
    if (!grade.buildLog.empty() && !grade.built) out << "  the submission did not build; the build log is in the report\n";
    if (grade.buildWarnings) out << "  " << grade.buildWarnings << " compiler warnings (not graded; read them)\n";
    std::string plugin;
    for (auto const& c : grade.checks) {
        if (c.plugin != plugin) {
            plugin = c.plugin;
            out << "  chapter " << c.chapter << ", " << c.plugin << ":\n";
        }
        out << "    " << verdict(c) << " " << std::left << std::setw(12) << c.check << std::right << std::setw(4)
            << points(c.score) << " / " << points(c.maxScore) << std::fixed << std::setprecision(1) << std::setw(6)
            << c.seconds << " s" << std::defaultfloat;
        if (c.status != CheckOutcome::Status::Passed) {
            std::string first = c.summary.substr(0, c.summary.find('\n'));
            out << "   " << printable(first, 600);
            if (!c.passed() && !hintOf(c).empty()) out << "\n          hint: " << hintOf(c);
        }
        out << "\n";
    }
    out << "  total " << points(grade.score()) << " / " << points(grade.maxScore()) << " (" << std::fixed
        << std::setprecision(1) << grade.seconds << " s)\n"
        << std::defaultfloat;
}

std::string resultsJson(Grade const& grade) {
    nlohmann::json tests = nlohmann::json::array();
    for (auto const& c : grade.checks) {
        std::string output = c.summary;
        if (!c.passed() && !hintOf(c).empty()) output += "\nHint: " + hintOf(c);
        tests.push_back({{"name", "ch" + c.chapter + " " + c.plugin + ": " + c.check},
                         {"score", c.score},
                         {"max_score", c.maxScore},
                         {"status", c.passed() ? "passed" : "failed"},
                         {"output", printable(output, 4000)},
                         {"visibility", "visible"}});
    }
    std::string summary = grade.error.empty() ? (grade.built ? "built with " + std::to_string(grade.buildWarnings) + " warnings"
                                                             : "the submission did not build")
                                              : "grading stopped: " + grade.error;
    nlohmann::json results = {{"score", grade.score()},
                              {"max_score", grade.maxScore()},
                              {"execution_time", grade.seconds},
                              {"output", printable(summary + "\n" + grade.confinement, 4000)},
                              {"tests", tests}};
    // Invalid UTF-8 from student output is replaced, never an exception.
    return results.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::string htmlReport(Grade const& grade) {
    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>rixgrade report</title>\n<style>"
            "body{font-family:sans-serif;margin:2em;max-width:1150px}table{border-collapse:collapse;width:100%}"
            "td,th{border:1px solid #ccc;padding:4px 8px;text-align:left;vertical-align:top}"
            ".pass{color:#176b1e}.fail{color:#b00020}.na{color:#555}img{max-width:260px;border:1px solid #ddd}"
            "pre{background:#f6f6f6;padding:8px;overflow:auto;max-height:300px;white-space:pre-wrap}"
            ".note{background:#fff4d6;padding:6px}</style></head><body>\n";
    html << "<h1>rixgrade: " << escapeHtml(grade.name, 200) << "</h1>\n<p><b>" << points(grade.score()) << " / "
         << points(grade.maxScore()) << "</b> points, graded in " << std::fixed << std::setprecision(1) << grade.seconds
         << " s. " << grade.buildWarnings << " compiler warnings.</p>\n"
         << std::defaultfloat;
    html << "<p class=\"note\">" << escapeHtml(grade.confinement) << "</p>\n";
    if (!grade.error.empty()) html << "<p class=\"fail\">Grading stopped: " << escapeHtml(grade.error, 2000) << "</p>\n";
    html << "<table><tr><th>chapter</th><th>plugin</th><th>check</th><th>points</th><th>result</th></tr>\n";
    for (auto const& c : grade.checks) {
        char const* cls = c.status == CheckOutcome::Status::Passed ? "pass" : c.status == CheckOutcome::Status::Failed ? "fail" : "na";
        html << "<tr><td>" << escapeHtml(c.chapter) << "</td><td>" << escapeHtml(c.plugin) << "</td><td>"
             << escapeHtml(c.check) << "</td><td>" << points(c.score) << " / " << points(c.maxScore) << "</td><td class=\""
             << cls << "\">" << escapeHtml(c.summary, 3000);
        if (!c.details.empty()) html << "<details><summary>numbers</summary><pre>" << escapeHtml(c.details, 8000) << "</pre></details>";
        if (!c.passed()) html << "<br><i>" << escapeHtml(hintOf(c)) << "</i>";
        html << "</td></tr>\n";
    }
    html << "</table>\n";
    for (auto const& c : grade.checks) {
        if (!c.hasImages) continue;
        std::string dir = "renders/" + c.plugin + "/";
        html << "<h2>" << escapeHtml(c.plugin) << "</h2><p>" << escapeHtml(c.summary) << "</p><table><tr><th>yours</th>"
             << "<th>solution</th><th>|difference|</th><th>failing pixels (red: yours brighter, blue: darker)</th></tr><tr>";
        for (char const* image : {"student.png", "solution.png", "difference.png", "failing-pixels.png"})
            html << "<td><img src=\"" << escapeHtml(dir + image) << "\" alt=\"" << image << "\"></td>";
        html << "</tr></table>\n";
    }
    for (auto const& [plugin, printed] : grade.pluginOutput)
        if (!printed.empty())
            html << "<h2>What " << escapeHtml(plugin) << " printed</h2><pre>" << escapeHtml(printed, 4000) << "</pre>\n";
    if (!grade.buildLog.empty()) html << "<h2>Build log</h2><pre>" << escapeHtml(grade.buildLog, 20000) << "</pre>\n";
    html << "</body></html>\n";
    return html.str();
}

void writeReports(Grade const& grade, OutputFolder const& out) {
    out.write("results.json", resultsJson(grade));
    out.write("report.html", htmlReport(grade));
}

}  // namespace rixgrade
