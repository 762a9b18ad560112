// Drives a Bxdf plugin directly, without a scene: the test suite and the
// autograder use it to ask a plugin for values, pdfs and samples at shade
// points they choose (normal, tangent, view direction), through the same
// loader, parameter matching and RixShadingContext interface as a render.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "RixBxdf.h"
#include "core/Diagnostics.h"
#include "core/Math.h"

namespace bxdflab {

/// A plugin function (call()) wrote past the end of memory the shading context
/// gave it (an array of numPts entries, or a block it allocated itself);
/// what() says so, naming the function, so that the message stands alone
/// when it crosses to the grader.
class MemoryOverrun : public std::runtime_error {
public:
    MemoryOverrun(std::string call, std::string const& what) : std::runtime_error(what), m_call(std::move(call)) {}
    std::string const& call() const { return m_call; }

private:
    std::string m_call;
};

/// A shade point set up by hand.
struct ProbePoint {
    Vec3 N{0.0f, 0.0f, 1.0f};     ///< unit shading normal
    Vec3 Ng{0.0f, 0.0f, 1.0f};    ///< unit geometric normal
    Vec3 dPdu{1.0f, 0.0f, 0.0f};  ///< tangent (any length; zero for a degenerate frame)
    Vec3 V{0.0f, 0.0f, 1.0f};     ///< unit direction toward the viewer
    bool wantsLobes = true;       ///< lobesWanted: every lobe, or (false) none
};

/// One answer of the Bxdf: the sampled or given direction, W = f |cos|, pdfs.
struct ProbeResult {
    Vec3 L{0.0f};
    RtColorRGB W;
    float FPdf = 0.0f;
    float RPdf = 0.0f;
    bool valid = false;  ///< GenerateSample: lobeSampled valid; EvaluateSample: some lobe evaluated
    bool discrete = false;  ///< GenerateSample: the sampled lobe is discrete (a single direction, like a mirror)
};

class BxdfProbe {
public:
    using CallObserver = void (*)(char const* call);
    /// Loads `plugin` (searching `searchPath`, then, when searchBuiltins is
    /// set, the usual plugin search path with the built-in folders) and makes
    /// one instance with `ribParams`, written as in a RIB Bxdf line, e.g.
    /// "\"color diffuseColor\" [1 1 1]". Throws RenderError/RibError. Every
    /// call below throws MemoryOverrun when the plugin wrote past an array.
    BxdfProbe(std::string const& plugin, std::string const& ribParams, std::vector<std::string> const& searchPath,
              Diagnostics& diagnostics, bool searchBuiltins = true, CallObserver observer = nullptr);
    ~BxdfProbe();
    BxdfProbe(BxdfProbe const&) = delete;
    BxdfProbe& operator=(BxdfProbe const&) = delete;

    /// GenerateSample for a batch, point i drawing from samples[i] (see
    /// labkit/measure/BxdfMeasurer.h for the usual ways to fill them).
    std::vector<ProbeResult> generate(std::vector<ProbePoint> const& points, std::vector<RixRNG::SampleCtx> samples);
    /// EvaluateSample for a batch: direction L[i] at points[i].
    std::vector<ProbeResult> evaluate(std::vector<ProbePoint> const& points, std::vector<Vec3> const& L);
    /// EvaluateSamplesAtIndex: many directions at one point. The point is
    /// index 1 of a two-point batch whose point 0 faces another way, so that a
    /// Bxdf reading index 0 where it should read `index` is seen.
    std::vector<ProbeResult> evaluateAtIndex(ProbePoint const& point, std::vector<Vec3> const& L);
    /// EmitLocal for a batch (zero where the Bxdf does not emit).
    std::vector<RtColorRGB> emission(std::vector<ProbePoint> const& points);
    /// The Bxdf's aggregate lobes (asked on a one-point batch).
    RixBXLobeTraits lobes();

    /// Called with the name of each plugin function just before it runs
    /// ("BeginScatter", "GenerateSample", ...), so that a crash can be blamed
    /// on the right one. The constructor's calls (loading, CreateInstanceData,
    /// Synchronize) are announced through the same hook when it is given there.
    void setCallObserver(CallObserver observer);
    /// Makes every float, colour and vector parameter the Bxdf reads per point
    /// (EvalParam with promote) differ from point to point, as a connected
    /// texture makes it: point i gets share s = varyingShare(i + firstShare) of
    /// a float or colour, and a vector turned by adding 1 - s of its components
    /// in turn. (A batch moved one place later with firstShare - 1 keeps every
    /// point's values.) With coloursOnly, floats and vectors stay as given.
    void setParamsVaryPerPoint(bool vary, int firstShare = 0, bool coloursOnly = false);
    /// A share in [0.85, 1], different for neighbouring points.
    static float varyingShare(int i);

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace bxdflab
