#include "measure/Wire.h"

#include <malloc.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <mutex>
#include <sstream>

namespace bxdflab::wire {

size_t requestItemBytes(Op op) {
    switch (op) {
        case Op::Lobes: return 0;
        case Op::Evaluate: return sizeof(EvaluateItem);
        case Op::Generate: return sizeof(GenerateItem);
        case Op::EvaluateAtIndex: return sizeof(Vec3Item);  // after one PointItem
        case Op::Emission: return sizeof(PointItem);
        case Op::SampleDirections: return sizeof(SamplingItem);
        case Op::DirectionPdfs: return sizeof(Vec3Item);
    }
    return 0;
}

size_t replyItemBytes(Op op) {
    switch (op) {
        case Op::Lobes: return sizeof(LobesItem);
        case Op::Evaluate:
        case Op::Generate:
        case Op::EvaluateAtIndex: return sizeof(ResultItem);
        case Op::Emission: return sizeof(ColorItem);
        case Op::SampleDirections: return sizeof(DirectionItem);
        case Op::DirectionPdfs: return sizeof(FloatItem);
    }
    return 0;
}

bool knownOp(uint32_t op) { return op >= static_cast<uint32_t>(Op::Lobes) && op <= static_cast<uint32_t>(Op::DirectionPdfs); }

PointItem toWire(ProbePoint const& p) {
    PointItem w;
    for (int k = 0; k < 3; ++k) {
        w.N[k] = p.N[k];
        w.Ng[k] = p.Ng[k];
        w.dPdu[k] = p.dPdu[k];
        w.V[k] = p.V[k];
    }
    w.wantsLobes = p.wantsLobes ? 1u : 0u;
    return w;
}

ProbePoint fromWire(PointItem const& w) {
    ProbePoint p;
    p.N = Vec3(w.N[0], w.N[1], w.N[2]);
    p.Ng = Vec3(w.Ng[0], w.Ng[1], w.Ng[2]);
    p.dPdu = Vec3(w.dPdu[0], w.dPdu[1], w.dPdu[2]);
    p.V = Vec3(w.V[0], w.V[1], w.V[2]);
    p.wantsLobes = w.wantsLobes != 0;
    return p;
}

ResultItem toWire(ProbeResult const& r) {
    ResultItem w;
    for (int k = 0; k < 3; ++k) {
        w.L[k] = r.L[k];
        w.W[k] = r.W[k];
    }
    w.FPdf = r.FPdf;
    w.RPdf = r.RPdf;
    w.valid = (r.valid ? 1u : 0u) | (r.discrete ? 2u : 0u);
    return w;
}

ProbeResult fromWire(ResultItem const& w) {
    ProbeResult r;
    r.L = Vec3(w.L[0], w.L[1], w.L[2]);
    r.W = RtColorRGB(w.W[0], w.W[1], w.W[2]);
    r.FPdf = w.FPdf;
    r.RPdf = w.RPdf;
    r.valid = (w.valid & 1u) != 0;
    r.discrete = (w.valid & 2u) != 0;
    return r;
}

std::string samplingParams(SamplingFunction f, float exponent) {
    char text[64];
    std::snprintf(text, sizeof text, "%d %.9g", static_cast<int>(f), static_cast<double>(exponent));
    return text;
}

bool parseSamplingParams(std::string const& text, SamplingFunction& f, float& exponent) {
    std::istringstream in(text);
    int number = -1;
    if (!(in >> number >> exponent) || number < 0 || number > 2) return false;
    f = static_cast<SamplingFunction>(number);
    return true;
}

namespace {

int g_replyFd = -1;

bool readAll(int fd, void* buffer, size_t bytes) {
    char* p = static_cast<char*>(buffer);
    while (bytes > 0) {
        ssize_t n = read(fd, p, bytes);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n;
        bytes -= static_cast<size_t>(n);
    }
    return true;
}

bool writeAll(int fd, void const* buffer, size_t bytes) {
    char const* p = static_cast<char const*>(buffer);
    while (bytes > 0) {
        ssize_t n = write(fd, p, bytes);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n;
        bytes -= static_cast<size_t>(n);
    }
    return true;
}

void replyError(int out, Op op, std::string message, uint32_t error) {
    if (message.size() > kMaxMessageBytes) message.resize(kMaxMessageBytes);
    ReplyHeader header{kReplyMagic, static_cast<uint32_t>(op), static_cast<uint32_t>(message.size()), error};
    writeAll(out, &header, sizeof header);
    writeAll(out, message.data(), message.size());
}

template <typename T> std::vector<T> items(std::vector<char> const& bytes, size_t first, size_t count) {
    std::vector<T> out(count);
    if (count) std::memcpy(out.data(), bytes.data() + first, count * sizeof(T));
    return out;
}

/// Runs one request; returns the reply items' bytes.
std::vector<char> answer(Op op, std::string const& params, uint32_t count, std::vector<char> const& payload,
                         BxdfMeasurer& m) {
    std::vector<char> out;
    switch (op) {
        case Op::Lobes: append(out, LobesItem{m.lobes(params).GetBits()}); break;
        case Op::Evaluate: {
            std::vector<ProbePoint> points;
            std::vector<Vec3> L;
            for (auto const& item : items<EvaluateItem>(payload, 0, count)) {
                points.push_back(fromWire(item.point));
                L.emplace_back(item.L[0], item.L[1], item.L[2]);
            }
            for (auto const& r : m.evaluate(params, points, L)) append(out, toWire(r));
            break;
        }
        case Op::Generate: {
            std::vector<ProbePoint> points;
            std::vector<SampleSpec> samples;
            for (auto const& item : items<GenerateItem>(payload, 0, count)) {
                points.push_back(fromWire(item.point));
                samples.push_back({item.patternid, item.sampleid, 0u, item.fixedValue, item.fixedValue2,
                                   item.fixedValue1D});
            }
            for (auto const& r : m.generate(params, points, samples)) append(out, toWire(r));
            break;
        }
        case Op::EvaluateAtIndex: {
            ProbePoint point = fromWire(itemAt<PointItem>(payload, 0));
            std::vector<Vec3> L;
            for (auto const& item : items<Vec3Item>(payload, sizeof(PointItem), count))
                L.emplace_back(item.v[0], item.v[1], item.v[2]);
            for (auto const& r : m.evaluateAtIndex(params, point, L)) append(out, toWire(r));
            break;
        }
        case Op::Emission: {
            std::vector<ProbePoint> points;
            for (auto const& item : items<PointItem>(payload, 0, count)) points.push_back(fromWire(item));
            for (auto const& c : m.emission(params, points)) append(out, ColorItem{{c.r, c.g, c.b}});
            break;
        }
        case Op::SampleDirections:
        case Op::DirectionPdfs: {
            SamplingFunction f;
            float exponent;
            if (!parseSamplingParams(params, f, exponent)) throw std::runtime_error("bad sampling parameters");
            if (op == Op::SampleDirections) {
                std::vector<RtFloat2> xi;
                for (auto const& item : items<SamplingItem>(payload, 0, count)) xi.emplace_back(item.xi[0], item.xi[1]);
                for (auto const& d : m.sampleDirections(f, exponent, xi))
                    append(out, DirectionItem{{d.w.x, d.w.y, d.w.z}, d.pdf});
            } else {
                std::vector<Vec3> w;
                for (auto const& item : items<Vec3Item>(payload, 0, count)) w.emplace_back(item.v[0], item.v[1], item.v[2]);
                for (float pdf : m.directionPdfs(f, exponent, w)) append(out, FloatItem{pdf});
            }
            break;
        }
    }
    return out;
}

}  // namespace

void announceCall(char const* call) {
    if (g_replyFd < 0) return;
    static std::mutex writing;  // two threads may ask at once (askedTogether): one record at a time
    std::lock_guard<std::mutex> guard(writing);
    size_t length = std::min<size_t>(std::strlen(call), kMaxCallNameBytes);
    CallRecord record{kCallMagic, static_cast<uint32_t>(length)};
    writeAll(g_replyFd, &record, sizeof record);
    writeAll(g_replyFd, call, length);
}

void serve(int in, int out, BxdfMeasurer& measurer) {
    g_replyFd = out;
    for (;;) {
        RequestHeader header;
        if (!readAll(in, &header, sizeof header)) return;  // the asker is done
        if (header.magic != kRequestMagic || !knownOp(header.op) || header.count > kMaxItems ||
            header.paramsBytes > kMaxParamsBytes)
            return;  // not a request of ours: stop rather than guess
        Op op = static_cast<Op>(header.op);
        std::string params(header.paramsBytes, '\0');
        size_t payloadBytes = header.count * requestItemBytes(op) + (op == Op::EvaluateAtIndex ? sizeof(PointItem) : 0);
        std::vector<char> payload(payloadBytes);
        if (!readAll(in, params.data(), params.size()) || !readAll(in, payload.data(), payload.size())) return;
        std::vector<char> reply;
        try {
            reply = answer(op, params, header.count, payload, measurer);
        } catch (MeasurementError const& e) {
            bool const overran = e.kind() == MeasurementError::Kind::Overran;
            replyError(out, op, e.what(), overran ? kErrorOverran : kErrorThrown);
            continue;
        } catch (std::exception const& e) {
            replyError(out, op, e.what(), kErrorThrown);
            continue;
        }
        uint32_t replyCount = static_cast<uint32_t>(reply.size() / replyItemBytes(op));
        ReplyHeader done{kReplyMagic, header.op, replyCount, 0u};
        if (!writeAll(out, &done, sizeof done) || !writeAll(out, reply.data(), reply.size())) return;
    }
}

void keepBatchBuffersOnHeap() {
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
}

}  // namespace bxdflab::wire
