#include "Similarity.h"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "Gradebook.h"
#include "Sandbox.h"
#include "Scratch.h"

namespace fs = std::filesystem;

namespace rixgrade {
namespace {

bool isSource(fs::path const& p) {
    std::string e = p.extension().string();
    return e == ".cpp" || e == ".cc" || e == ".cxx" || e == ".h" || e == ".hpp";
}

std::string trim(std::string const& s) {
    size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

std::vector<std::string> readLines(std::string const& path, size_t maxBytes = 1 << 20) {
    struct stat st;
    std::vector<std::string> lines;
    if (lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode) || static_cast<size_t>(st.st_size) > maxBytes) return lines;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

/// The source files of a folder (no links followed, build folders left out), relative paths.
std::vector<std::string> sourcesIn(std::string const& folder) {
    std::vector<std::string> out;
    std::error_code error;
    fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, error), end;
    for (; !error && it != end; it.increment(error)) {
        struct stat st;
        if (lstat(it->path().c_str(), &st) != 0) continue;
        if (S_ISDIR(st.st_mode)) {
            std::string leaf = it->path().filename().string();
            if (leaf.rfind("build", 0) == 0 || leaf.rfind("grade", 0) == 0 || leaf[0] == '.') it.disable_recursion_pending();
            continue;
        }
        if (S_ISREG(st.st_mode) && isSource(it->path())) out.push_back(fs::relative(it->path(), folder).string());
        if (out.size() > 400) break;
    }
    std::sort(out.begin(), out.end());
    return out;
}

/// `lines` without those of `skeleton` (the starter's file); empty when nothing is left.
std::string ownLines(std::vector<std::string> const& lines, std::set<std::string> const& skeleton) {
    std::string out;
    int kept = 0;
    for (auto const& line : lines) {
        std::string t = trim(line);
        if (t.empty() || t == "{" || t == "}" || skeleton.count(t)) continue;
        out += line + "\n";
        ++kept;
    }
    return kept >= 3 ? out : "";
}

std::string flatName(std::string const& relative) {
    std::string s = relative;
    std::replace(s.begin(), s.end(), '/', '^');
    return s;
}

}  // namespace

SimilarityReport compareSubmissions(std::vector<Submission> const& submissions, std::string const& courseRoot,
                                    std::vector<bxdflab::Exercise> const& exercises, int reportThreshold) {
    SimilarityReport report;
    if (!fs::exists("/usr/bin/sim_c++")) {
        report.note = "similarity was not measured: sim_c++ is not installed (Debian package similarity-tester)";
        return report;
    }
    // The starter's lines, by file name (a file is judged against the skeleton it started from).
    std::map<std::string, std::set<std::string>> skeleton;
    std::string starter = courseRoot + "/starter";
    for (auto const& relative : sourcesIn(starter)) {
        auto& set = skeleton[fs::path(relative).filename().string()];
        for (auto const& line : readLines(starter + "/" + relative)) set.insert(trim(line));
    }
    Scratch work;
    struct Origin {
        std::string who, file;
    };
    std::map<std::string, Origin> origins;  // written path -> where it came from
    std::vector<std::string> newFiles, oldFiles;
    auto add = [&](std::string const& who, std::string const& tag, std::string const& folder, std::string const& relative,
                   std::vector<std::string>& list) {
        std::string text = ownLines(readLines(folder + "/" + relative), skeleton[fs::path(relative).filename().string()]);
        if (text.empty()) return;
        fs::create_directories(work.path() + "/" + tag);
        std::string path = work.path() + "/" + tag + "/" + flatName(relative);
        std::ofstream(path) << text;
        origins[path] = {who, relative};
        list.push_back(path);
    };
    for (size_t k = 0; k < submissions.size(); ++k)
        for (auto const& relative : sourcesIn(submissions[k].folder))
            add(submissions[k].name, "s" + std::to_string(k), submissions[k].folder, relative, newFiles);
    for (auto const& e : exercises) {
        std::string folder = courseRoot + "/" + e.solutionFolder;
        for (auto const& relative : sourcesIn(folder)) add("reference solution", "ref", folder, e.solutionFolder + "/" + relative, oldFiles);
        // Course code that already does what the exercise asks (the stock integrators for ch11).
        for (auto const& relative : e.similarTo) add("course source " + relative, "course", courseRoot, relative, oldFiles);
    }
    if (newFiles.empty()) {
        report.note = "no submission has source files of its own to compare";
        return report;
    }
    // sim_c++ -p: percentages; -e: every pair on its own; -s: no file against itself; files after "/" are old.
    SandboxLayout trusted;
    trusted.confinement = Confinement::Trusted;
    Launch launch;
    launch.argv = {"/usr/bin/sim_c++", "-p", "-e", "-s", "-T", "-t", std::to_string(reportThreshold), "-i"};
    launch.workdir = work.path();
    launch.limits.wallSeconds = 300;
    launch.limits.outputBytes = 8 << 20;
    launch.inputs = {0};
    {
        Child child(trusted, launch);
        std::string list;
        for (auto const& f : newFiles) list += f + "\n";
        list += "/\n";
        for (auto const& f : oldFiles) list += f + "\n";
        child.write(0, list.data(), list.size(), Clock::now() + std::chrono::seconds(30));
        child.closeInput(0);
        ExitStatus status = child.wait(Clock::now() + std::chrono::seconds(300));
        if (!status.ok()) {
            report.note = "sim_c++ " + status.describe(launch.limits);
            return report;
        }
        std::regex line("(.+) consists for ([0-9]+) % of (.+) material");
        std::istringstream in(child.out());
        for (std::string text; std::getline(in, text);) {
            std::smatch m;
            if (!std::regex_match(text, m, line)) continue;
            auto a = origins.find(m[1].str()), b = origins.find(m[3].str());
            if (a == origins.end() || b == origins.end() || a->second.who == b->second.who) continue;
            report.matches.push_back({a->second.who, b->second.who, a->second.file, b->second.file, std::stoi(m[2].str()), ""});
            report.matches.back().regions = m[1].str() + "\n" + m[3].str();  // paths, replaced below
        }
    }
    std::sort(report.matches.begin(), report.matches.end(),
              [](SimilarMatch const& a, SimilarMatch const& b) { return a.percent > b.percent; });
    // The matching regions of flagged pairs, side by side.
    for (auto& m : report.matches) {
        std::string paths = m.regions;
        m.regions.clear();
        if (m.percent < report.flagThreshold) continue;
        size_t split = paths.find('\n');
        Launch regions;
        regions.argv = {"/usr/bin/sim_c++", "-s", "-T", "-w", "160", paths.substr(0, split), paths.substr(split + 1)};
        regions.workdir = work.path();
        regions.limits.wallSeconds = 60;
        regions.limits.outputBytes = 16 << 10;
        Finished f = runToEnd(trusted, regions);
        m.regions = f.out;
    }
    return report;
}

std::string similarityCsv(SimilarityReport const& report) {
    std::string csv = "student,similar_to,file,other_file,percent\r\n";
    for (auto const& m : report.matches)
        csv += csvField(m.student) + "," + csvField(m.other) + "," + csvField(m.file) + "," + csvField(m.otherFile) + "," +
               std::to_string(m.percent) + "\r\n";
    return csv;
}

}  // namespace rixgrade
