#include "measure/ProbeMeasurer.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <exception>
#include <filesystem>
#include <thread>

#include "core/CrashReport.h"
#include "core/Error.h"

namespace bxdflab {

namespace {

/// Runs one probe call; a write past an array becomes the measurement error
/// the checks report, naming the plugin function that made it.
template <typename Call> auto guarded(Call&& call) {
    try {
        return call();
    } catch (MemoryOverrun const& e) {
        throw MeasurementError(MeasurementError::Kind::Overran, e.call(), e.what());
    }
}

/// The same answer to the bit (a NaN included); field by field, as the
/// struct's padding holds anything.
bool sameBits(ProbeResult const& a, ProbeResult const& b) {
    auto same = [](auto const& x, auto const& y) { return std::memcmp(&x, &y, sizeof x) == 0; };
    return same(a.L, b.L) && same(a.W, b.W) && same(a.FPdf, b.FPdf) && same(a.RPdf, b.RPdf) && a.valid == b.valid &&
           a.discrete == b.discrete;
}

template <typename T> std::vector<T> slice(std::vector<T> const& all, size_t begin, size_t end) {
    return std::vector<T>(all.begin() + static_cast<std::ptrdiff_t>(begin), all.begin() + static_cast<std::ptrdiff_t>(end));
}

}  // namespace

template <typename Ask>
std::vector<ProbeResult> ProbeMeasurer::askTogether(std::string const& params, int rounds, size_t count, Ask&& ask) {
    rounds = std::clamp(rounds, 1, 256);
    size_t const half = count / 2;
    // A second instance of the plugin (same shared object, so the same static
    // and global variables), as two render threads would shade with.
    BxdfProbe* probes[2] = {&probe(params), &probe(params + "\n# the second thread's instance\n")};
    std::vector<ProbeResult> first[2], shown[2];
    std::exception_ptr failure[2];
    std::atomic<int> ready{0};
    auto run = [&](int t) {
        try {
            ready.fetch_add(1);
            while (ready.load() < 2) std::this_thread::yield();  // start together, to overlap
            size_t const begin = t == 0 ? 0 : half, end = t == 0 ? half : count;
            for (int round = 0; round < rounds; ++round) {
                std::vector<ProbeResult> answers = ask(*probes[t], begin, end);
                if (round == 0) {
                    first[t] = shown[t] = answers;
                    continue;
                }
                for (size_t i = 0; i < answers.size() && i < first[t].size(); ++i)
                    if (sameBits(shown[t][i], first[t][i]) && !sameBits(answers[i], first[t][i])) shown[t][i] = answers[i];
            }
        } catch (...) {
            failure[t] = std::current_exception();
            ready.store(2);
        }
    };
    std::thread second([&] {
        crashreport::prepareThread();  // a crash on this thread is reported too
        run(1);
    });
    run(0);
    second.join();
    for (auto const& f : failure)
        if (f) std::rethrow_exception(f);
    shown[0].insert(shown[0].end(), shown[1].begin(), shown[1].end());
    return shown[0];
}

ProbeMeasurer::ProbeMeasurer(std::string plugin, std::vector<std::string> searchPath, Diagnostics& diagnostics,
                             BxdfProbe::CallObserver observer)
    : m_plugin(std::move(plugin)), m_searchPath(std::move(searchPath)), m_diagnostics(diagnostics), m_observer(observer) {}

ProbeMeasurer::~ProbeMeasurer() = default;

BxdfProbe& ProbeMeasurer::probe(std::string const& params) {
    auto& slot = m_probes[params];
    if (!slot) {
        try {
            std::string ribParams = params;
            std::optional<VaryingMark> const varying = takeVaryingMark(ribParams);
            slot = std::make_unique<BxdfProbe>(m_plugin, ribParams, m_searchPath, m_diagnostics, false, m_observer);
            if (varying) slot->setParamsVaryPerPoint(true, varying->firstShare, varying->coloursOnly);
        } catch (std::exception const& e) {
            m_probes.erase(params);
            throw MeasurementError(MeasurementError::Kind::PluginError, "loading the plugin", e.what());
        }
    }
    return *slot;
}

RixBXLobeTraits ProbeMeasurer::lobes(std::string const& params) {
    std::lock_guard<std::mutex> guard(m_lock);
    return guarded([&] { return probe(params).lobes(); });
}

template <typename Input, typename Call>
std::vector<ProbeResult> ProbeMeasurer::askPerPoint(std::string const& params, std::vector<ProbePoint> const& points,
                                                    std::vector<Input> const& inputs, Call&& call) {
    std::lock_guard<std::mutex> guard(m_lock);
    std::string asked = params;
    if (std::optional<int> rounds = takeTogetherMark(asked))
        return guarded([&] {
            return askTogether(asked, *rounds, points.size(), [&](BxdfProbe& p, size_t begin, size_t end) {
                return call(p, slice(points, begin, end), slice(inputs, begin, end));
            });
        });
    return guarded([&] { return call(probe(params), points, inputs); });
}

std::vector<ProbeResult> ProbeMeasurer::evaluate(std::string const& params, std::vector<ProbePoint> const& points,
                                                 std::vector<Vec3> const& L) {
    return askPerPoint(params, points, L, [](BxdfProbe& p, std::vector<ProbePoint> const& at,
                                             std::vector<Vec3> const& directions) { return p.evaluate(at, directions); });
}

std::vector<ProbeResult> ProbeMeasurer::generate(std::string const& params, std::vector<ProbePoint> const& points,
                                                 std::vector<SampleSpec> const& samples) {
    return askPerPoint(params, points, samples,
                       [](BxdfProbe& p, std::vector<ProbePoint> const& at, std::vector<SampleSpec> const& randoms) {
                           return p.generate(at, randoms);
                       });
}

std::vector<ProbeResult> ProbeMeasurer::evaluateAtIndex(std::string const& params, ProbePoint const& point,
                                                        std::vector<Vec3> const& L) {
    std::lock_guard<std::mutex> guard(m_lock);
    return guarded([&] { return probe(params).evaluateAtIndex(point, L); });
}

std::vector<RtColorRGB> ProbeMeasurer::emission(std::string const& params, std::vector<ProbePoint> const& points) {
    std::lock_guard<std::mutex> guard(m_lock);
    return guarded([&] { return probe(params).emission(points); });
}

void ProbeMeasurer::loadSampling() {
    if (m_sampling) return;
    std::string found;
    for (auto const& folder : m_searchPath) {
        std::error_code error;
        auto candidate = std::filesystem::path(folder) / (m_plugin + ".so");
        if (std::filesystem::is_regular_file(candidate, error)) {
            found = candidate.string();
            break;
        }
    }
    if (found.empty())
        throw MeasurementError(MeasurementError::Kind::PluginError, "loading the plugin",
                               m_plugin + ".so was not built (is it in your CMakeLists.txt?)");
    if (m_observer) m_observer("loading the plugin (its static initialisers)");
    try {
        m_sampling = std::make_unique<SharedObject>(found, "the sampling exercise (" + found + ")");
    } catch (std::exception const& e) {
        throw MeasurementError(MeasurementError::Kind::PluginError, "loading the plugin", e.what());
    }
    m_sample = reinterpret_cast<SampleFn>(m_sampling->symbol("RixSamplingExerciseSample"));
    m_pdf = reinterpret_cast<PdfFn>(m_sampling->symbol("RixSamplingExercisePdf"));
    if (!m_sample || !m_pdf)
        throw MeasurementError(MeasurementError::Kind::PluginError, "loading the plugin",
                               found + " does not export RixSamplingExerciseSample and RixSamplingExercisePdf "
                                       "(keep SamplingExport.cpp in the build)");
}

std::vector<DirectionSample> ProbeMeasurer::sampleDirections(SamplingFunction f, float exponent,
                                                             std::vector<RtFloat2> const& xi) {
    std::lock_guard<std::mutex> guard(m_lock);
    loadSampling();
    std::vector<DirectionSample> out(xi.size());
    if (m_observer) m_observer("your sampling function");
    for (size_t i = 0; i < xi.size(); ++i) {
        float w[3] = {0, 0, 0}, pdf = 0;
        m_sample(static_cast<int>(f), exponent, xi[i].x, xi[i].y, w, &pdf);
        out[i] = {Vec3(w[0], w[1], w[2]), pdf};
    }
    return out;
}

std::vector<float> ProbeMeasurer::directionPdfs(SamplingFunction f, float exponent, std::vector<Vec3> const& w) {
    std::lock_guard<std::mutex> guard(m_lock);
    loadSampling();
    std::vector<float> out(w.size());
    if (m_observer) m_observer("your pdf function");
    for (size_t i = 0; i < w.size(); ++i) {
        float v[3] = {w[i].x, w[i].y, w[i].z};
        out[i] = m_pdf(static_cast<int>(f), exponent, v);
    }
    return out;
}

}  // namespace bxdflab
