// Measures a plugin loaded into this process (through BxdfProbe): the
// course's own tests, a student's self-check, and the reference solutions
// the autograder compares with. One probe per parameter set, kept.
#pragma once

#include <map>
#include <memory>
#include <mutex>

#include "measure/BxdfMeasurer.h"
#include "shade/SharedObject.h"

namespace bxdflab {

class ProbeMeasurer final : public BxdfMeasurer {
public:
    /// `plugin` is looked for in `searchPath` only (no built-in folders).
    ProbeMeasurer(std::string plugin, std::vector<std::string> searchPath, Diagnostics& diagnostics,
                  BxdfProbe::CallObserver observer = nullptr);
    ~ProbeMeasurer() override;

    RixBXLobeTraits lobes(std::string const& params) override;
    std::vector<ProbeResult> evaluate(std::string const& params, std::vector<ProbePoint> const& points,
                                      std::vector<Vec3> const& L) override;
    std::vector<ProbeResult> generate(std::string const& params, std::vector<ProbePoint> const& points,
                                      std::vector<SampleSpec> const& samples) override;
    std::vector<ProbeResult> evaluateAtIndex(std::string const& params, ProbePoint const& point,
                                             std::vector<Vec3> const& L) override;
    std::vector<RtColorRGB> emission(std::string const& params, std::vector<ProbePoint> const& points) override;
    std::vector<DirectionSample> sampleDirections(SamplingFunction f, float exponent,
                                                  std::vector<RtFloat2> const& xi) override;
    std::vector<float> directionPdfs(SamplingFunction f, float exponent, std::vector<Vec3> const& w) override;

private:
    BxdfProbe& probe(std::string const& params);
    /// askedTogether(): `ask(probe, begin, end)` answers points [begin, end)
    /// on one probe; two probes of `params` (two instances of the plugin) ask
    /// for the two halves of `count` points on two threads at once, `rounds` times.
    template <typename Ask>
    std::vector<ProbeResult> askTogether(std::string const& params, int rounds, size_t count, Ask&& ask);
    /// One call of the probe per point (evaluate, generate): on this thread, or
    /// split between two threads when the parameters ask for that.
    template <typename Input, typename Call>
    std::vector<ProbeResult> askPerPoint(std::string const& params, std::vector<ProbePoint> const& points,
                                         std::vector<Input> const& inputs, Call&& call);
    /// The sampling exercise's entry points (loaded on first use).
    void loadSampling();

    std::string m_plugin;
    std::vector<std::string> m_searchPath;
    Diagnostics& m_diagnostics;
    BxdfProbe::CallObserver m_observer;
    std::map<std::string, std::unique_ptr<BxdfProbe>> m_probes;
    std::mutex m_lock;  ///< one question at a time (the grader shares solutions between students)

    using SampleFn = int (*)(int function, float exponent, float xi0, float xi1, float* w, float* pdf);
    using PdfFn = float (*)(int function, float exponent, float const* w);
    std::unique_ptr<SharedObject> m_sampling;
    SampleFn m_sample = nullptr;
    PdfFn m_pdf = nullptr;
};

}  // namespace bxdflab
