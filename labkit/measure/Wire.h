// The fixed binary format in which the autograder asks a sandboxed
// rixmeasure process for measurements, and gets them back. Both sides are
// built from this header; the asking side checks every size and count
// before it believes anything (the answering side runs student code).
//
// A request:  RequestHeader, `paramsBytes` of RIB parameter text, then
//             `count` items of the op's request type.
// The answer stream: any number of CallRecords (the plugin function about to
//             run, so a crash can be blamed on it), then one ReplyHeader and
//             `count` items of the op's reply type -- or, when status is not
//             0, `count` bytes of error message.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "measure/BxdfMeasurer.h"

namespace bxdflab::wire {

constexpr uint32_t kRequestMagic = 0x51584d52u;  // "RMXQ"
constexpr uint32_t kReplyMagic = 0x52584d52u;    // "RMXR"
constexpr uint32_t kCallMagic = 0x43584d52u;     // "RMXC"
constexpr uint32_t kMaxItems = 1u << 21;         ///< per request; bigger batches are split by the asker
constexpr uint32_t kMaxParamsBytes = 16384;
constexpr uint32_t kMaxMessageBytes = 4096;
constexpr uint32_t kMaxCallNameBytes = 256;

enum class Op : uint32_t {
    Lobes = 1,             ///< count 1, request item: none; reply: LobesItem
    Evaluate = 2,          ///< EvaluateItem -> ResultItem
    Generate = 3,          ///< GenerateItem -> ResultItem
    EvaluateAtIndex = 4,   ///< first item a PointItem, then count L vectors (Vec3Item) -> ResultItem
    Emission = 5,          ///< PointItem -> ColorItem
    SampleDirections = 6,  ///< SamplingItem (xi) -> DirectionItem; params: "function exponent"
    DirectionPdfs = 7,     ///< Vec3Item -> FloatItem; params: "function exponent"
};

struct RequestHeader {
    uint32_t magic, op, count, paramsBytes;
};
struct ReplyHeader {
    uint32_t magic, op, count, status;  ///< status 0: count items follow; else count message bytes
};
constexpr uint32_t kErrorThrown = 1u;   ///< status: the plugin or the probe threw (the message says what)
constexpr uint32_t kErrorOverran = 2u;  ///< status: the plugin wrote past the end of an array it was given
struct CallRecord {
    uint32_t magic, length;  ///< then `length` bytes naming the call
};

struct PointItem {
    float N[3], Ng[3], dPdu[3], V[3];
    uint32_t wantsLobes;
};
struct Vec3Item {
    float v[3];
};
struct EvaluateItem {
    PointItem point;
    float L[3];
};
struct GenerateItem {
    PointItem point;
    uint32_t patternid, sampleid;
    float fixedValue, fixedValue2, fixedValue1D;
};
struct ResultItem {
    float L[3], W[3], FPdf, RPdf;
    uint32_t valid;  ///< bit 0: valid, bit 1: discrete
};
struct ColorItem {
    float rgb[3];
};
struct LobesItem {
    uint32_t bits;
};
struct SamplingItem {
    float xi[2];
};
struct DirectionItem {
    float w[3], pdf;
};
struct FloatItem {
    float value;
};

/// Bytes of one request item and one reply item for each op.
size_t requestItemBytes(Op op);
size_t replyItemBytes(Op op);
bool knownOp(uint32_t op);

PointItem toWire(ProbePoint const& p);
ProbePoint fromWire(PointItem const& p);
ProbeResult fromWire(ResultItem const& r);
ResultItem toWire(ProbeResult const& r);

/// Appends a plain struct's bytes.
template <typename T> void append(std::vector<char>& out, T const& item) {
    char const* bytes = reinterpret_cast<char const*>(&item);
    out.insert(out.end(), bytes, bytes + sizeof(T));
}
/// Reads item i of a byte array of T.
template <typename T> T itemAt(std::vector<char> const& bytes, size_t i) {
    T item;
    std::memcpy(&item, bytes.data() + i * sizeof(T), sizeof(T));
    return item;
}

/// "function exponent": the params of the sampling ops.
std::string samplingParams(SamplingFunction f, float exponent);
bool parseSamplingParams(std::string const& text, SamplingFunction& f, float& exponent);

/// Answers requests read from `in` with replies written to `out` until `in`
/// ends, using `measurer` (the plugin loaded in this process). Call records
/// are written through announceCall, which the measurer's probe calls.
void serve(int in, int out, BxdfMeasurer& measurer);

/// For both ends of the wire: measurements come in batches of megabytes,
/// allocated and freed again and again; kept on the heap (not mapped and
/// unmapped each time) they cost no page faults. Call once, first thing in main.
void keepBatchBuffersOnHeap();
/// Writes a call record to the reply stream `serve` is using (for the probe's call observer).
void announceCall(char const* call);

}  // namespace bxdflab::wire
