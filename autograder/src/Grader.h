// Grades one submission: copies it into a scratch folder, builds it in the
// sandbox, measures each plugin through a sandboxed rixmeasure and renders
// its scene with a sandboxed rixrender -- and judges every measurement here,
// in the grader, which never loads student code. The reference side (the
// solutions' measurements and renders) is shared by every grading of a run.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "Sandbox.h"
#include "checks/Check.h"
#include "exercise/Exercise.h"
#include "image/RenderComparison.h"

namespace rixgrade {

struct CheckResult {
    std::string chapter, plugin, check;
    double score = 0.0, maxScore = 0.0;
    bxdflab::CheckOutcome::Status status = bxdflab::CheckOutcome::Status::Failed;
    std::string summary;  ///< the verdict in one sentence, with its numbers
    std::string details;  ///< every number it rests on
    std::string hint;     ///< what to look at, when not the check's own hint (a crash)
    double seconds = 0.0;
    bool hasImages = false;  ///< a render check that wrote renders/<plugin>/*.png
    bool passed() const { return status != bxdflab::CheckOutcome::Status::Failed; }
    /// A failed result with no points yet, for `check` of exercise `e`.
    static CheckResult start(bxdflab::Exercise const& e, std::string const& check, double maxScore) {
        CheckResult r;
        r.chapter = e.chapter;
        r.plugin = e.plugin;
        r.check = check;
        r.maxScore = maxScore;
        return r;
    }
};

struct Grade {
    std::string name;  ///< the submission's name as given (a class folder's name)
    std::vector<CheckResult> checks;
    std::string buildLog;
    int buildWarnings = 0;
    std::vector<std::string> lookAt;  ///< its files an instructor should look at, and why (compiled code, embedded data)
    bool built = false;              ///< CMake configured and built at least part of it
    std::string confinement;         ///< how student code was confined, for the reports
    std::string error;               ///< why grading stopped, when it did (the student gets 0 and this reason)
    std::map<std::string, std::string> pluginOutput;  ///< what each plugin printed (capped)
    double seconds = 0.0;
    double score() const;
    double maxScore() const;
};

struct GradeOptions {
    std::string submission;  ///< a copy of starter/ with the student's code (built with CMake)
    std::string plugins;     ///< or: a folder of already built plugins (no build)
    std::string name;        ///< shown in reports (default: the folder's name)
    std::vector<std::string> chapters;  ///< empty: all
    std::vector<std::string> only;      ///< grade only these plugins (empty: all)
    nlohmann::json rubric;   ///< points and time limits (autograder/rubric.json)
    uint32_t seed = 0;       ///< the grader's own random draws
    bool keepScratch = false;
    std::string scratchParent;
};

/// The course side of a grading run: where the course is, how student code
/// is confined, the reference solutions' measurements and renders (computed
/// once, shared by every student of a class).
class Course {
public:
    Course(std::string root, std::string binDir, Confinement confinement);
    std::string const& root() const { return m_root; }
    std::vector<bxdflab::Exercise> const& exercises() const { return m_exercises; }
    Confinement confinement() const { return m_confinement; }
    /// What student code sees of the course, stage by stage: each stage only
    /// what it needs, and never a reference solution or a compiled copy of one.
    /// The build: the API headers and the CMake helpers.
    SandboxLayout buildLayout(std::string const& scratch) const;
    /// The checks: the measuring program and the submission's frozen plugins.
    SandboxLayout checkLayout(std::string const& scratch, std::string const& plugins) const;
    /// A render of exercise e: the renderer, the scenes, the integrators (not
    /// for an integrator exercise) and the `stock` plugins the scene uses, less
    /// those built from e's own solution (plugins/stock/solutions.json).
    SandboxLayout renderLayout(std::string const& scratch, std::string const& plugins, bxdflab::Exercise const& e,
                               std::vector<std::string> const& stock) const;
    /// The stock plugins (names) a scene loads, found once by rendering one pixel of it.
    std::vector<std::string> const& stockPluginsOf(std::string const& scene);
    /// All that any stage mounts (to check up front that it can be mounted).
    SandboxLayout layout(std::string const& scratch) const;
    /// The reference solution of an exercise (loaded once, shared).
    bxdflab::BxdfMeasurer& reference(std::string const& plugin);
    /// The reference render of a scene (rendered once per spp, shared). Throws on failure.
    bxdflab::RenderImage const& referenceRender(std::string const& scene, int spp, double seconds);
    /// Points of a check of a plugin: the rubric's when it sets them, else the manifest's.
    std::vector<std::pair<std::string, double>> pointsFor(bxdflab::Exercise const& e, nlohmann::json const& rubric) const;

private:
    std::string m_root, m_binDir;
    Confinement m_confinement;
    std::vector<bxdflab::Exercise> m_exercises;
    std::map<std::string, std::vector<std::string>> m_stockSolves;  ///< stock plugin -> exercises it solves
    std::mutex m_stockLock;
    std::map<std::string, std::vector<std::string>> m_sceneStock;  ///< scene -> stock plugins it loads
    std::mutex m_lock;
    std::map<std::string, std::unique_ptr<bxdflab::BxdfMeasurer>> m_references;
    std::map<std::string, std::unique_ptr<bxdflab::RenderImage>> m_renders;
    std::map<std::string, std::unique_ptr<std::mutex>> m_renderLocks;
};

/// Whether an exercise is among those `options` asks for.
bool selected(bxdflab::Exercise const& e, GradeOptions const& options);

class OutputFolder;
/// Grades one submission; report images go into `out` (renders/<plugin>/...).
Grade grade(GradeOptions const& options, Course& course, OutputFolder const& out);

/// Reads raw image bytes (film/RawImage.h) and checks their form; throws with the reason.
bxdflab::RenderImage parseRawImage(std::string const& bytes, int expectWidth = -1, int expectHeight = -1);

}  // namespace rixgrade
