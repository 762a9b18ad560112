// The grader's side of rixmeasure: measurements of a student's plugin,
// asked of a sandboxed process in the fixed format of labkit/measure/Wire.h.
// Every answer is checked for form and size before it is believed; a crash,
// a hang or a malformed answer becomes a MeasurementError naming the plugin
// function that was running. After a crash the next question starts a fresh
// process.
#pragma once

#include <memory>

#include "Sandbox.h"
#include "measure/BxdfMeasurer.h"
#include "measure/Wire.h"

namespace rixgrade {

class RemoteMeasurer final : public bxdflab::BxdfMeasurer {
public:
    /// `folder` is where the plugin is, as the sandbox sees it.
    RemoteMeasurer(SandboxLayout layout, std::string plugin, std::string folder, Limits limits);
    ~RemoteMeasurer() override;

    RixBXLobeTraits lobes(std::string const& params) override;
    std::vector<bxdflab::ProbeResult> evaluate(std::string const& params, std::vector<bxdflab::ProbePoint> const& points,
                                               std::vector<bxdflab::Vec3> const& L) override;
    std::vector<bxdflab::ProbeResult> generate(std::string const& params, std::vector<bxdflab::ProbePoint> const& points,
                                               std::vector<bxdflab::SampleSpec> const& samples) override;
    std::vector<bxdflab::ProbeResult> evaluateAtIndex(std::string const& params, bxdflab::ProbePoint const& point,
                                                      std::vector<bxdflab::Vec3> const& L) override;
    std::vector<RtColorRGB> emission(std::string const& params, std::vector<bxdflab::ProbePoint> const& points) override;
    std::vector<bxdflab::DirectionSample> sampleDirections(bxdflab::SamplingFunction f, float exponent,
                                                           std::vector<RtFloat2> const& xi) override;
    std::vector<float> directionPdfs(bxdflab::SamplingFunction f, float exponent,
                                     std::vector<bxdflab::Vec3> const& w) override;

    /// What the plugin printed so far (stderr and stdout, capped).
    std::string printed() const;
    /// Seconds spent waiting for answers.
    double seconds() const { return m_seconds; }

private:
    /// Sends one request (at most wire::kMaxItems items) and returns the reply items' bytes.
    std::vector<char> exchange(bxdflab::wire::Op op, std::string const& params, uint32_t count,
                               std::vector<char> const& payload, uint32_t expectedItems);
    [[noreturn]] void failed(bxdflab::MeasurementError::Kind kind, std::string const& what);

    SandboxLayout m_layout;
    std::string m_plugin, m_folder;
    Limits m_limits;
    std::unique_ptr<Child> m_child;
    std::string m_lastCall = "starting the measuring process";
    std::string m_printed;
    double m_seconds = 0.0;
};

}  // namespace rixgrade
