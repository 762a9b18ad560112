#include "Grader.h"

#include <chrono>
#include <filesystem>
#include <regex>

#include "ChildProcess.h"
#include "RenderComparison.h"

namespace fs = std::filesystem;

namespace rixgrade {

double Grade::score() const {
    double s = 0;
    for (auto const& c : checks) s += c.score;
    return s;
}

double Grade::maxScore() const {
    double s = 0;
    for (auto const& c : checks) s += c.maxScore;
    return s;
}

namespace {

/// The first failure Catch2 reported in its JUnit output, in a readable form.
std::string firstFailure(std::string const& junit) {
    // <failure message="expression" type="REQUIRE">details (INFO lines, file:line)</failure>
    std::smatch match;
    std::regex failure("<failure(?: message=\"([^\"]*)\")?[^>]*>([\\s\\S]*?)</failure>");
    std::string text;
    if (std::regex_search(junit, match, failure)) {
        text = match[1].matched ? match[1].str() + "\n" : "";
        std::string body = match[2].str();
        if (body.rfind("\nFAILED:\n", 0) == 0 || body.rfind("FAILED:\n", 0) == 0) body = body.substr(body.find(":\n") + 2);
        text += body;
    }
    for (auto const& [entity, plain] : {std::pair<std::string, std::string>{"&quot;", "\""}, {"&lt;", "<"}, {"&gt;", ">"},
                                        {"&#10;", "\n"}, {"&apos;", "'"}, {"&amp;", "&"}}) {
        for (size_t at; (at = text.find(entity)) != std::string::npos;) text.replace(at, entity.size(), plain);
    }
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    return text.size() > 1500 ? text.substr(0, 1500) + " ..." : text;
}

/// Student code (checks and renders) may write only into the grading folder
/// and may not start processes; a build may start processes (compilers).
SandboxPolicy confined(GradeOptions const& options, bool allowNewProcesses = false) {
    return {{options.out}, allowNewProcesses};
}

/// Children keep their temporary files in the grading folder too.
std::map<std::string, std::string> gradingEnvironment(GradeOptions const& options, std::map<std::string, std::string> extra = {}) {
    extra["TMPDIR"] = options.out + "/tmp";
    return extra;
}

CheckResult runCheck(GradeOptions const& options, std::string const& pluginDir, std::string const& chapter,
                     std::string const& plugin, std::string const& check, double points) {
    CheckResult r{chapter, plugin, check, 0.0, points, false, "", 0.0};
    Limits limits;
    limits.seconds = options.rubric.value("check_timeout_s", 120.0);
    Outcome outcome = run({options.binDir + "/rixcheck", "[" + check + "]", "-r", "junit"},
                          gradingEnvironment(options, {{"RIXCHECK_PLUGIN", plugin}, {"RIXCHECK_PLUGIN_DIR", pluginDir}}),
                          options.out, limits, confined(options));
    r.seconds = outcome.seconds;
    if (outcome.ok()) {
        r.passed = true;
        r.score = points;
        r.output = "passed";
    } else if (outcome.timedOut || outcome.signal) {
        r.output = "the " + check + " check " + outcome.describe(limits) + " while running your plugin";
    } else {
        std::string why = firstFailure(outcome.out);
        r.output = why.empty() ? "failed (" + outcome.describe(limits) + "): " + outcome.err.substr(0, 800) : why;
    }
    return r;
}

CheckResult runRender(GradeOptions const& options, std::string const& pluginDir, std::string const& chapter,
                      std::string const& plugin, std::string const& scene, double points) {
    CheckResult r{chapter, plugin, "renders", 0.0, points, false, "", 0.0};
    std::string dir = options.out + "/renders/" + plugin;
    fs::create_directories(dir);
    std::string spp = std::to_string(options.rubric.value("render_spp", 8));
    std::string scenePath = options.root + "/scenes/" + scene;
    Limits limits;
    limits.seconds = options.rubric.value("render_timeout_s", 300.0);
    auto render = [&](std::string const& who, std::string const& seed, std::vector<std::string> extra) {
        std::vector<std::string> argv = {options.binDir + "/rixrender", "--quiet", "--spp", spp, "--seed", seed,
                                         "-o", dir + "/" + who + ".exr", "--variance", dir + "/" + who + "-variance.exr"};
        argv.insert(argv.end(), extra.begin(), extra.end());
        argv.push_back(scenePath);
        return run(argv, gradingEnvironment(options), options.out, limits, confined(options));
    };
    Outcome mine = render("student", "1", {"--plugin-path", pluginDir});
    Outcome theirs = render("solution", "2", {});
    r.seconds = mine.seconds + theirs.seconds;
    if (!mine.ok()) {
        r.output = "rendering " + scene + " with your plugin " + mine.describe(limits) + ": " + mine.err.substr(0, 800);
        return r;
    }
    if (!theirs.ok()) {
        r.output = "the solution's render failed: " + theirs.err.substr(0, 400);
        return r;
    }
    RenderVerdict v = compareRenders(dir + "/student.exr", dir + "/student-variance.exr", dir + "/solution.exr",
                                     dir + "/solution-variance.exr", dir + "/failing-pixels.png");
    r.passed = v.passed;
    r.score = v.passed ? points : 0.0;
    r.output = v.message;
    // Display versions for the HTML report.
    run({options.binDir + "/rixdiff", dir + "/student.exr", dir + "/solution.exr", "--heatmap", dir + "/difference.png"},
        gradingEnvironment(options), options.out, limits, confined(options));
    for (std::string who : {"student", "solution"}) toDisplayPng(dir + "/" + who + ".exr", dir + "/" + who + ".png");
    return r;
}

}  // namespace

Grade grade(GradeOptions const& options) {
    auto start = std::chrono::steady_clock::now();
    Grade g;
    g.submission = options.submission.empty() ? options.plugins : options.submission;
    fs::create_directories(options.out);
    fs::create_directories(options.out + "/tmp");

    std::string pluginDir = options.plugins;
    if (pluginDir.empty()) {
        // Build the submission against the course's API, in scratch space.
        std::string build = options.out + "/build";
        Limits limits;
        limits.seconds = 600;
        Outcome configure = run({"cmake", "-S", options.submission, "-B", build, "-DBXDFLAB_ROOT=" + options.root,
                                 "-DCMAKE_BUILD_TYPE=Release"},
                                gradingEnvironment(options), options.out, limits, confined(options, true));
        Outcome compile = configure.ok() ? run({"cmake", "--build", build, "--parallel", "2"}, gradingEnvironment(options),
                                               options.out, limits, confined(options, true))
                                         : configure;
        g.buildLog = configure.out + configure.err + (configure.ok() ? compile.out + compile.err : "");
        g.built = configure.ok() && compile.ok();
        std::regex warning("warning:");
        g.buildWarnings = static_cast<int>(std::distance(std::sregex_iterator(g.buildLog.begin(), g.buildLog.end(), warning),
                                                         std::sregex_iterator()));
        pluginDir = build + "/plugins";
    } else {
        g.built = fs::is_directory(pluginDir);
    }

    for (auto const& [chapter, plugins] : options.rubric["chapters"].items()) {
        if (!options.chapters.empty() &&
            std::find(options.chapters.begin(), options.chapters.end(), chapter) == options.chapters.end())
            continue;
        for (auto const& [plugin, spec] : plugins.items()) {
            bool present = fs::is_regular_file(pluginDir + "/" + plugin + ".so");
            for (auto const& [check, points] : spec["checks"].items()) {
                double max = points.get<double>();
                if (!g.built || !present) {
                    g.checks.push_back({chapter, plugin, check, 0.0, max, false,
                                        !g.built ? "the submission did not build (see the build log)"
                                                 : plugin + ".so was not built (is it in your CMakeLists.txt?)",
                                        0.0});
                } else if (check == "renders") {
                    g.checks.push_back(runRender(options, pluginDir, chapter, plugin, spec.value("scene", ""), max));
                } else {
                    g.checks.push_back(runCheck(options, pluginDir, chapter, plugin, check, max));
                }
            }
        }
    }
    g.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return g;
}

}  // namespace rixgrade
