// An exercise's facts, read from the exercise.json beside its starter
// (starter/chNN/<plugin>/exercise.json): the one place that says what a
// plugin is checked with and what it must satisfy. rixcheck, rixgrade, the
// solutions' tests, the reports and the starter build all read it; adding an
// exercise is one folder and one manifest.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace bxdflab {

/// How a model treats views from below its surface (V on the back side of Ng).
enum class Sidedness {
    TwoSided,  ///< it reflects on both sides (the normal is turned toward V)
    OneSided,  ///< it is black seen from below
    Either,    ///< the exercise accepts both (the course text writes it one-sided, the reference two-sided)
};

struct SamplingMode {
    std::string name;    ///< e.g. "cosine"
    std::string params;  ///< RIB parameters selecting it, e.g. "\"int samplingMode\" [1]" (may be empty)
    bool singleDraw = true;  ///< one 2-D draw maps to the direction (so the Jacobian check applies)
};

/// A property check that does not apply to a model, and why (said in the report).
struct NotApplicable {
    std::string check, because;
};

struct Exercise {
    std::string plugin;   ///< the plugin's name (and the .so's)
    std::string chapter;  ///< "6", "7", "8", ...
    std::string title;
    int order = 0;        ///< place within its chapter (the order the chapter teaches them)
    std::string kind;     ///< "bxdf", "sampling" (the ch08 sampling functions) or "integrator" (ch11)
    std::string folder;   ///< the starter folder, relative to the course root ("starter/ch06/diffuse")
    std::string solutionFolder;  ///< relative to the course root ("solutions/ch06/diffuse")
    std::vector<std::string> sources;              ///< files the plugin is built from
    std::vector<std::string> identicalToSolution;  ///< starter files that must equal the solution's
    std::string scene;    ///< rendered for the "renders" check (relative to scenes/), or empty
    std::vector<std::string> scenes;  ///< every scene the "renders" check compares ("scenes", or just "scene")
    std::vector<std::string> similarTo;  ///< course files (from the root) a copy of which the similarity report flags
    /// API functions that do this exercise's work: the grader compiles the
    /// exercise from its sources alone with these poisoned, so none is called.
    std::vector<std::string> writeYourself;
    int renderSpp = 0;        ///< samples per pixel of the "renders" check's images (0: the rubric's render_spp)
    int compareBlock = 1;     ///< the "renders" check compares squares of this many pixels a side (see compareRenders)
    double noiseLimit = 1.5;  ///< the "noise" check: the render's variance at most this times the solution's
    /// Scenes (of `scenes`) whose parameters fix the estimator, one sampling
    /// strategy alone: there the "noise" check also wants the variance at
    /// least 1 / noiseLimit times the solution's.
    std::vector<std::string> sameNoiseScenes;

    std::string params;       ///< parameters every check uses (white where energy matters)
    std::string colorParams;  ///< a second, coloured set the values check also compares
    std::vector<std::string> hardCaseParams;  ///< extreme parameter sets the hard-cases check adds
    std::vector<SamplingMode> samplingModes;  ///< at least one

    Sidedness sides = Sidedness::TwoSided;
    bool emitsOnly = false;      ///< no lobes: only EmitLocal
    bool anisotropic = false;    ///< depends on the tangent direction (views at several azimuths)
    bool reciprocal = true;      ///< f(V, L) = f(L, V)
    std::string notReciprocalBecause;  ///< why not, for the report, where reciprocal is false
    bool conservesEnergy = true; ///< directional albedo <= 1 for white parameters
    std::vector<NotApplicable> notApplicable;  ///< checks skipped for this model, with the reason

    /// A model that also transmits (chapter 10): its directions fill the whole
    /// sphere, and radiance crossing the boundary scales by the square of the
    /// ratio of refractive indices, which reciprocity and energy account for.
    bool transmits = false;
    std::string iorParam;      ///< the float parameter holding the refractive index inside (e.g. "ior")
    std::string smoothParams;  ///< parameters that make the boundary smooth (discrete lobes), for the "smooth" check

    std::vector<std::pair<std::string, double>> checks;  ///< check name -> default points, in report order

    /// Whether `check` is one rixgrade runs by rendering the exercise's scene
    /// ("renders", "noise") rather than by probing the plugin.
    static bool isRenderCheck(std::string const& check);
    /// Whether the exercise is graded with `check`.
    bool gradedWith(std::string const& check) const;
    /// The reason `check` does not apply, or empty.
    std::string notApplicableReason(std::string const& check) const;
    /// The refractive index inside that a parameter string sets (iorParam's
    /// value), 1 for a model that does not transmit. Throws when it is missing.
    double ior(std::string const& params) const;
    /// params + a sampling mode's parameters.
    std::string withMode(std::string const& base, SamplingMode const& mode) const;
};

/// Reads one manifest; throws std::runtime_error naming the file and the field.
Exercise loadExercise(std::string const& courseRoot, std::string const& manifestPath);
/// Every exercise of the course (starter/ch*/*/exercise.json), by chapter then plugin.
std::vector<Exercise> loadExercises(std::string const& courseRoot);
/// The exercise for `plugin`, or nullptr.
Exercise const* findExercise(std::vector<Exercise> const& exercises, std::string const& plugin);

}  // namespace bxdflab
