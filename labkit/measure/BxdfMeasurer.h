// What the checks ask of a Bxdf plugin: values, pdfs and samples at shade
// points and with random numbers the asker chooses. Two implementations:
//   ProbeMeasurer   loads the plugin into this process (the course's own
//                   tests, a student's self-check, the reference solutions);
//   RemoteMeasurer  (autograder) asks a sandboxed rixmeasure process, so the
//                   grader never loads student code.
// The checks (labkit/checks) judge the answers; a measurer only measures.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "probe/BxdfProbe.h"

namespace bxdflab {

/// A measurement that could not be made. `call` names the plugin function
/// that was running ("GenerateSample", "loading the plugin", ...).
class MeasurementError : public std::runtime_error {
public:
    enum class Kind {
        PluginError,  ///< the plugin could not be loaded or refused the parameters (message says why)
        Crashed,      ///< the process running the plugin died (signal or exit)
        Hung,         ///< no answer within the time allowed
        BadReply,     ///< an answer that does not have the promised form
        Overran,      ///< the plugin wrote past the end of an array it was given (message says where)
    };
    MeasurementError(Kind kind, std::string call, std::string const& what)
        : std::runtime_error(what), m_kind(kind), m_call(std::move(call)) {}
    Kind kind() const { return m_kind; }
    std::string const& call() const { return m_call; }

private:
    Kind m_kind;
    std::string m_call;
};

/// Random numbers for one GenerateSample point: a sequence position, or a
/// fixed value every draw returns (the sampling mapping itself).
using SampleSpec = RixRNG::SampleCtx;

/// The ch08 sampling exercise's functions, by number.
enum class SamplingFunction : int { UniformHemisphere = 0, CosineHemisphere = 1, PhongLobe = 2 };

struct DirectionSample {
    Vec3 w{0.0f};
    float pdf = 0.0f;
};

class BxdfMeasurer {
public:
    virtual ~BxdfMeasurer() = default;

    /// `params` are written as on a RIB Bxdf line ("\"float gloss\" [30]");
    /// every call may use a different set, and varyingParams() makes a set
    /// differ from point to point.
    virtual RixBXLobeTraits lobes(std::string const& params) = 0;
    virtual std::vector<ProbeResult> evaluate(std::string const& params, std::vector<ProbePoint> const& points,
                                              std::vector<Vec3> const& L) = 0;
    virtual std::vector<ProbeResult> generate(std::string const& params, std::vector<ProbePoint> const& points,
                                              std::vector<SampleSpec> const& samples) = 0;
    virtual std::vector<ProbeResult> evaluateAtIndex(std::string const& params, ProbePoint const& point,
                                                     std::vector<Vec3> const& L) = 0;
    virtual std::vector<RtColorRGB> emission(std::string const& params, std::vector<ProbePoint> const& points) = 0;

    /// The ch08 sampling exercise (a plugin exporting the three samplers).
    virtual std::vector<DirectionSample> sampleDirections(SamplingFunction f, float exponent,
                                                          std::vector<RtFloat2> const& xi) = 0;
    virtual std::vector<float> directionPdfs(SamplingFunction f, float exponent, std::vector<Vec3> const& w) = 0;
};

/// `params` made to differ from point to point, as a texture connected to
/// them would: every float, colour and vector the Bxdf reads per point
/// (EvalParam with promote) changes with the point (BxdfProbe::
/// setParamsVaryPerPoint). Point i takes varyingShare(i + firstShare): a
/// batch shifted one place later with firstShare -1 gives every point the
/// values it had before. The mark is a RIB comment, so the set stays a valid
/// parameter list.
std::string varyingParams(std::string const& params, int firstShare = 0);
/// The same for colours alone: floats and vectors (a refractive index that
/// fixes where light goes, say) stay as given.
std::string varyingColours(std::string const& params);
/// What varyingParams() or varyingColours() asked for.
struct VaryingMark {
    int firstShare = 0;
    bool coloursOnly = false;
};
/// Removes either function's mark from `params`; what it asked for, when it was there.
std::optional<VaryingMark> takeVaryingMark(std::string& params);

/// `params` asked of two instances of the plugin on two threads at once, for
/// `rounds` rounds: evaluate() and generate() give the first half of the
/// points to one thread and the rest to the other. A point's answer is the
/// first round's, or the first answer that differed from it. A plugin that
/// keeps per-call data in a static or global variable answers differently
/// than from one thread. The mark is a RIB comment, like varyingParams()'s.
std::string askedTogether(std::string const& params, int rounds);
/// Removes askedTogether()'s mark from `params`; its rounds when it was there.
std::optional<int> takeTogetherMark(std::string& params);

// Common ways of drawing random numbers, built on generate().

/// Point i takes sample `first + i` of one scrambled low-discrepancy sequence.
std::vector<SampleSpec> stratifiedSamples(size_t count, uint32_t seed, uint32_t first = 0);
/// Every point gets independent uniform numbers (what statistical tests assume).
std::vector<SampleSpec> independentSamples(size_t count, uint32_t seed, uint32_t first = 0);
/// Every draw of every point returns xi; 1-D draws return `choice` if it is
/// given (>= 0), else xi[0].
std::vector<SampleSpec> fixedSamples(size_t count, RtFloat2 xi, float choice = -1.0f);

}  // namespace bxdflab
