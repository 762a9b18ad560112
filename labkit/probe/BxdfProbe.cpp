#include "probe/BxdfProbe.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>

#include "RixBxdfScratch.h"
#include "scene/SceneBuilder.h"
#include "shade/BxdfInstance.h"
#include "shade/BatchMemory.h"
#include "shade/MemoryArena.h"
#include "shade/PluginLoader.h"
#include "shade/PluginSearchPath.h"
#include "shade/ShadingContextImpl.h"

namespace bxdflab {
namespace {

/// What memory a plugin has not written holds while the probe runs it: 0xFF bytes
/// make a NaN of every float and a pointer no process can read.
constexpr unsigned char kPoisonByte = 0xFF;

/// Fills the stack below the caller with kPoisonByte. Called just before a plugin
/// function, at the same depth, it leaves the poison where that function's
/// locals will be: a local it reads before setting (a parameter EvalParam never
/// filled) then holds NaN or a pointer that crashes, not the value a call before
/// it happened to leave there, which is often the right one.
[[gnu::noinline]] void poisonStack() {
    unsigned char area[16 * 1024];
    std::memset(area, kPoisonByte, sizeof area);
    asm volatile("" : : "r"(area) : "memory");  // the writes are kept although nothing reads them
}

/// A RixShadingContext whose builtins are the hand-made probe points.
/// Every block it hands out (the arrays a Bxdf is given, its lobe weights,
/// the Bxdf object itself) holds kPoisonByte until written, so that a member
/// or an array read before it is set fails the checks instead of finding what
/// the last batch left, and is followed by a guard band of known bytes, so
/// that a write past the end of one -- a loop that runs to i <= numPts -- is
/// seen instead of silently damaging the next array.
class ProbeShadingContext final : public RixShadingContext {
public:
    ProbeShadingContext(BxdfInstance const& material, std::vector<ProbePoint> const& points, MemoryArena& arena,
                        RixInterface* messages, std::optional<int> firstShare, bool coloursOnly)
        : m_material(material), m_memory(arena), m_messages(messages), m_firstShare(firstShare),
          m_coloursOnly(coloursOnly) {
        numPts = static_cast<int>(points.size());
        auto n = static_cast<size_t>(numPts);
        auto* P = arena.allocArray<RtPoint3>(n);
        auto* Nn = arena.allocArray<RtNormal3>(n);
        auto* Ngn = arena.allocArray<RtNormal3>(n);
        auto* Tn = arena.allocArray<RtVector3>(n);
        auto* Vn = arena.allocArray<RtVector3>(n);
        auto* dPdu = arena.allocArray<RtVector3>(n);
        auto* dPdv = arena.allocArray<RtVector3>(n);
        auto* dPdtime = arena.allocArray<RtVector3>(n);
        float* scalars[10];
        for (auto& s : scalars) s = arena.allocArray<float>(n);
        for (size_t i = 0; i < n; ++i) {
            ProbePoint const& p = points[i];
            P[i] = RtPoint3(0.0f, 0.0f, 0.0f);
            Nn[i] = toRt(p.N);
            Ngn[i] = toRt(p.Ng);
            Vn[i] = toRt(p.V);
            dPdu[i] = toRt(p.dPdu);
            dPdv[i] = toRt(glm::cross(p.N, p.dPdu));
            Tn[i] = toRt(safeNormalize(p.dPdu - p.N * glm::dot(p.N, p.dPdu)));
            dPdtime[i] = RtVector3(0.0f, 0.0f, 0.0f);
            // VLen u v du dv s t biasR PRadius time
            float values[10] = {1.0f, 0.5f, 0.5f, 0.0f, 0.0f, 0.5f, 0.5f, 0.0f, 0.0f, 0.0f};
            for (int k = 0; k < 10; ++k) scalars[k][i] = values[k];
        }
        void* table[k_numBuiltins] = {P, Nn, Ngn, Tn, Vn, scalars[0], scalars[1], scalars[2],
                                      scalars[3], scalars[4], dPdu, dPdv, scalars[5], scalars[6], scalars[7],
                                      P, scalars[8], Nn, dPdtime, scalars[9]};
        static_assert(std::size(table) == k_numBuiltins, "one entry per builtin");
        std::copy(std::begin(table), std::end(table), m_builtins);
    }
    RixInterface* GetRixInterface(RixInterfaceId id) const override {
        return id == k_RixMessages ? m_messages : nullptr;
    }

protected:
    /// Probe points lie on no geometry: they have no primvars (a fill value
    /// is all there is), except the texture coordinates every surface has,
    /// "st", which are the builtins s and t, as in the renderer.
    RixSCDetail PrimVar(RtUString const name, RixSCType wanted, void const** result, RtFloat const** radius,
                        void const* fill) const override {
        bool const st = wanted == k_RixSCFloat2 && name == RtUString("st");
        float* values = fill || st ? primvarValues(wanted, fill, numPts, m_memory) : nullptr;
        *result = values;
        if (radius) *radius = values ? primvarValues(k_RixSCFloat, nullptr, numPts, m_memory) : nullptr;
        if (!st) return k_RixSCInvalidDetail;
        for (int i = 0; i < numPts; ++i) {
            values[2 * i] = static_cast<float const*>(m_builtins[k_s])[i];
            values[2 * i + 1] = static_cast<float const*>(m_builtins[k_t])[i];
        }
        return k_RixSCVarying;
    }
    /// Probe points lie on no shape, at the world's origin: "object" space is
    /// the world too, and so is "current"; other spaces are unknown here.
    int TransformValues(TransformInterpretation, RtUString const fromSpace, RtUString const toSpace, RtFloat3*,
                        RtFloat*) const override {
        auto isWorld = [](RtUString const& space) {
            std::string const name = space.CStr() ? space.CStr() : "";
            return namesWorldSpace(name) || name == "object";
        };
        return isWorld(fromSpace) && isWorld(toSpace) ? 0 : 1;
    }
    int Builtin(BuiltinId id, RixSCType wanted, void const** result) const override {
        *result = nullptr;
        if (id < 0 || id >= k_numBuiltins) return 1;
        if (isFloatBuiltin(id) != (wanted == k_RixSCFloat)) return 1;
        *result = m_builtins[id];
        return 0;
    }
    RixSCDetail Param(int id, int arrayIndex, RixSCType wanted, size_t elementSize, void const** result,
                      void const* dflt, bool promote) const override {
        RixSCDetail detail = evalUniformParam(m_material.params(), {id, arrayIndex, wanted, elementSize, dflt, promote},
                                              result, numPts, m_memory);
        bool const scaled = wanted == k_RixSCColor || (wanted == k_RixSCFloat && !m_coloursOnly);
        bool const turned = !m_coloursOnly && (wanted == k_RixSCVector || wanted == k_RixSCNormal);
        if (!m_firstShare || !promote || !*result || !(scaled || turned)) return detail;
        size_t const floats = elementSize / sizeof(float), count = floats * static_cast<size_t>(numPts);
        auto const* same = static_cast<float const*>(*result);
        float* varied = m_memory.allocArray<float>(count);
        for (size_t k = 0; k < count; ++k) {
            float const share = BxdfProbe::varyingShare(static_cast<int>(k / floats) + *m_firstShare);
            // A direction scaled is the same direction: a vector is turned instead,
            // by adding a share of its own components taken in turn (x from y, ...).
            size_t const next = k - k % floats + (k % floats + 1) % floats;
            varied[k] = scaled ? same[k] * share : same[k] + (1.0f - share) * same[next];
        }
        *result = varied;
        return k_RixSCVarying;
    }
    int ParamInfo(int id, RixSCType* type, RixSCConnectionInfo* cinfo, int* arrayLength) const override {
        return m_material.params().describe(id, type, cinfo, arrayLength);
    }
    void* Allocate(size_t bytes, size_t alignment) const override {
        auto* block = static_cast<unsigned char*>(m_memory.allocate(bytes + kGuardBytes, alignment));
        std::memset(block, kPoisonByte, bytes);
        std::memset(block + bytes, kGuardByte, kGuardBytes);
        m_guards.push_back(block + bytes);
        return block;
    }

public:
    /// False once anything has written into a guard band.
    bool guardsIntact() const {
        return std::all_of(m_guards.begin(), m_guards.end(), [](unsigned char const* guard) {
            return std::all_of(guard, guard + kGuardBytes, [](unsigned char b) { return b == kGuardByte; });
        });
    }

private:
    static constexpr size_t kGuardBytes = 64;  // a whole colour or vector and then some, past any array
    static constexpr unsigned char kGuardByte = 0xA5;
    BxdfInstance const& m_material;
    mutable BatchMemory m_memory;
    RixInterface* m_messages;
    std::optional<int> m_firstShare;  ///< set: parameters vary per point, point 0 taking this share
    bool m_coloursOnly;               ///< only colours vary
    void* m_builtins[k_numBuiltins] = {};
    mutable std::vector<unsigned char*> m_guards;
};

/// A point facing another way than `point` (its normal along point's tangent,
/// seen head-on), put before it in a batch: a Bxdf that reads the wrong index
/// then answers with this point's normal, view and parameters.
ProbePoint decoyBeside(ProbePoint const& point) {
    Vec3 across = point.dPdu - point.N * glm::dot(point.N, point.dPdu);
    if (glm::dot(across, across) < 1e-6f)  // a degenerate tangent: any direction across N
        across = glm::cross(point.N, std::fabs(point.N.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0));
    ProbePoint decoy;
    decoy.N = decoy.Ng = decoy.V = glm::normalize(across);
    decoy.dPdu = point.N;
    return decoy;
}

}  // namespace

struct BxdfProbe::Impl {
    CallObserver observer = nullptr;
    Diagnostics& diagnostics;
    PluginLoader loader;
    Scene scene;
    std::unique_ptr<BxdfInstance> instance;
    MemoryArena arena;

    Impl(std::vector<std::string> const& searchPath, Diagnostics& d, bool searchBuiltins)
        : diagnostics(d), loader(folders(searchPath, searchBuiltins), d) {}

    static std::vector<std::string> folders(std::vector<std::string> const& first, bool searchBuiltins) {
        if (!searchBuiltins) return first;
        std::string joined;
        for (auto const& f : first) joined += f + ":";
        return pluginSearchPath({joined, {}, ""});
    }

    /// Runs `body` with a Bxdf built for `points`, then releases it. A call
    /// that wrote past the end of memory the context gave out is an error
    /// (after EndScatter, so that the Bxdf is released either way).
    template <typename Body>
    void withBxdf(std::vector<ProbePoint> const& points, Body&& body) {
        arena.reset();
        ProbeShadingContext ctx(*instance, points, arena, &instance->plugin().messages(), firstShare, coloursOnly);
        RixBxdfFactory* factory = instance->plugin().factory();
        announce("BeginScatter");
        RixBxdf* bxdf = factory->BeginScatter(&ctx, RixBXLobeTraits::All(), k_RixSCScatterQuery, nullptr,
                                              instance->instanceData());
        if (!bxdf) throw RenderError("plugin \"" + instance->plugin().name() + "\": BeginScatter returned null");
        char const* overran = ctx.guardsIntact() ? nullptr : "BeginScatter";
        body(ctx, *bxdf);
        if (!overran && !ctx.guardsIntact()) overran = lastCall;
        announce("EndScatter");
        factory->EndScatter(bxdf);
        if (!overran && !ctx.guardsIntact()) overran = "EndScatter";
        if (overran) {
            // EvaluateSamplesAtIndex's arrays hold numSamples entries, the others' numPts.
            bool const atIndex = std::string(overran) == "EvaluateSamplesAtIndex";
            throw MemoryOverrun(overran, std::string(overran) + " wrote past the end of an array " +
                                             (atIndex ? "it was given (does a loop run to s <= numSamples?)"
                                                      : "the shading context gave it (numPts is " +
                                                            std::to_string(ctx.numPts) +
                                                            " here: does a loop run to i <= numPts?)"));
        }
    }
    /// Says which plugin function is called next, and poisons the stack it will use
    /// (inlined, so that the poison lies at the depth of the call that follows).
    [[gnu::always_inline]] inline void announce(char const* call) {
        lastCall = call;
        if (observer) observer(call);
        poisonStack();
    }
    char const* lastCall = "";
    std::optional<int> firstShare;  ///< set while parameters vary per point
    bool coloursOnly = false;       ///< ...and then only the colours
};

BxdfProbe::BxdfProbe(std::string const& plugin, std::string const& ribParams, std::vector<std::string> const& searchPath,
                     Diagnostics& diagnostics, bool searchBuiltins, CallObserver observer)
    : m_impl(std::make_unique<Impl>(searchPath, diagnostics, searchBuiltins)) {
    m_impl->observer = observer;
    SceneBuilder builder(m_impl->scene, diagnostics);
    builder.readText("Bxdf \"" + plugin + "\" \"probe\" " + ribParams + "\n", "<probe parameters>");
    m_impl->announce("loading the plugin (its static initialisers, CreateRixBxdfFactory, Init, GetParamTable)");
    ShadingPlugin& loaded = m_impl->loader.bxdf(plugin);
    m_impl->announce("CreateInstanceData");
    m_impl->instance = std::make_unique<BxdfInstance>(m_impl->scene.materials.at(0), loaded, diagnostics);
    m_impl->announce("Synchronize");
    loaded.factory()->Synchronize(loaded.context(), k_RixSCRenderBegin, nullptr);
}

BxdfProbe::~BxdfProbe() {
    if (m_impl && m_impl->instance) {
        ShadingPlugin& plugin = m_impl->instance->plugin();
        m_impl->announce("Synchronize");
        plugin.factory()->Synchronize(plugin.context(), k_RixSCRenderEnd, nullptr);
        m_impl->instance.reset();
    }
}

void BxdfProbe::setCallObserver(CallObserver observer) { m_impl->observer = observer; }

void BxdfProbe::setParamsVaryPerPoint(bool vary, int firstShare, bool coloursOnly) {
    m_impl->firstShare = vary ? std::optional<int>(firstShare) : std::nullopt;
    m_impl->coloursOnly = coloursOnly;
}

float BxdfProbe::varyingShare(int i) {
    float const golden = 0.618034f;  // consecutive points spread evenly over the range
    float const phase = static_cast<float>(i) * golden;
    return 0.85f + 0.15f * (phase - std::floor(phase));
}

std::vector<ProbeResult> BxdfProbe::generate(std::vector<ProbePoint> const& points,
                                             std::vector<RixRNG::SampleCtx> samples) {
    std::vector<ProbeResult> out(points.size());
    int n = static_cast<int>(points.size());
    m_impl->withBxdf(points, [&](RixShadingContext const& ctx, RixBxdf& bxdf) {
        RixRNG rng(samples.data(), n);
        // The integrators' arrays, cleared as they clear them; unlike them, the
        // probe hands back what the Bxdf wrote as it is (a bad pdf is for the checks to judge).
        RixBxdfScratch q(ctx);
        for (int i = 0; i < n; ++i) {
            if (!points[static_cast<size_t>(i)].wantsLobes) q.lobesWanted[i] = RixBXLobeTraits();
            q.lobeSampled[i] = RixBXLobeSampled();
            q.Ln[i] = RtVector3(0.0f, 0.0f, 0.0f);
            q.FPdf[i] = q.RPdf[i] = 0.0f;
        }
        m_impl->announce("GenerateSample");
        bxdf.GenerateSample(k_RixBXDirectLighting, q.lobesWanted, &rng, q.lobeSampled, q.Ln, q.W, q.FPdf, q.RPdf);
        for (int i = 0; i < n; ++i) {
            RixBXLobeSampled const& lobe = q.lobeSampled[i];
            out[static_cast<size_t>(i)] = {toVec3(q.Ln[i]), q.W.SumAtPoint(i), q.FPdf[i], q.RPdf[i], lobe.GetValid(),
                                           lobe.GetValid() && lobe.GetDiscrete()};
        }
    });
    return out;
}

std::vector<ProbeResult> BxdfProbe::evaluate(std::vector<ProbePoint> const& points, std::vector<Vec3> const& L) {
    std::vector<ProbeResult> out(points.size());
    int n = static_cast<int>(points.size());
    m_impl->withBxdf(points, [&](RixShadingContext const& ctx, RixBxdf& bxdf) {
        auto* samples = RixShadingContext::Allocator(&ctx).AllocFor<RixRNG::SampleCtx>(n);
        RixBxdfScratch q(ctx);
        for (int i = 0; i < n; ++i) {
            if (!points[static_cast<size_t>(i)].wantsLobes) q.lobesWanted[i] = RixBXLobeTraits();
            samples[i] = {0u, static_cast<uint32_t>(i), 0, -1.0f};
            q.lobesEvaluated[i] = RixBXLobeTraits();
            q.Ln[i] = toRt(L[static_cast<size_t>(i)]);
            q.FPdf[i] = q.RPdf[i] = 0.0f;
        }
        RixRNG rng(samples, n);
        m_impl->announce("EvaluateSample");
        bxdf.EvaluateSample(k_RixBXDirectLighting, q.lobesWanted, &rng, q.lobesEvaluated, q.Ln, q.W, q.FPdf, q.RPdf);
        for (int i = 0; i < n; ++i)
            out[static_cast<size_t>(i)] = {L[static_cast<size_t>(i)], q.W.SumAtPoint(i), q.FPdf[i], q.RPdf[i],
                                           q.lobesEvaluated[i].GetValid() || q.lobesEvaluated[i].HasAny()};
    });
    return out;
}

std::vector<ProbeResult> BxdfProbe::evaluateAtIndex(ProbePoint const& point, std::vector<Vec3> const& L) {
    std::vector<ProbeResult> out(L.size());
    int n = static_cast<int>(L.size());
    m_impl->withBxdf({decoyBeside(point), point}, [&](RixShadingContext const& ctx, RixBxdf& bxdf) {
        RixShadingContext::Allocator pool(&ctx);
        RixRNG::SampleCtx samples[2] = {{0u, 0u, 0u, -1.0f}, {0u, 1u, 0u, -1.0f}};
        RixRNG rng(samples, 2);
        auto* evaluated = pool.AllocFor<RixBXLobeTraits>(n);
        auto* Ln = pool.AllocFor<RtVector3>(n);
        auto* FPdf = pool.AllocFor<float>(n);
        auto* RPdf = pool.AllocFor<float>(n);
        for (int i = 0; i < n; ++i) {
            evaluated[i] = RixBXLobeTraits();
            Ln[i] = toRt(L[static_cast<size_t>(i)]);
            FPdf[i] = RPdf[i] = 0.0f;
        }
        RixBXLobeWeights W(n, &ctx);
        m_impl->announce("EvaluateSamplesAtIndex");
        bxdf.EvaluateSamplesAtIndex(k_RixBXDirectLighting, RixBXLobeTraits::All(), &rng, 1, n, evaluated, Ln, W, FPdf, RPdf);
        for (int i = 0; i < n; ++i)
            out[static_cast<size_t>(i)] = {L[static_cast<size_t>(i)], W.SumAtPoint(i), FPdf[i], RPdf[i],
                                           evaluated[i].GetValid() || evaluated[i].HasAny()};
    });
    return out;
}

std::vector<RtColorRGB> BxdfProbe::emission(std::vector<ProbePoint> const& points) {
    std::vector<RtColorRGB> out(points.size(), RtColorRGB(0.0f));
    m_impl->withBxdf(points, [&](RixShadingContext const& ctx, RixBxdf& bxdf) {
        auto* emitted = RixShadingContext::Allocator(&ctx).AllocFor<RtColorRGB>(ctx.numPts);
        for (int i = 0; i < ctx.numPts; ++i) emitted[i] = RtColorRGB(0.0f);
        m_impl->announce("EmitLocal");
        if (bxdf.EmitLocal(emitted)) std::copy(emitted, emitted + ctx.numPts, out.begin());
    });
    return out;
}

RixBXLobeTraits BxdfProbe::lobes() {
    RixBXLobeTraits traits;
    m_impl->withBxdf({ProbePoint{}}, [&](RixShadingContext const&, RixBxdf& bxdf) {
        m_impl->announce("GetAggregateLobeTraits");
        traits = bxdf.GetAllLobeTraits();
    });
    return traits;
}

}  // namespace bxdflab
