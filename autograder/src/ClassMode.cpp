#include "ClassMode.h"

#include <sys/stat.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <filesystem>
#include <mutex>
#include <ostream>
#include <set>
#include <sstream>

#include "Gradebook.h"
#include "OutputFolder.h"
#include "Reports.h"
#include "Similarity.h"

namespace fs = std::filesystem;

namespace rixgrade {
namespace {

struct Student {
    std::string name;    ///< the folder's name, as it is
    std::string folder;  ///< its path
    std::string outName; ///< a safe, unique folder name for its reports
};

std::string classReport(std::vector<Grade> const& grades, std::vector<Student> const& students,
                        SimilarityReport const& similarity, std::vector<std::string> const& notSubmissions) {
    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>rixgrade: class report</title><style>"
            "body{font-family:sans-serif;margin:2em;max-width:1150px}table{border-collapse:collapse}"
            "td,th{border:1px solid #ccc;padding:4px 8px;text-align:left;vertical-align:top}"
            "pre{background:#f6f6f6;padding:8px;overflow:auto;max-height:400px;font-size:11px}</style></head><body>\n"
            "<h1>Class report</h1>\n<p>"
         << grades.size() << " submissions graded. The gradebook is gradebook.csv; each student's report is in students/.</p>\n";
    if (!notSubmissions.empty()) {
        html << "<p>Not submissions (left out): ";
        for (auto const& n : notSubmissions) html << escapeHtml(n, 200) << "; ";
        html << "</p>\n";
    }
    html << "<table><tr><th>student</th><th>score</th><th>report</th><th>notes</th></tr>\n";
    for (size_t k = 0; k < grades.size(); ++k) {
        // Compiled code or a blob of data in a source submission: a plugin built elsewhere?
        std::string notes = grades[k].error;
        for (auto const& file : grades[k].lookAt) notes += (notes.empty() ? "look at: " : "; look at: ") + file;
        html << "<tr><td>" << escapeHtml(students[k].name, 200) << "</td><td>" << grades[k].score() << " / "
             << grades[k].maxScore() << "</td><td><a href=\"students/" << escapeHtml(students[k].outName)
             << "/report.html\">report</a></td><td>" << escapeHtml(notes, 1000) << "</td></tr>\n";
    }
    html << "</table>\n<h2>Similarity</h2>\n";
    if (!similarity.note.empty()) html << "<p>" << escapeHtml(similarity.note) << "</p>\n";
    html << "<p>Each file is compared by the lines its author wrote (the starter's lines taken out), with sim_c++. "
            "Pairs at or above "
         << similarity.flagThreshold << "% are shown with their matching regions; similarity.csv lists all above "
         << "the reporting threshold. A high share is a reason to look, not a verdict.</p>\n";
    int flagged = 0;
    for (auto const& m : similarity.matches) {
        if (m.percent < similarity.flagThreshold) break;
        ++flagged;
        html << "<h3>" << escapeHtml(m.student, 200) << " &mdash; " << escapeHtml(m.other, 200) << ": " << m.percent
             << "% of " << escapeHtml(m.file) << " is in " << escapeHtml(m.otherFile) << "</h3><pre>"
             << escapeHtml(m.regions, 12000) << "</pre>\n";
    }
    if (!flagged) html << "<p>No pair reaches " << similarity.flagThreshold << "%.</p>\n";
    html << "</body></html>\n";
    return html.str();
}

}  // namespace

int gradeClass(ClassOptions const& options, GradeOptions const& base, Course& course, std::ostream& progress) {
    OutputFolder out(options.out);
    std::vector<Student> students;
    std::vector<std::string> notSubmissions;
    std::set<std::string> usedNames;
    std::error_code error;
    for (auto const& entry : fs::directory_iterator(options.classFolder, error)) {
        struct stat st;
        std::string name = entry.path().filename().string();
        if (lstat(entry.path().c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
            notSubmissions.push_back(name + " (not a folder)");
            continue;
        }
        students.push_back({name, entry.path().string(), ""});
    }
    if (error) throw std::runtime_error("cannot read the class folder \"" + options.classFolder + "\": " + error.message());
    std::sort(students.begin(), students.end(), [](Student const& a, Student const& b) { return a.name < b.name; });
    for (auto& s : students) {
        std::string name = safeName(s.name);
        for (int k = 2; usedNames.count(name); ++k) name = safeName(s.name) + "-" + std::to_string(k);
        usedNames.insert(name);
        s.outName = name;
    }

    std::vector<Grade> grades(students.size());
    std::mutex printing;
    tbb::task_arena arena(options.jobs);
    arena.execute([&] {
        tbb::parallel_for(size_t(0), students.size(), size_t(1), [&](size_t k) {
            Student const& s = students[k];
            Grade& g = grades[k];
            // The error boundary: nothing that happens to one student stops the class.
            try {
                OutputFolder mine = out.sub("students").sub(s.outName);
                GradeOptions o = base;
                o.submission = s.folder;
                o.name = s.name;
                g = grade(o, course, mine);
                writeReports(g, mine);
            } catch (std::exception const& e) {
                g = Grade{};
                g.name = s.name;
                g.error = e.what();
            } catch (...) {
                g = Grade{};
                g.name = s.name;
                g.error = "unknown failure";
            }
            if (!g.error.empty()) {
                try {
                    writeReports(g, out.sub("students").sub(s.outName));
                } catch (...) {
                }
            }
            std::lock_guard<std::mutex> guard(printing);
            progress << s.outName << ": " << g.score() << " / " << g.maxScore() << (g.error.empty() ? "" : " (" + g.error + ")")
                     << std::endl;
        });
    });

    out.write("gradebook.csv", gradebookCsv(grades, gradebookColumns(course, base)));
    std::vector<Submission> submissions;
    for (auto const& s : students) submissions.push_back({s.name, s.folder});
    SimilarityReport similarity = compareSubmissions(submissions, course.root(), course.exercises(), options.similarityThreshold);
    out.write("similarity.csv", similarityCsv(similarity));
    out.write("report.html", classReport(grades, students, similarity, notSubmissions));
    return static_cast<int>(students.size());
}

}  // namespace rixgrade
