#include "Grader.h"

#include <sys/stat.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>

#include "OutputFolder.h"
#include "RemoteMeasurer.h"
#include "RenderCache.h"
#include "Scratch.h"
#include "film/RawImage.h"
#include "measure/ProbeMeasurer.h"

namespace rixgrade {

using namespace bxdflab;

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

std::chrono::milliseconds ms(double seconds) { return std::chrono::milliseconds(static_cast<long long>(seconds * 1000)); }

/// The last `lines` lines of a text (what a crashed program said last).
std::string tail(std::string const& text, size_t maxBytes = 800) {
    if (text.size() <= maxBytes) return text;
    return "..." + text.substr(text.size() - maxBytes);
}

bool isRegularFile(std::string const& path) {
    struct stat st;
    return lstat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

/// The compiler's error lines about one exercise's folder.
std::string errorsAbout(std::string const& log, std::string const& folder) {
    std::istringstream in(log);
    std::string line, out;
    int kept = 0;
    while (std::getline(in, line))
        if (line.find("/scratch/submission/" + folder + "/") != std::string::npos && line.find("error") != std::string::npos &&
            kept++ < 8)
            out += line + "\n";
    return out;
}

/// One run of rixrender that sends a scene's raw image (the mean and variance
/// of every pixel) back through descriptor 3.
struct RawRender {
    std::string bytes;  ///< the image, as rixrender wrote it (at most the limit read)
    ExitStatus status;
    std::string said;   ///< what rixrender wrote to stderr
};

/// Renders `scene` at `spp` with `seed`, searching `pluginPath` first, inside
/// `layout`; reads at most `maxBytes` of the image before `limits.wallSeconds`.
RawRender renderRaw(SandboxLayout const& layout, std::string const& rixrender, std::string const& pluginPath,
                    std::string const& scene, int spp, int seed, Limits const& limits, size_t maxBytes,
                    std::string const& workdir = "/scratch", float resolutionScale = 1.0f) {
    Launch launch;
    launch.argv = {rixrender,        "--quiet",  "--spp", std::to_string(spp), "--seed", std::to_string(seed),
                   "--raw-out-fd",   "3",        "--plugin-path", pluginPath, "--resolution-scale",
                   std::to_string(resolutionScale), scene};
    launch.workdir = workdir;
    launch.outputs = {3};
    launch.limits = limits;
    Child child(layout, launch);
    RawRender out;
    auto deadline = Clock::now() + ms(limits.wallSeconds);
    child.readAll(3, out.bytes, maxBytes, deadline);
    out.status = child.wait(deadline);
    out.said = child.err();
    return out;
}

}  // namespace

RenderImage parseRawImage(std::string const& bytes, int expectWidth, int expectHeight) {
    RawImageHeader header;
    if (bytes.size() < sizeof header) throw std::runtime_error("no image came back");
    std::memcpy(&header, bytes.data(), sizeof header);
    if (header.magic != RawImageHeader::kMagic || header.channels != RawImageHeader::kChannels)
        throw std::runtime_error("what came back is not a rixrender raw image");
    // The size is checked before anything is allocated for it.
    if (expectWidth >= 0 && (static_cast<int>(header.width) != expectWidth || static_cast<int>(header.height) != expectHeight))
        throw std::runtime_error("the image is " + std::to_string(header.width) + " x " + std::to_string(header.height) +
                                 " pixels; the scene's is " + std::to_string(expectWidth) + " x " +
                                 std::to_string(expectHeight));
    if (header.width == 0 || header.height == 0 || header.width > 16384 || header.height > 16384)
        throw std::runtime_error("the image has an impossible size");
    size_t pixels = static_cast<size_t>(header.width) * header.height;
    if (bytes.size() != sizeof header + pixels * RawImageHeader::kChannels * sizeof(float))
        throw std::runtime_error("the image has " + std::to_string(bytes.size()) + " bytes, not the size it declares");
    RenderImage image;
    image.width = static_cast<int>(header.width);
    image.height = static_cast<int>(header.height);
    image.rgb.resize(3 * pixels);
    image.variance.resize(3 * pixels);
    char const* data = bytes.data() + sizeof header;
    for (size_t p = 0; p < pixels; ++p) {
        float values[RawImageHeader::kChannels];
        std::memcpy(values, data + p * sizeof values, sizeof values);
        for (int c = 0; c < 3; ++c) {
            image.rgb[3 * p + static_cast<size_t>(c)] = values[c];
            image.variance[3 * p + static_cast<size_t>(c)] = values[4 + c];
        }
    }
    return image;
}

Course::Course(std::string root, std::string binDir, Confinement confinement)
    : m_root(std::move(root)), m_binDir(std::move(binDir)), m_confinement(confinement),
      m_exercises(loadExercises(m_root)) {
    // Which stock plugins are an exercise's solution under another name: the
    // stock build lists them. Without the list no render could be made safely.
    std::string const list = m_binDir + "/../plugins/stock/solutions.json";
    std::ifstream in(list);
    if (!in) throw std::runtime_error("cannot read " + list + " (is the course built?)");
    nlohmann::json const solves = nlohmann::json::parse(in);
    for (auto const& [plugin, exercises] : solves.items()) m_stockSolves[plugin] = exercises.get<std::vector<std::string>>();
}

namespace {

/// Course files a sandbox sees: real path -> path under /course.
using Mounts = std::vector<std::pair<std::string, std::string>>;

SandboxLayout layoutWith(std::string const& scratch, std::string const& plugins, Mounts mounts, std::string const& binDir,
                         std::string const& root, Confinement confinement) {
    SandboxLayout l;
    l.scratch = scratch;
    l.plugins = plugins;
    l.jail = binDir + "/rixjail";
    l.courseRoot = root;
    l.confinement = confinement;
    l.courseMounts = std::move(mounts);
    return l;
}

}  // namespace

SandboxLayout Course::buildLayout(std::string const& scratch) const {
    return layoutWith(scratch, {}, {{m_root + "/cmake", "cmake"}, {m_root + "/renderer/include", "renderer/include"}},
                      m_binDir, m_root, m_confinement);
}

SandboxLayout Course::checkLayout(std::string const& scratch, std::string const& plugins) const {
    return layoutWith(scratch, plugins, {{m_binDir + "/rixmeasure", "bin/rixmeasure"}}, m_binDir, m_root, m_confinement);
}

SandboxLayout Course::renderLayout(std::string const& scratch, std::string const& plugins, Exercise const& e,
                                   std::vector<std::string> const& stock) const {
    std::string const compiled = m_binDir + "/../plugins";
    Mounts mounts = {{m_root + "/scenes", "scenes"},
                     {m_binDir + "/rixrender", "bin/rixrender"},
                     {m_binDir + "/../lib/rixoiio.so", "lib/rixoiio.so"}};  // rixrender's image files
    // An integrator exercise renders without the course's integrators in reach,
    // so a submission cannot hand its work to PxrDirectLighting or PxrPathTracer.
    if (e.kind != "integrator") mounts.push_back({compiled + "/integrators", "plugins/integrators"});
    // The stock plugins the scene uses, one by one, less those that are this exercise's
    // solution under another name (a diffuse plugin must not hand its work to PxrDiffuse).
    for (std::string const& name : stock) {
        auto solves = m_stockSolves.find(name);
        if (solves != m_stockSolves.end() &&
            std::find(solves->second.begin(), solves->second.end(), e.plugin) != solves->second.end())
            continue;
        mounts.push_back({compiled + "/stock/" + name + ".so", "plugins/stock/" + name + ".so"});
    }
    return layoutWith(scratch, plugins, std::move(mounts), m_binDir, m_root, m_confinement);
}

SandboxLayout Course::layout(std::string const& scratch) const {
    SandboxLayout all = buildLayout(scratch);
    for (auto const& mount : checkLayout(scratch, {}).courseMounts) all.courseMounts.push_back(mount);
    Exercise none;  // solved by no stock plugin, not an integrator: every render mount
    std::vector<std::string> stock;
    std::error_code error;
    for (auto const& entry : std::filesystem::directory_iterator(m_binDir + "/../plugins/stock", error))
        if (entry.path().extension() == ".so") stock.push_back(entry.path().stem().string());
    std::sort(stock.begin(), stock.end());
    for (auto const& mount : renderLayout(scratch, {}, none, stock).courseMounts) all.courseMounts.push_back(mount);
    return all;
}

std::vector<std::string> const& Course::stockPluginsOf(std::string const& scene) {
    std::lock_guard<std::mutex> guard(m_stockLock);  // one scene at a time: a render each, once
    auto found = m_sceneStock.find(scene);
    if (found != m_sceneStock.end()) return found->second;
    // A one-pixel render with the solutions says which plugins the scene loads, and from where.
    SandboxLayout trusted;
    trusted.confinement = Confinement::Trusted;
    Limits limits;
    limits.wallSeconds = 120;
    limits.memoryBytes = 0;
    std::string const plugins = m_binDir + "/../plugins";
    RawRender probe = renderRaw(trusted, m_binDir + "/rixrender", plugins + "/solutions", m_root + "/scenes/" + scene, 1, 2,
                                limits, 1u << 20, m_root, 0.01f);
    if (!probe.status.ok())
        throw std::runtime_error("the scene " + scene + " does not render with the solutions: " + tail(probe.said));
    std::vector<std::string> stock;
    std::regex const loaded(R"re(([A-Za-z0-9_]+) \(([^)]*)\))re");
    // Its line "rixrender: plugins: NAME (PATH), ..."
    size_t const line = probe.said.rfind("rixrender: plugins: ");
    std::string const said = line == std::string::npos ? "" : probe.said.substr(line, probe.said.find('\n', line) - line);
    std::string const stockFolder = std::filesystem::weakly_canonical(plugins + "/stock").string();
    for (std::sregex_iterator it(said.begin(), said.end(), loaded), end; it != end; ++it)
        if (std::filesystem::weakly_canonical((*it)[2].str()).parent_path().string() == stockFolder)
            stock.push_back((*it)[1].str());
    return m_sceneStock[scene] = stock;
}

BxdfMeasurer& Course::reference(std::string const& plugin) {
    std::lock_guard<std::mutex> guard(m_lock);
    auto& slot = m_references[plugin];
    if (!slot) {
        static Diagnostics quiet(false);
        slot = std::make_unique<ProbeMeasurer>(plugin, std::vector<std::string>{m_binDir + "/../plugins/solutions"}, quiet);
    }
    return *slot;
}

RenderImage const& Course::referenceRender(std::string const& scene, int spp, double seconds) {
    std::string key = scene + "@" + std::to_string(spp);
    std::mutex* lock;
    {
        std::lock_guard<std::mutex> guard(m_lock);
        auto& l = m_renderLocks[key];
        if (!l) l = std::make_unique<std::mutex>();
        lock = l.get();
    }
    std::lock_guard<std::mutex> guard(*lock);  // one student renders it, the others wait and share it
    {
        std::lock_guard<std::mutex> g(m_lock);
        if (m_renders.count(key)) return *m_renders[key];
    }
    // Rendered before, by this or an earlier grading run, with the same renderer, plugins and scene?
    int const seed = 2;  // not the students' seed (1): the two renders' noise is independent
    std::string const scenePath = m_root + "/scenes/" + scene, plugins = m_binDir + "/../plugins";
    std::string const cacheFolder = m_binDir + "/../grader-cache";
    std::string const cacheKey = renderCacheKey(scenePath, spp, seed,
                                                {m_binDir + "/rixrender", m_binDir + "/../lib", plugins + "/solutions",
                                                 plugins + "/integrators", plugins + "/stock",
                                                 std::filesystem::path(scenePath).parent_path().string()});
    std::unique_ptr<RenderImage> image;
    if (std::optional<std::string> bytes = loadCachedRender(cacheFolder, cacheKey)) {
        try {
            image = std::make_unique<RenderImage>(parseRawImage(*bytes));
        } catch (std::exception const&) {
            image.reset();  // damaged: render it again
        }
    }
    if (!image) {
        SandboxLayout trusted;
        trusted.confinement = Confinement::Trusted;
        Limits limits;
        limits.wallSeconds = seconds;
        limits.memoryBytes = 0;
        RawRender render = renderRaw(trusted, m_binDir + "/rixrender", plugins + "/solutions", scenePath, spp, seed,
                                     limits, 1u << 30, m_root);
        if (!render.status.ok())
            throw std::runtime_error("the reference render of " + scene + " " + render.status.describe(limits) + ": " +
                                     tail(render.said));
        image = std::make_unique<RenderImage>(parseRawImage(render.bytes));
        storeCachedRender(cacheFolder, cacheKey, render.bytes);
    }
    std::lock_guard<std::mutex> g(m_lock);
    return *(m_renders[key] = std::move(image));
}

std::vector<std::pair<std::string, double>> Course::pointsFor(Exercise const& e, nlohmann::json const& rubric) const {
    nlohmann::json const chapters = rubric.value("chapters", nlohmann::json::object());
    if (chapters.contains(e.chapter) && chapters[e.chapter].contains(e.plugin)) {
        nlohmann::json const checks = chapters[e.chapter][e.plugin].value("checks", nlohmann::json::object());
        // The manifest's order first, then any check only the rubric names.
        std::vector<std::pair<std::string, double>> points;
        for (auto const& [check, value] : e.checks)
            if (checks.contains(check)) points.emplace_back(check, checks[check].get<double>());
        for (auto const& [check, value] : checks.items())
            if (std::none_of(points.begin(), points.end(), [&](auto const& p) { return p.first == check; }))
                points.emplace_back(check, value.get<double>());
        return points;
    }
    return e.checks;
}

namespace {

/// The images a report shows for a render check.
void writeRenderImages(OutputFolder const& out, std::string const& plugin, RenderImage const& mine,
                       RenderImage const& theirs, RenderVerdict const& v) {
    std::string dir = "renders/" + plugin + "/";
    out.writePng(dir + "student.png", mine.rgb, mine.width, mine.height);
    out.writePng(dir + "solution.png", theirs.rgb, theirs.width, theirs.height);
    std::vector<float> difference(mine.rgb.size()), failing(mine.rgb.size());
    for (size_t i = 0; i < mine.rgb.size(); ++i)
        difference[i] = std::isfinite(mine.rgb[i]) ? std::min(1.0f, std::fabs(mine.rgb[i] - theirs.rgb[i])) : 1.0f;
    // Failing pixels: red where yours is brighter, blue where darker; grey shows how close to failing the rest are.
    for (size_t p = 0; p < v.zMap.size(); ++p) {
        float z = v.zMap[p], a = std::fabs(z) / static_cast<float>(v.zCritical);
        float grey = 0.25f * std::min(1.0f, a);
        float rgb[3] = {grey, grey, grey};
        if (a > 1.0f) {
            rgb[0] = z > 0 ? 1.0f : 0.0f;
            rgb[1] = 0.0f;
            rgb[2] = z > 0 ? 0.0f : 1.0f;
        }
        for (int c = 0; c < 3; ++c) failing[3 * p + static_cast<size_t>(c)] = rgb[c];
    }
    out.writePng(dir + "difference.png", difference, mine.width, mine.height);
    out.writePng(dir + "failing-pixels.png", failing, mine.width, mine.height);
}

/// One scene rendered with the student's plugin and compared with the solution's render.
struct SceneRender {
    std::string problem;                  ///< why there is no image to compare, or empty
    std::string rendererSaid;             ///< the end of the renderer's messages
    RenderImage mine;
    RenderImage const* theirs = nullptr;
    RenderVerdict verdict;
};

SceneRender renderScene(Exercise const& e, std::string const& scene, Course& course, SandboxLayout const& layout,
                        nlohmann::json const& rubric) {
    SceneRender out;
    int spp = e.renderSpp > 0 ? e.renderSpp : rubric.value("render_spp", 8);
    double seconds = rubric.value("render_timeout_s", 300.0);
    RenderImage const* theirs;
    try {
        theirs = &course.referenceRender(scene, spp, seconds);
    } catch (std::exception const& error) {
        out.problem = std::string("could not be graded: ") + error.what();
        return out;
    }
    SandboxLayout renderLayout;
    try {
        renderLayout = course.renderLayout(layout.scratch, layout.plugins, e, course.stockPluginsOf(scene));
    } catch (std::exception const& error) {
        out.problem = std::string("could not be graded: ") + error.what();
        return out;
    }
    std::string const pluginPath =
        (e.kind == "integrator" ? std::string() : std::string("/course/plugins/integrators:")) + "/course/plugins/stock:/plugins";
    Limits limits;
    limits.wallSeconds = seconds;
    size_t expected = sizeof(RawImageHeader) + static_cast<size_t>(theirs->width) * theirs->height * RawImageHeader::kChannels * 4;
    RawRender render = renderRaw(renderLayout, "/course/bin/rixrender", pluginPath, "/course/scenes/" + scene, spp, 1,
                                 limits, expected + 1);
    out.rendererSaid = tail(render.said, 2000);
    if (!render.status.ok()) {
        out.problem = "rendering " + scene + " with your plugin " + render.status.describe(limits) +
                      (render.said.empty() ? "" : "; the renderer said: " + tail(render.said, 400));
        return out;
    }
    try {
        out.mine = parseRawImage(render.bytes, theirs->width, theirs->height);
    } catch (std::exception const& error) {
        out.problem = std::string("your render did not come back as an image: ") + error.what();
        return out;
    }
    out.theirs = theirs;
    out.verdict = compareRenders(out.mine, *theirs, 16.0, e.compareBlock);
    return out;
}

/// One scene's two images, kept for the noise check.
struct SceneImages {
    std::string scene;
    RenderImage mine;
    RenderImage const* theirs = nullptr;
};

/// A render check's result, and the images of every scene that came back (for the noise check that follows it).
struct RenderOutcome {
    CheckResult result;
    std::vector<SceneImages> images;  ///< in the manifest's order; empty until a render came back as an image
};

/// Renders every scene of the exercise; the check passes when each agrees with
/// the solution's. The report shows the images of the first scene that does
/// not (or of the first scene).
RenderOutcome renderCheck(Exercise const& e, double points, Course& course, SandboxLayout const& layout,
                          nlohmann::json const& rubric, OutputFolder const& out) {
    RenderOutcome outcome{CheckResult::start(e, "renders", points), {}};
    CheckResult& r = outcome.result;
    auto start = Clock::now();
    std::optional<SceneRender> shown;
    std::string failure, agreements;
    for (std::string const& scene : e.scenes) {
        SceneRender one = renderScene(e, scene, course, layout, rubric);
        std::string prefix = e.scenes.size() > 1 ? scene + ": " : "";
        if (!one.problem.empty()) {
            failure = prefix + one.problem;
            r.details = one.rendererSaid;
            break;
        }
        outcome.images.push_back({scene, one.mine, one.theirs});
        agreements += prefix + one.verdict.message + "\n";
        bool const failed = !one.verdict.passed();
        if (failed || !shown) {
            shown = std::move(one);
            r.details = shown->rendererSaid;
        }
        if (failed) {
            failure = prefix + shown->verdict.message;
            break;
        }
    }
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (shown) {
        writeRenderImages(out, e.plugin, shown->mine, *shown->theirs, shown->verdict);
        r.hasImages = true;
    }
    if (!failure.empty()) {
        r.summary = failure;
        return outcome;
    }
    r.status = CheckOutcome::Status::Passed;
    r.score = points;
    r.summary = e.scenes.size() > 1 ? "all " + std::to_string(e.scenes.size()) + " scenes agree with the solution's" : agreements.substr(0, agreements.size() - 1);
    if (e.scenes.size() > 1) r.details = agreements + r.details;
    return outcome;
}

/// The noise check: the first scene's variance at most noiseLimit times the
/// solution's, and each of the manifest's sameNoiseScenes within noiseLimit
/// of it both ways (there the scene fixes the estimator).
NoiseVerdict noiseVerdict(Exercise const& e, std::vector<SceneImages> const& images) {
    NoiseVerdict all;
    all.passed = true;
    for (SceneImages const& image : images) {
        bool const fixed = std::find(e.sameNoiseScenes.begin(), e.sameNoiseScenes.end(), image.scene) !=
                           e.sameNoiseScenes.end();
        if (&image != &images.front() && !fixed) continue;
        NoiseVerdict v = compareNoise(image.mine, *image.theirs, e.noiseLimit, fixed);
        if (e.scenes.size() > 1) v.message = image.scene + ": " + v.message;
        if (!v.passed) return v;
        if (&image == &images.front()) all.ratio = v.ratio;
        all.message += (all.message.empty() ? "" : "; ") + v.message;
    }
    return all;
}

}  // namespace

bool selected(Exercise const& e, GradeOptions const& options) {
    auto has = [](std::vector<std::string> const& list, std::string const& x) {
        return list.empty() || std::find(list.begin(), list.end(), x) != list.end();
    };
    return has(options.chapters, e.chapter) && has(options.only, e.plugin);
}

namespace {

/// An exercise whose work the API already does (its manifest's writeYourself,
/// e.g. chapter 8's samplers) is compiled again by the grader from the
/// manifest's sources alone, with those API functions poisoned: a call, however
/// it is spelt (a header of the submission, a macro pasting the name), stops
/// the compile. Leaves the plugin at graded/<plugin>.so in the scratch folder
/// and returns "", or returns why the exercise is not graded.
std::string compileOwnWork(Exercise const& e, Course const& course, Scratch& scratch, nlohmann::json const& rubric) {
    std::string const header = "writeyourself-" + e.plugin + ".h";
    {
        std::ofstream poison(scratch.graderFolder() + "/" + header);
        poison << "// The API functions that do exercise " << e.plugin << "'s work: its code may not use them.\n"
               << "#pragma once\n#include \"RixShadingUtils.h\"\n#pragma GCC poison";
        for (auto const& name : e.writeYourself) poison << " " << name;
        poison << "\n";
    }
    std::error_code error;
    std::filesystem::remove_all(scratch.path() + "/graded", error);  // whatever the build left there, links included
    std::filesystem::create_directory(scratch.path() + "/graded", error);
    scratch.handOver();

    std::string const folder = "/scratch/submission/" + e.folder.substr(std::strlen("starter/"));
    Launch compile;
    compile.argv = {"c++", "-std=c++17", "-O2", "-fPIC", "-shared", "-fvisibility=hidden", "-I", "/course/renderer/include/rix",
                    "-I", folder, "-I", "/scratch/submission/common", "-include", "/course/grader/" + header};
    for (auto const& source : e.sources) compile.argv.push_back(folder + "/" + source);
    compile.argv.insert(compile.argv.end(), {"-o", "/scratch/graded/" + e.plugin + ".so"});
    compile.allowProcesses = true;
    compile.limits.wallSeconds = rubric.value("build_timeout_s", 600.0);
    compile.limits.fileBytes = 512ull << 20;
    compile.limits.processes = 64;
    compile.limits.scratchBytes = 2ull << 30;
    SandboxLayout layout = course.buildLayout(scratch.path());
    layout.courseMounts.push_back({scratch.graderFolder(), "grader"});
    Finished built = runToEnd(layout, compile);
    if (built.status.ok()) return "";
    // The compiler's first error, without the sandbox's folder names.
    std::string firstError;
    std::istringstream lines(built.err);
    for (std::string line; std::getline(lines, line);)
        if (line.find("error") != std::string::npos) {
            if (firstError.empty() || line.find("poisoned") != std::string::npos) firstError = line;
            if (line.find("poisoned") != std::string::npos) break;
        }
    for (std::string const& prefix : {layout.realPath(folder) + "/", layout.realPath("/scratch/submission") + "/"})
        for (size_t at; (at = firstError.find(prefix)) != std::string::npos;) firstError.erase(at, prefix.size());
    if (firstError.find("poisoned") != std::string::npos)
        return "chapter " + e.chapter + " asks you to write this exercise's functions yourself, not to call the API's, "
               "and your code calls one: " + firstError;
    return "compiled from its own sources alone (as its exercise.json lists them, with its folder and common/ for "
           "headers) it does not build: " + (firstError.empty() ? built.status.describe(compile.limits) : firstError);
}

}  // namespace

Grade grade(GradeOptions const& options, Course& course, OutputFolder const& out) {
    auto start = Clock::now();
    Grade g;
    g.name = options.name;
    g.confinement = course.confinement() == Confinement::Sandbox
                        ? "Student code ran in a bubblewrap sandbox: no network, nothing of this machine but the "
                          "system and the course's API visible, only its scratch folder writable, Landlock, seccomp "
                          "and resource limits inside."
                        : "WARNING: graded with --unsafe-no-sandbox. Student code ran without namespaces: Landlock "
                          "kept its reads to the system, the course's API and its scratch folder and its writes to "
                          "the scratch folder, but it could reach the network and signal the grader's processes; "
                          "seccomp and resource limits confined it too.";
    Scratch scratch(options.scratchParent);
    if (options.keepScratch) scratch.keep();
    SandboxLayout const layout = course.buildLayout(scratch.path());
    nlohmann::json const& rubric = options.rubric;

    bool configured = false;
    if (!options.plugins.empty()) {
        scratch.copyPlugins(options.plugins, "build/plugins");
        scratch.handOver();
        configured = g.built = true;
    } else {
        Scratch::CopyReport copied = scratch.copySubmission(options.submission, "submission");
        std::string log;
        for (auto const& s : copied.skipped) log += "left out of the build: " + s + "\n";
        g.lookAt = copied.lookAt;
        for (auto const& file : copied.lookAt) log += "to look at: " + file + "\n";
        scratch.handOver();
        Launch configure;
        configure.argv = {"cmake", "-S", "/scratch/submission", "-B", "/scratch/build", "-DBXDFLAB_ROOT=/course",
                          "-DCMAKE_BUILD_TYPE=Release"};
        configure.allowProcesses = true;
        configure.limits.wallSeconds = rubric.value("configure_timeout_s", 120.0);
        configure.limits.fileBytes = 512ull << 20;
        configure.limits.processes = 512;
        configure.limits.scratchBytes = 2ull << 30;
        configure.limits.outputBytes = 256 * 1024;
        Finished c = runToEnd(layout, configure);
        log += c.out + c.err;
        configured = c.status.ok();
        if (!configured) {
            log += "\nCMake could not configure the submission: it " + c.status.describe(configure.limits) + "\n";
        } else {
            Launch build = configure;
            build.limits.wallSeconds = rubric.value("build_timeout_s", 600.0);
            // -k: a plugin that does not compile costs only its own checks.
            // Returns whether the build named a target the submission does not have.
            auto buildTargets = [&](std::vector<std::string> const& targets) {
                build.argv = {"cmake", "--build", "/scratch/build", "--parallel", "2"};
                if (!targets.empty()) build.argv.push_back("--target");
                build.argv.insert(build.argv.end(), targets.begin(), targets.end());
                build.argv.insert(build.argv.end(), {"--", "-k"});
                Finished b = runToEnd(layout, build);
                std::string const said = b.out + b.err;
                bool const unknownTarget = !b.status.ok() && !targets.empty() &&
                                           (said.find("No rule to make target") != std::string::npos ||
                                            said.find("unknown target") != std::string::npos);
                if (unknownTarget) return true;
                log += said;
                if (!b.status.ok()) log += "\nThe build " + b.status.describe(build.limits) + "\n";
                return false;
            };
            // Grading some exercises builds only their plugins (the starter names each target
            // after its plugin); a submission whose CMakeLists names them otherwise is built
            // whole, as it is when everything is graded.
            std::vector<std::string> targets;
            if (!options.only.empty() || !options.chapters.empty())
                for (Exercise const& e : course.exercises())
                    if (selected(e, options)) targets.push_back(e.plugin);
            if (buildTargets(targets)) buildTargets({});
        }
        g.built = configured;
        g.buildLog = log;
        std::regex warning("warning:");
        g.buildWarnings = static_cast<int>(
            std::distance(std::sregex_iterator(log.begin(), log.end(), warning), std::sregex_iterator()));
    }

    // Exercises whose work the API already does, compiled again from their own sources.
    std::map<std::string, std::string> ownWork;  // plugin -> why it is not graded ("" when it was compiled)
    if (options.plugins.empty() && configured)
        for (Exercise const& e : course.exercises())
            if (selected(e, options) && !e.writeYourself.empty()) ownWork[e.plugin] = compileOwnWork(e, course, scratch, rubric);
    // What was built is what every check and render loads: no stage can change it.
    std::string const pluginFolder = scratch.freezePlugins("build/plugins");
    for (auto const& [plugin, why] : ownWork)
        if (why.empty()) scratch.freezeAs("graded/" + plugin + ".so", plugin + ".so");
    SandboxLayout const checking = course.checkLayout(scratch.path(), pluginFolder);

    Limits checkLimits;
    checkLimits.wallSeconds = rubric.value("check_timeout_s", 60.0);
    checkLimits.processes = 64;
    std::vector<Exercise const*> graded;
    for (Exercise const& e : course.exercises())
        if (selected(e, options)) graded.push_back(&e);
    // Plugins are graded side by side (each has its own sandboxed processes);
    // their results are gathered in the course's order.
    std::vector<std::vector<CheckResult>> results(graded.size());
    std::vector<std::string> printed(graded.size());
    auto gradePlugin = [&](size_t k) {
        Exercise const& e = *graded[k];
        auto points = course.pointsFor(e, rubric);
        bool present = isRegularFile(pluginFolder + "/" + e.plugin + ".so");
        if (!present) {
            std::string why;
            if (!options.plugins.empty())
                why = e.plugin + ".so is not in the plugin folder";
            else if (!configured)
                why = "the submission did not configure with CMake (see the build log)";
            else {
                std::string errors = errorsAbout(g.buildLog, e.folder.substr(std::strlen("starter/")));
                why = e.plugin + ".so was not built" +
                      (errors.empty() ? " (is it in your CMakeLists.txt? see the build log)" : "; the compiler said:\n" + errors);
            }
            for (auto const& [check, max] : points) {
                results[k].push_back(CheckResult::start(e, check, max));
                results[k].back().summary = why;
            }
            return;
        }
        RemoteMeasurer student(checking, e.plugin, "/plugins", checkLimits);
        std::string stopped;  // why the remaining checks are not run (a plugin that hung once)
        if (auto own = ownWork.find(e.plugin); own != ownWork.end() && !own->second.empty()) stopped = own->second;
        std::optional<RenderOutcome> rendered;  // the "renders" check's images, for "noise"
        for (auto const& [check, max] : points) {
            CheckResult r = CheckResult::start(e, check, max);
            auto checkStart = Clock::now();
            if (!stopped.empty()) {
                r.summary = "not run: " + stopped;
            } else if (check == "renders") {
                rendered = renderCheck(e, max, course, checking, rubric, out);
                r = rendered->result;
            } else if (check == "noise") {
                if (!rendered || rendered->images.empty()) {
                    r.summary = "not run: it compares the images of the renders check, which must come first and "
                                "produce an image";
                } else if (!rendered->result.passed()) {
                    // A wrong image earns nothing for being smooth (a black one has no noise at all).
                    r.summary = "not graded: the noise of an image counts only once the image is right (the renders "
                                "check failed)";
                } else {
                    NoiseVerdict const v = noiseVerdict(e, rendered->images);
                    r.status = v.passed ? CheckOutcome::Status::Passed : CheckOutcome::Status::Failed;
                    r.summary = v.message;
                }
            } else {
                try {
                    CheckContext context{e, student, course.reference(e.plugin), options.seed};
                    CheckOutcome outcome = runCheck(check, context);
                    r.status = outcome.status;
                    r.summary = outcome.summary;
                    r.details = outcome.details;
                } catch (MeasurementError const& m) {
                    using Kind = MeasurementError::Kind;
                    if (m.kind() == Kind::Hung) {
                        r.summary = "your plugin " + std::string(m.what()) + " in " + m.call() + " (an endless loop?)";
                        stopped = "your plugin hung in " + m.call() + " during the " + check +
                                  " check, so its remaining checks are skipped";
                    } else if (m.kind() == Kind::Crashed) {
                        r.summary = "your plugin " + std::string(m.what()) + ", in " + m.call();
                        r.hint = bxdflab::crashHint();
                    } else if (m.kind() == Kind::PluginError && m.call().rfind("loading", 0) == 0) {
                        r.summary = "your plugin could not be loaded: " + std::string(m.what());
                    } else if (m.kind() == Kind::PluginError) {
                        r.summary = "your plugin threw an exception in " + m.call() + ": " + m.what();
                    } else if (m.kind() == Kind::Overran) {
                        r.summary = "your plugin's " + std::string(m.what());
                    } else {
                        r.summary = "the measuring process " + std::string(m.what());
                    }
                } catch (std::invalid_argument const& unknown) {
                    r.summary = std::string("the rubric names an unknown check: ") + unknown.what();
                }
                r.seconds = std::chrono::duration<double>(Clock::now() - checkStart).count();
            }
            if (r.passed()) r.score = max;
            results[k].push_back(r);
        }
        printed[k] = student.printed();
    };
    tbb::task_arena arena(rubric.value("plugins_at_once", 2));
    arena.execute([&] { tbb::parallel_for(size_t(0), graded.size(), size_t(1), gradePlugin); });
    for (size_t k = 0; k < graded.size(); ++k) {
        g.checks.insert(g.checks.end(), results[k].begin(), results[k].end());
        if (!printed[k].empty()) g.pluginOutput[graded[k]->plugin] = printed[k];
    }
    g.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return g;
}

}  // namespace rixgrade
