// rixgrade: the course's autograder.
//
// Student, on their own work:
//   rixgrade --submission DIR [--chapter N]... [--out grade]
// Instructor, on a class (one sub-folder per student):
//   rixgrade --class DIR --jobs N --out grades
// Every check that runs student code runs in a child process with a timeout
// and resource limits, may write only inside the output folder, and may not
// start processes (Sandbox.h). Points come from autograder/rubric.json (or --rubric).
// Nothing is written inside a submission.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <thread>

#include "CommandLine.h"
#include "Grader.h"
#include "Reports.h"
#include "Sandbox.h"

namespace fs = std::filesystem;
using namespace rixgrade;

namespace {

std::string binDirectory() {
    std::error_code error;
    fs::path exe = fs::read_symlink("/proc/self/exe", error);
    return error ? "build/bin" : exe.parent_path().string();
}

bool inside(fs::path const& child, fs::path const& parent) {
    auto c = fs::weakly_canonical(child), p = fs::weakly_canonical(parent);
    return std::mismatch(p.begin(), p.end(), c.begin(), c.end()).first == p.end();
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"rixgrade: grade Bxdf exercises (a student's own work, or a whole class)"};
    std::string submission, plugins, classDir, out, rubricPath = std::string(BXDFLAB_SOURCE_DIR) + "/autograder/rubric.json";
    std::vector<std::string> chapters;
    int jobs = 1;
    auto* one = app.add_option("--submission", submission, "your copy of starter/ (built with CMake)");
    auto* prebuilt = app.add_option("--plugins", plugins, "a folder of already built plugins (skips the build)");
    auto* many = app.add_option("--class", classDir, "a folder with one submission folder per student");
    one->excludes(many);
    prebuilt->excludes(many);
    app.add_option("--chapter", chapters, "grade only these chapters (6, 7, 8)");
    app.add_option("--out", out, "where reports and scratch files go (default: grade, or grades for --class)");
    app.add_option("--jobs", jobs, "students graded at once (--class)")->check(CLI::Range(1, 64));
    app.add_option("--rubric", rubricPath, "points per check per plugin (JSON)");
    BXDFLAB_PARSE_COMMAND_LINE(app, argc, argv);
    if (submission.empty() && plugins.empty() && classDir.empty()) {
        std::cerr << "rixgrade: give --submission DIR, --plugins DIR or --class DIR\n";
        return 2;
    }
    try {
        std::ifstream rubricFile(rubricPath);
        if (!rubricFile) throw std::runtime_error("cannot read the rubric " + rubricPath);
        GradeOptions base;
        base.rubric = nlohmann::json::parse(rubricFile);
        base.chapters = chapters;
        base.root = BXDFLAB_SOURCE_DIR;
        base.binDir = binDirectory();
        if (!Sandbox::writeConfinementAvailable())
            std::cerr << "rixgrade: warning: this kernel has no Landlock, so student code is not kept from writing "
                         "outside the grading folder (Linux 5.13 or later confines it)\n";

        if (classDir.empty()) {
            base.submission = submission.empty() ? "" : fs::absolute(submission).string();
            base.plugins = plugins.empty() ? "" : fs::absolute(plugins).string();
            base.out = fs::absolute(out.empty() ? "grade" : out).string();
            if (!base.submission.empty() && inside(base.out, base.submission))
                throw std::runtime_error("--out must not be inside the submission (nothing is written there)");
            Grade g = grade(base);
            printSummary(g, std::cout);
            writeResultsJson(g, base.out + "/results.json");
            writeHtmlReport(g, base.out);
            std::cout << "reports: " << base.out << "/report.html, " << base.out << "/results.json\n";
            return 0;
        }

        // A class: each student in their own folder of the output, several at once.
        std::string outDir = fs::absolute(out.empty() ? "grades" : out).string();
        std::vector<fs::path> students;
        for (auto const& entry : fs::directory_iterator(classDir))
            if (entry.is_directory()) students.push_back(entry.path());
        std::sort(students.begin(), students.end());
        std::vector<Grade> grades(students.size());
        std::mutex printing;
        size_t next = 0;
        std::vector<std::thread> workers;
        for (int j = 0; j < jobs; ++j)
            workers.emplace_back([&] {
                for (;;) {
                    size_t k;
                    {
                        std::lock_guard<std::mutex> guard(printing);
                        if (next >= students.size()) return;
                        k = next++;
                    }
                    GradeOptions options = base;
                    options.submission = fs::absolute(students[k]).string();
                    options.out = outDir + "/" + students[k].filename().string();
                    grades[k] = grade(options);
                    writeResultsJson(grades[k], options.out + "/results.json");
                    writeHtmlReport(grades[k], options.out);
                    std::lock_guard<std::mutex> guard(printing);
                    std::cout << students[k].filename().string() << ": " << grades[k].score() << " / "
                              << grades[k].maxScore() << '\n';
                }
            });
        for (auto& w : workers) w.join();
        std::ofstream csv(outDir + "/gradebook.csv");
        csv << "student,score,max_score,built,warnings";
        if (!grades.empty())
            for (auto const& c : grades[0].checks) csv << ",ch" << c.chapter << " " << c.plugin << " " << c.check;
        csv << '\n';
        for (size_t k = 0; k < students.size(); ++k) {
            csv << students[k].filename().string() << ',' << grades[k].score() << ',' << grades[k].maxScore() << ','
                << grades[k].built << ',' << grades[k].buildWarnings;
            for (auto const& c : grades[k].checks) csv << ',' << c.score;
            csv << '\n';
        }
        std::cout << "gradebook: " << outDir << "/gradebook.csv\n";
        return 0;
    } catch (std::exception const& e) {
        std::cerr << "rixgrade: " << e.what() << '\n';
        return 1;
    }
}
