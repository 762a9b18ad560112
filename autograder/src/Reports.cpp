#include "Reports.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>

namespace fs = std::filesystem;

namespace rixgrade {
namespace {

std::string escapeHtml(std::string const& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '&': out += "&amp;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

/// What to look at when a check fails.
const char* hint(std::string const& check) {
    if (check == "loads") return "Does the plugin build, export its create/destroy pair and return a parameter table?";
    if (check == "values") return "Compare your W = f cos(theta_L) and pdfs with the formulas in the chapter; rixlobe plots them.";
    if (check == "chi2") return "Your sampling does not match your FPdf: look at rixwarp's picture for this plugin.";
    if (check == "jacobian") return "At a fixed random number your FPdf is not the density your mapping produces: recheck its derivation.";
    if (check == "consistency") return "GenerateSample and EvaluateSample disagree: render ch07/validate.rib with your plugin.";
    if (check == "reciprocity") return "f(V, L) should equal f(L, V), and RPdf should be the pdf of the reverse direction.";
    if (check == "energy") return "The surface reflects more (or less) than the solution: check the normalisation constants.";
    if (check == "hardcases") return "Guard grazing angles, zero tangents and xi = 0 against NaN, infinity and negative pdfs.";
    if (check == "renders") return "Diff your render with the solution's (rixdiff); the heatmap shows where they disagree.";
    return "";
}

}  // namespace

void printSummary(Grade const& grade, std::ostream& out) {
    out << "rixgrade: " << grade.submission << "\n";
    if (!grade.built) out << "  the submission did not build; the build log is in the report\n";
    if (grade.buildWarnings) out << "  " << grade.buildWarnings << " compiler warnings (not graded; read them)\n";
    std::string plugin;
    for (auto const& c : grade.checks) {
        if (c.plugin != plugin) {
            plugin = c.plugin;
            out << "  chapter " << c.chapter << ", " << c.plugin << ":\n";
        }
        out << "    " << (c.passed ? "PASS " : "FAIL ") << std::left << std::setw(12) << c.check << std::right
            << std::setw(4) << c.score << " / " << c.maxScore;
        if (!c.passed) out << "   " << c.output.substr(0, c.output.find('\n')) << "\n          hint: " << hint(c.check);
        out << "\n";
    }
    out << "  total " << grade.score() << " / " << grade.maxScore() << " (" << std::fixed << std::setprecision(1)
        << grade.seconds << " s)\n";
}

void writeResultsJson(Grade const& grade, std::string const& path) {
    nlohmann::json tests = nlohmann::json::array();
    for (auto const& c : grade.checks)
        tests.push_back({{"name", "ch" + c.chapter + " " + c.plugin + ": " + c.check},
                         {"score", c.score},
                         {"max_score", c.maxScore},
                         {"status", c.passed ? "passed" : "failed"},
                         {"output", c.passed ? std::string("passed") : c.output + "\nHint: " + hint(c.check)},
                         {"visibility", "visible"}});
    nlohmann::json results = {{"score", grade.score()},
                              {"max_score", grade.maxScore()},
                              {"execution_time", grade.seconds},
                              {"output", grade.built ? "built with " + std::to_string(grade.buildWarnings) + " warnings"
                                                     : "the submission did not build"},
                              {"tests", tests}};
    std::ofstream(path) << results.dump(2) << '\n';
}

void writeHtmlReport(Grade const& grade, std::string const& folder) {
    std::ofstream html(folder + "/report.html");
    html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>rixgrade report</title>\n<style>"
            "body{font-family:sans-serif;margin:2em;max-width:1100px}table{border-collapse:collapse;width:100%}"
            "td,th{border:1px solid #ccc;padding:4px 8px;text-align:left;vertical-align:top}"
            ".pass{color:#176b1e}.fail{color:#b00020}img{max-width:330px;border:1px solid #ddd}"
            "pre{background:#f6f6f6;padding:8px;overflow:auto;max-height:300px;white-space:pre-wrap}"
            "</style></head><body>\n";
    html << "<h1>rixgrade: " << escapeHtml(grade.submission) << "</h1>\n<p><b>" << grade.score() << " / "
         << grade.maxScore() << "</b> points, graded in " << std::fixed << std::setprecision(1) << grade.seconds
         << " s. " << grade.buildWarnings << " compiler warnings.</p>\n";
    html << "<table><tr><th>chapter</th><th>plugin</th><th>check</th><th>points</th><th>result</th></tr>\n";
    for (auto const& c : grade.checks)
        html << "<tr><td>" << c.chapter << "</td><td>" << escapeHtml(c.plugin) << "</td><td>" << c.check << "</td><td>"
             << c.score << " / " << c.maxScore << "</td><td class=\"" << (c.passed ? "pass" : "fail") << "\">"
             << (c.passed ? "passed" : "<pre>" + escapeHtml(c.output) + "</pre><i>" + escapeHtml(hint(c.check)) + "</i>")
             << "</td></tr>\n";
    html << "</table>\n";
    for (auto const& c : grade.checks) {
        if (c.check != "renders") continue;
        std::string dir = "renders/" + c.plugin + "/";
        if (!fs::exists(folder + "/" + dir + "student.png")) continue;
        html << "<h2>" << escapeHtml(c.plugin) << "</h2><p>" << escapeHtml(c.output) << "</p><table><tr><th>yours</th>"
             << "<th>solution</th><th>difference</th><th>failing pixels (red)</th></tr><tr>";
        for (const char* image : {"student.png", "solution.png", "difference.png", "failing-pixels.png"})
            html << "<td><img src=\"" << dir << image << "\" alt=\"" << image << "\"></td>";
        html << "</tr></table>\n";
    }
    if (!grade.buildLog.empty()) html << "<h2>Build log</h2><pre>" << escapeHtml(grade.buildLog.substr(0, 20000)) << "</pre>\n";
    html << "</body></html>\n";
}

}  // namespace rixgrade
