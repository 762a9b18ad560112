// rixgrade: the course's autograder.
//
// Student, on their own work:
//   rixgrade --submission DIR [--chapter N]... [--out grade]
// Instructor, on a class (one sub-folder per student):
//   rixgrade --class DIR --jobs N --out grades
//
// Student code (the build, every check, every render) runs in a sandbox
// (Sandbox.h) and only sends raw measurements back; every verdict is computed
// here, in a process that never loads student code. Reports go to --out,
// which no sandbox sees. Points and time limits: autograder/rubric.json
// (--rubric); each exercise's checks and default points: its exercise.json.
#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "ClassMode.h"
#include "CommandLine.h"
#include "Grader.h"
#include "OutputFolder.h"
#include "Reports.h"
#include "Sandbox.h"
#include "Scratch.h"
#include "measure/Wire.h"

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

/// Without the sandbox, student code runs as nobody from the real folders (as root): say
/// up front which folder it cannot reach instead of failing every check with status 126.
void refuseWhatNobodyCannotReach(SandboxLayout const& layout) {
    std::vector<std::pair<std::string, int>> needed = {{layout.scratch, X_OK}, {layout.jail, X_OK}};
    for (auto const& mount : layout.courseMounts) needed.emplace_back(mount.first, R_OK);
    std::string blocked = unusableByNobody(needed);
    if (blocked.empty()) return;
    throw std::runtime_error("--unsafe-no-sandbox runs student code as the user nobody, who cannot use " + blocked +
                             " (it, or a folder above it, is closed to other users). Grade with the sandbox, or move the "
                             "course or TMPDIR where every user may enter.");
}

}  // namespace

int main(int argc, char** argv) {
    bxdflab::wire::keepBatchBuffersOnHeap();
    CLI::App app{"rixgrade: grade Bxdf exercises (a student's own work, or a whole class)"};
    std::string submission, plugins, classDir, out, rubricPath = std::string(BXDFLAB_SOURCE_DIR) + "/autograder/rubric.json";
    std::vector<std::string> chapters;
    int jobs = 1;
    uint32_t seed = 0;
    bool unsafe = false, keepScratch = false;
    auto* one = app.add_option("--submission", submission, "your copy of starter/ (built with CMake)");
    auto* prebuilt = app.add_option("--plugins", plugins, "a folder of already built plugins (no build)");
    auto* many = app.add_option("--class", classDir, "a folder with one submission folder per student");
    one->excludes(many);
    prebuilt->excludes(many);
    one->excludes(prebuilt);
    app.add_option("--chapter", chapters, "grade only these chapters (e.g. 6 9: those with exercise manifests in starter/)");
    std::vector<std::string> only;
    app.add_option("--only", only, "grade only these plugins (e.g. diffuse)");
    app.add_option("--out", out, "where the reports go (default: grade, or grades for --class)");
    app.add_option("--jobs", jobs, "students graded at once (--class)")->check(CLI::Range(1, 64));
    app.add_option("--rubric", rubricPath, "points and time limits (JSON)");
    app.add_option("--seed", seed, "seed of the grader's own random draws (the same seed gives the same grade)");
    app.add_flag("--unsafe-no-sandbox", unsafe,
                 "grade even where namespaces cannot be created: student code is then confined by Landlock, seccomp "
                 "and limits only, and every report says so");
    app.add_flag("--keep-scratch", keepScratch, "keep the scratch folders (for debugging the grader)");
    BXDFLAB_PARSE_COMMAND_LINE(app, argc, argv);
    if (submission.empty() && plugins.empty() && classDir.empty()) {
        std::cerr << "rixgrade: give --submission DIR, --plugins DIR or --class DIR\n";
        return 2;
    }
    signal(SIGPIPE, SIG_IGN);  // a child that dies mid-answer is reported, not fatal
    try {
        std::ifstream rubricFile(rubricPath);
        if (!rubricFile) throw std::runtime_error("cannot read the rubric " + rubricPath);
        GradeOptions base;
        base.rubric = nlohmann::json::parse(rubricFile);
        base.chapters = chapters;
        base.only = only;
        base.seed = seed;
        base.keepScratch = keepScratch;

        Confinement confinement = unsafe ? Confinement::JailOnly : Confinement::Sandbox;
        Course course(BXDFLAB_SOURCE_DIR, binDirectory(), confinement);
        SandboxLayout const grading = course.layout(Scratch::parentFolder(base.scratchParent));
        std::string why;
        if (unsafe) {
            std::cerr << "rixgrade: WARNING: --unsafe-no-sandbox: student code runs without namespaces\n";
            refuseWhatNobodyCannotReach(grading);
        } else if (!sandboxAvailable(grading, why)) {
            throw std::runtime_error(why + "\n  Student code is not run without its sandbox. Where namespaces cannot be "
                                           "created (some containers), --unsafe-no-sandbox grades anyway, with weaker "
                                           "confinement, and every report says so.");
        }

        if (classDir.empty()) {
            base.submission = submission.empty() ? "" : fs::absolute(submission).string();
            base.plugins = plugins.empty() ? "" : fs::absolute(plugins).string();
            base.name = fs::path(submission.empty() ? plugins : submission).lexically_normal().filename().string();
            if (base.name.empty() || base.name == ".") base.name = fs::absolute(submission.empty() ? plugins : submission).lexically_normal().parent_path().filename().string();
            std::string outDir = fs::absolute(out.empty() ? "grade" : out).string();
            std::string given = base.submission.empty() ? base.plugins : base.submission;
            if (!fs::is_directory(given)) throw std::runtime_error("\"" + given + "\" is not a folder");
            if (inside(outDir, given)) throw std::runtime_error("--out must not be inside the submission (nothing is written there)");
            OutputFolder folder(outDir);
            Grade g = grade(base, course, folder);
            printSummary(g, std::cout);
            writeReports(g, folder);
            std::cout << "reports: " << outDir << "/report.html, " << outDir << "/results.json\n";
            return 0;
        }
        ClassOptions options;
        options.classFolder = classDir;
        options.out = fs::absolute(out.empty() ? "grades" : out).string();
        options.jobs = jobs;
        if (inside(options.out, classDir)) throw std::runtime_error("--out must not be inside the class folder");
        int count = gradeClass(options, base, course, std::cout);
        std::cout << count << " submissions graded; gradebook: " << options.out << "/gradebook.csv, class report: "
                  << options.out << "/report.html\n";
        return 0;
    } catch (std::exception const& e) {
        std::cerr << "rixgrade: " << e.what() << '\n';
        return 1;
    }
}
