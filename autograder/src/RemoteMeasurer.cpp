#include "RemoteMeasurer.h"

namespace rixgrade {

using namespace bxdflab;
using wire::Op;

namespace {

/// Requests are split so that no batch exceeds this many items.
constexpr size_t kBatch = 1u << 17;

template <typename Item, typename Source, typename Make>
std::vector<char> pack(Source const& source, size_t first, size_t count, Make make) {
    std::vector<char> bytes;
    bytes.reserve(count * sizeof(Item));
    for (size_t i = first; i < first + count; ++i) wire::append(bytes, make(source, i));
    return bytes;
}

}  // namespace

RemoteMeasurer::RemoteMeasurer(SandboxLayout layout, std::string plugin, std::string folder, Limits limits)
    : m_layout(std::move(layout)), m_plugin(std::move(plugin)), m_folder(std::move(folder)), m_limits(limits) {}

RemoteMeasurer::~RemoteMeasurer() = default;

std::string RemoteMeasurer::printed() const {
    std::string all = m_printed;
    if (m_child) all += m_child->err() + m_child->out();
    return all.size() > 4000 ? all.substr(0, 4000) + "\n[... more output cut]" : all;
}

void RemoteMeasurer::failed(MeasurementError::Kind kind, std::string const& what) {
    if (m_child) {
        m_printed += m_child->err() + m_child->out();
        m_child.reset();  // killed if still running
    }
    std::string call = m_lastCall;
    m_lastCall = "starting the measuring process";
    throw MeasurementError(kind, call, what);
}

std::vector<char> RemoteMeasurer::exchange(Op op, std::string const& params, uint32_t count,
                                           std::vector<char> const& payload, uint32_t expectedItems) {
    auto start = Clock::now();
    auto deadline = start + std::chrono::milliseconds(static_cast<long>(m_limits.wallSeconds * 1000));
    if (!m_child) {
        Launch launch;
        launch.argv = {"/course/bin/rixmeasure", m_plugin, m_folder};
        launch.limits = m_limits;
        launch.limits.wallSeconds = 1e9;  // each answer has its own deadline
        launch.inputs = {3};
        launch.outputs = {4};
        m_child = std::make_unique<Child>(m_layout, launch);
        m_lastCall = "starting the measuring process";
    }
    auto io = [&](Child::Io result) {
        if (result == Child::Io::Done) return;
        if (result == Child::Io::TimedOut) {
            failed(MeasurementError::Kind::Hung,
                   "did not answer within " + std::to_string(static_cast<int>(m_limits.wallSeconds)) + " s");
        }
        ExitStatus status = m_child->wait(Clock::now() + std::chrono::seconds(5));
        std::string said = m_child->err();
        if (said.size() > 600) said = "..." + said.substr(said.size() - 600);
        failed(MeasurementError::Kind::Crashed,
               status.describe(m_limits) + (said.empty() ? "" : "; it printed:\n" + said));
    };

    wire::RequestHeader header{wire::kRequestMagic, static_cast<uint32_t>(op), count,
                               static_cast<uint32_t>(params.size())};
    io(m_child->write(3, &header, sizeof header, deadline));
    io(m_child->write(3, params.data(), params.size(), deadline));
    io(m_child->write(3, payload.data(), payload.size(), deadline));

    for (;;) {
        uint32_t magic = 0;
        io(m_child->read(4, &magic, sizeof magic, deadline));
        if (magic == wire::kCallMagic) {
            uint32_t length = 0;
            io(m_child->read(4, &length, sizeof length, deadline));
            if (length > wire::kMaxCallNameBytes) failed(MeasurementError::Kind::BadReply, "sent a malformed answer");
            std::string name(length, '\0');
            io(m_child->read(4, name.data(), length, deadline));
            m_lastCall = name;
            continue;
        }
        if (magic != wire::kReplyMagic) failed(MeasurementError::Kind::BadReply, "sent a malformed answer");
        uint32_t rest[3];
        io(m_child->read(4, rest, sizeof rest, deadline));
        if (rest[0] != static_cast<uint32_t>(op)) failed(MeasurementError::Kind::BadReply, "answered another question");
        if (rest[2] != 0) {
            if (rest[1] > wire::kMaxMessageBytes) failed(MeasurementError::Kind::BadReply, "sent a malformed answer");
            std::string message(rest[1], '\0');
            io(m_child->read(4, message.data(), message.size(), deadline));
            std::string call = m_lastCall;
            throw MeasurementError(rest[2] == wire::kErrorOverran ? MeasurementError::Kind::Overran
                                                                  : MeasurementError::Kind::PluginError,
                                   call, message);
        }
        if (rest[1] != expectedItems) failed(MeasurementError::Kind::BadReply, "answered with the wrong number of items");
        std::vector<char> reply(static_cast<size_t>(expectedItems) * wire::replyItemBytes(op));
        io(m_child->read(4, reply.data(), reply.size(), deadline));
        m_seconds += std::chrono::duration<double>(Clock::now() - start).count();
        return reply;
    }
}

RixBXLobeTraits RemoteMeasurer::lobes(std::string const& params) {
    auto reply = exchange(Op::Lobes, params, 1, {}, 1);
    return RixBXLobeTraits::FromBits(wire::itemAt<wire::LobesItem>(reply, 0).bits);
}

std::vector<ProbeResult> RemoteMeasurer::evaluate(std::string const& params, std::vector<ProbePoint> const& points,
                                                  std::vector<Vec3> const& L) {
    std::vector<ProbeResult> out;
    out.reserve(points.size());
    for (size_t first = 0; first < points.size(); first += kBatch) {
        size_t n = std::min(kBatch, points.size() - first);
        auto payload = pack<wire::EvaluateItem>(points, first, n, [&](auto const&, size_t i) {
            wire::EvaluateItem item{wire::toWire(points[i]), {L[i].x, L[i].y, L[i].z}};
            return item;
        });
        auto reply = exchange(Op::Evaluate, params, static_cast<uint32_t>(n), payload, static_cast<uint32_t>(n));
        for (size_t i = 0; i < n; ++i) out.push_back(wire::fromWire(wire::itemAt<wire::ResultItem>(reply, i)));
    }
    return out;
}

std::vector<ProbeResult> RemoteMeasurer::generate(std::string const& params, std::vector<ProbePoint> const& points,
                                                  std::vector<SampleSpec> const& samples) {
    std::vector<ProbeResult> out;
    out.reserve(points.size());
    for (size_t first = 0; first < points.size(); first += kBatch) {
        size_t n = std::min(kBatch, points.size() - first);
        auto payload = pack<wire::GenerateItem>(points, first, n, [&](auto const&, size_t i) {
            SampleSpec const& s = samples[i];
            return wire::GenerateItem{
                wire::toWire(points[i]), s.patternid, s.sampleid, s.fixedValue, s.fixedValue2, s.fixedValue1D};
        });
        auto reply = exchange(Op::Generate, params, static_cast<uint32_t>(n), payload, static_cast<uint32_t>(n));
        for (size_t i = 0; i < n; ++i) out.push_back(wire::fromWire(wire::itemAt<wire::ResultItem>(reply, i)));
    }
    return out;
}

std::vector<ProbeResult> RemoteMeasurer::evaluateAtIndex(std::string const& params, ProbePoint const& point,
                                                         std::vector<Vec3> const& L) {
    std::vector<ProbeResult> out;
    for (size_t first = 0; first < L.size(); first += kBatch) {
        size_t n = std::min(kBatch, L.size() - first);
        std::vector<char> payload;
        wire::append(payload, wire::toWire(point));
        for (size_t i = first; i < first + n; ++i) wire::append(payload, wire::Vec3Item{{L[i].x, L[i].y, L[i].z}});
        auto reply = exchange(Op::EvaluateAtIndex, params, static_cast<uint32_t>(n), payload, static_cast<uint32_t>(n));
        for (size_t i = 0; i < n; ++i) out.push_back(wire::fromWire(wire::itemAt<wire::ResultItem>(reply, i)));
    }
    return out;
}

std::vector<RtColorRGB> RemoteMeasurer::emission(std::string const& params, std::vector<ProbePoint> const& points) {
    std::vector<RtColorRGB> out;
    for (size_t first = 0; first < points.size(); first += kBatch) {
        size_t n = std::min(kBatch, points.size() - first);
        auto payload = pack<wire::PointItem>(points, first, n, [&](auto const&, size_t i) { return wire::toWire(points[i]); });
        auto reply = exchange(Op::Emission, params, static_cast<uint32_t>(n), payload, static_cast<uint32_t>(n));
        for (size_t i = 0; i < n; ++i) {
            auto c = wire::itemAt<wire::ColorItem>(reply, i);
            out.emplace_back(c.rgb[0], c.rgb[1], c.rgb[2]);
        }
    }
    return out;
}

std::vector<DirectionSample> RemoteMeasurer::sampleDirections(SamplingFunction f, float exponent,
                                                              std::vector<RtFloat2> const& xi) {
    std::vector<DirectionSample> out;
    std::string params = wire::samplingParams(f, exponent);
    for (size_t first = 0; first < xi.size(); first += kBatch) {
        size_t n = std::min(kBatch, xi.size() - first);
        std::vector<char> payload;
        for (size_t i = first; i < first + n; ++i) wire::append(payload, wire::SamplingItem{{xi[i].x, xi[i].y}});
        auto reply = exchange(Op::SampleDirections, params, static_cast<uint32_t>(n), payload, static_cast<uint32_t>(n));
        for (size_t i = 0; i < n; ++i) {
            auto d = wire::itemAt<wire::DirectionItem>(reply, i);
            out.push_back({Vec3(d.w[0], d.w[1], d.w[2]), d.pdf});
        }
    }
    return out;
}

std::vector<float> RemoteMeasurer::directionPdfs(SamplingFunction f, float exponent, std::vector<Vec3> const& w) {
    std::vector<float> out;
    std::string params = wire::samplingParams(f, exponent);
    for (size_t first = 0; first < w.size(); first += kBatch) {
        size_t n = std::min(kBatch, w.size() - first);
        std::vector<char> payload;
        for (size_t i = first; i < first + n; ++i) wire::append(payload, wire::Vec3Item{{w[i].x, w[i].y, w[i].z}});
        auto reply = exchange(Op::DirectionPdfs, params, static_cast<uint32_t>(n), payload, static_cast<uint32_t>(n));
        for (size_t i = 0; i < n; ++i) out.push_back(wire::itemAt<wire::FloatItem>(reply, i).value);
    }
    return out;
}

}  // namespace rixgrade
