// The student-facing API: value types, lobes, the RNG and RixShadingUtils.
#include <catch2/catch.hpp>

#include "shade/LobeTable.h"
#include <algorithm>
#include <cstdint>
#include <set>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include "RixBxdf.h"
#include "RixPattern.h"
#include "RixPredefinedStrings.hpp"
#include "RixShadingUtils.h"
#include "shade/BatchMemory.h"
#include "shade/MemoryArena.h"


namespace {
void checkOrthonormal(RtNormal3 const& N, RtVector3 const& TX, RtVector3 const& TY) {
    CHECK(TX.Length() == Approx(1.0f).epsilon(1e-5));
    CHECK(TY.Length() == Approx(1.0f).epsilon(1e-5));
    CHECK(TX.Dot(N) == Approx(0.0f).margin(1e-5));
    CHECK(TY.Dot(N) == Approx(0.0f).margin(1e-5));
    CHECK(TX.Dot(TY) == Approx(0.0f).margin(1e-5));
}
}  // namespace

TEST_CASE("Rt types: vector algebra, colour arithmetic, interned strings", "[api]") {
    RtVector3 a(1, 2, 3), b(4, 5, 6);
    CHECK(a.Dot(b) == 32.0f);
    RtVector3 c = a.Cross(b);
    CHECK((c.x == -3.0f && c.y == 6.0f && c.z == -3.0f));
    RtNormal3 n = 2.0f * a - b;  // vectors convert to normals and back
    CHECK(n.x == -2.0f);
    RtVector3 zero(0, 0, 0);
    zero.Normalize();
    CHECK(zero.IsZero());  // no NaN from normalising zero
    RtColorRGB red(1, 0, 0), grey(0.5f);
    RtColorRGB product = red * grey;
    CHECK(product.r == 0.5f);
    CHECK(product.g == 0.0f);
    CHECK(RtUString("diffuseColor") == RtUString(std::string("diffuseColor").c_str()));
    CHECK(RtUString("a") != RtUString("b"));
    // As a condition, a string is true when it holds text.
    CHECK(static_cast<bool>(RtUString("st")));
    CHECK_FALSE(static_cast<bool>(RtUString("")));
    CHECK_FALSE(static_cast<bool>(RtUString()));
}

TEST_CASE("scalar helpers: RixFractional repeats below zero too, angles convert both ways", "[api]") {
    CHECK(RixFractional(2.25f) == 0.25f);
    CHECK(RixFractional(-0.25f) == 0.75f);
    CHECK(RixFractional(3.0f) == 0.0f);
    CHECK(RixDegreesToRadians(180.0f) == Approx(F_PI));
    CHECK(RixRadiansToDegrees(F_PIDIV2) == Approx(90.0f));
}

TEST_CASE("RixPredefinedStrings.hpp: RenderMan's names for primvars and coordinate systems", "[api]") {
    CHECK(Rix::k_st == RtUString("st"));
    CHECK(Rix::k_Cs == RtUString("Cs"));
    CHECK(Rix::k_Pref == RtUString("__Pref"));
    CHECK(Rix::k_object == RtUString("object"));
    CHECK(Rix::k_NDC == RtUString("NDC"));
    CHECK(Rix::k_empty.Empty());
    CHECK(Rix::k_st.CStr() == RtUString("st").CStr());  // interned: the same text, once
}

namespace {
// Written as public plugins are, for RenderMan 22 (CreateInstanceData returns
// int) and 23 onwards (void) alike: prmanapi.h's version picks the branch.
class EitherVersionPattern : public RixPattern {
public:
    int Init(RixContext&, RtUString const) override { return 0; }
    void Finalize(RixContext&) override {}
    void Synchronize(RixContext&, RixSCSyncMsg, RixParameterList const*) override {}
    RixSCParamInfo const* GetParamTable() override { return nullptr; }
    int ComputeOutputParams(RixShadingContext const*, RtInt*, OutputSpec**, RtPointer,
                            RixSCParamInfo const*) override {
        return 1;
    }
#if _PRMANAPI_VERSION_MAJOR_ >= 23
    void CreateInstanceData(RixContext&, RtUString const, RixParameterList const*, InstanceData*) override {}
#else
    int CreateInstanceData(RixContext&, RtUString const, RixParameterList const*, InstanceData*) { return 0; }
#endif
};
}  // namespace

TEST_CASE("prmanapi.h: the RenderMan version the headers follow, for plugins that switch on it", "[api]") {
    CHECK(_PRMANAPI_VERSION_MAJOR_ == 24);
    CHECK(_PRMANAPI_VERSION_ == _PRMANAPI_VERSION_MAJOR_);
    CHECK(std::string(_PRMANAPI_VERSION_STR_) == "24.0");
    using Create = decltype(&EitherVersionPattern::CreateInstanceData);
    using OfThisApi = void (EitherVersionPattern::*)(RixContext&, RtUString, RixParameterList const*,
                                                      RixShadingPlugin::InstanceData*);
    CHECK(std::is_same<Create, OfThisApi>::value);  // the branch taken is the one that overrides
}

TEST_CASE("RtUString: equal text interns to one pointer, also when threads race to add it", "[api]") {
    // Four threads intern the same 2,000 names (more than the table's 256
    // lists, so lists hold several), each in its own order; every thread
    // must get the same pointer for a name, and its text must be the name.
    int const names = 2000, threads = 4;
    std::vector<std::vector<char const*>> seen(threads, std::vector<char const*>(names));
    std::vector<std::thread> workers;
    for (int t = 0; t < threads; ++t)
        workers.emplace_back([&, t] {
            for (int k = 0; k < names; ++k) {
                int i = (t % 2 == 0) ? k : names - 1 - k;
                std::string name = "param" + std::to_string(i);
                seen[t][i] = RtUString(name.c_str()).CStr();
            }
        });
    for (auto& w : workers) w.join();
    int mismatches = 0, wrongText = 0;
    std::set<char const*> distinct;
    for (int i = 0; i < names; ++i) {
        for (int t = 1; t < threads; ++t) mismatches += seen[t][i] != seen[0][i];
        wrongText += std::string(seen[0][i]) != "param" + std::to_string(i);
        distinct.insert(seen[0][i]);
    }
    CHECK(mismatches == 0);
    CHECK(wrongText == 0);
    CHECK(distinct.size() == static_cast<size_t>(names));
    // The text is copied: the RtUString outlives the buffer it was made from.
    RtUString kept;
    {
        std::string buffer = "temporary";
        kept = RtUString(buffer.c_str());
        buffer = "overwritten";
    }
    CHECK(std::string(kept.CStr()) == "temporary");
    CHECK(RtUString().CStr() == std::string());
}

TEST_CASE("lobe traits: sets of lobes combine with & and |", "[api]") {
    RixBXLobeSampled diffuse(false, false, true, false, 1, 0);
    RixBXLobeSampled specular(false, true, true, false, 2, 0);
    RixBXLobeTraits d(diffuse), s(specular);
    CHECK(d.HasAny());
    CHECK((d & s).HasAny() == false);
    CHECK(((d | s) & s).HasAny());
    CHECK((RixBXLobeTraits::All() & d) == d);
    RixBXLobeTraits none;
    CHECK_FALSE(none.HasAny());
    none.SetValid(true);
    CHECK(none.GetValid());
}

TEST_CASE("lobe weights: AddActiveLobe zeroes once and the sum covers every lobe", "[api]") {
    std::vector<RtColorRGB> storage(3 * RixBXLobeWeights::k_numSlots, RtColorRGB(7.0f));
    RixBXLobeWeights W(3, storage.data());
    RixBXLobeSampled diffuse(false, false, true, false, 1, 0), specular(false, true, true, false, 2, 3);
    RtColorRGB* wd = W.AddActiveLobe(diffuse);
    CHECK(wd[2].r == 0.0f);
    wd[1] = RtColorRGB(0.25f);
    CHECK(W.AddActiveLobe(diffuse)[1].r == 0.25f);  // not zeroed again
    W.AddActiveLobe(specular)[1] = RtColorRGB(0.5f);
    CHECK(W.GetNumActiveLobes() == 2);
    CHECK(W.SumAtPoint(1).g == 0.75f);
}

TEST_CASE("RixBXChooseLobe picks in proportion and remaps the random number", "[api]") {
    float weights[3] = {1.0f, 0.0f, 3.0f};
    float remapped, probability;
    CHECK(RixBXChooseLobe(0.1f, weights, 3, &remapped, &probability) == 0);
    CHECK(probability == Approx(0.25f));
    CHECK(remapped == Approx(0.4f));
    CHECK(RixBXChooseLobe(0.5f, weights, 3, &remapped, &probability) == 2);
    CHECK(remapped == Approx(1.0f / 3.0f));
    float none[2] = {0.0f, 0.0f};
    CHECK(RixBXChooseLobe(0.5f, none, 2) == -1);
}

TEST_CASE("RNG: deterministic, batch and per-point draws agree, stratified per pixel", "[api][rng]") {
    std::vector<RixRNG::SampleCtx> a(16), b(16);
    for (uint32_t i = 0; i < 16; ++i) a[i] = b[i] = {12345u, i, 0, -1.0f};
    RixRNG batch(a.data(), 16), single(b.data(), 16);
    std::vector<RtFloat2> xi(16);
    batch.DrawSamples2D(xi.data());
    std::set<int> cells;
    for (int i = 0; i < 16; ++i) {
        RtFloat2 one = single.DrawSample2D(i);
        CHECK(one.x == xi[static_cast<size_t>(i)].x);
        CHECK(one.y == xi[static_cast<size_t>(i)].y);
        REQUIRE(xi[static_cast<size_t>(i)].x >= 0.0f);
        REQUIRE(xi[static_cast<size_t>(i)].x < 1.0f);
        // 16 Sobol' points form a (0,2)-net: one in each cell of a 4x4 grid.
        cells.insert(static_cast<int>(xi[static_cast<size_t>(i)].x * 4) * 4 + static_cast<int>(xi[static_cast<size_t>(i)].y * 4));
    }
    CHECK(cells.size() == 16u);
    // A second draw is a new, independently scrambled set.
    RtFloat2 next = batch.DrawSample2D(0);
    CHECK(next.x != xi[0].x);
    // Another pixel gets different numbers.
    RixRNG::SampleCtx other{54321u, 0, 0, -1.0f};
    CHECK(RixRNG::Sample2D(other).x != xi[0].x);
}

TEST_CASE("RNG: fixed values, for tests that feed a sampler chosen numbers", "[api][rng]") {
    // fixedValue alone: every coordinate of every draw.
    RixRNG::SampleCtx same{7u, 3u, 0, 0.25f};
    CHECK(RixRNG::Sample1D(same) == 0.25f);
    CHECK(RixRNG::Sample2D(same).y == 0.25f);
    // fixedValue2 sets the second coordinate, fixedValue1D the 1-D draws (a
    // lobe choice apart from the direction's numbers).
    RixRNG::SampleCtx apart{7u, 3u, 0, 0.25f, 0.5f, 0.875f};
    RtFloat2 xi = RixRNG::Sample2D(apart);
    CHECK(xi.x == 0.25f);
    CHECK(xi.y == 0.5f);
    CHECK(RixRNG::Sample1D(apart) == 0.875f);
    // Without fixedValue the other two are ignored.
    RixRNG::SampleCtx drawn{7u, 3u, 0, -1.0f, 0.5f, 0.875f};
    CHECK(RixRNG::Sample1D(drawn) != 0.875f);
}

TEST_CASE("RNG: the first 2^m samples of a pixel are a (0,m,2)-net for every shape of cell", "[api][rng]") {
    // Scrambled Sobol' points in two dimensions: every box [i/2^a, (i+1)/2^a) x
    // [j/2^(m-a), (j+1)/2^(m-a)) holds exactly one of the first 2^m samples,
    // for every split a. A wrong second dimension breaks this at some (m, a).
    for (uint32_t pixel : {7u, 12345u, 0xdeadbeefu})
        for (int m = 1; m <= 12; ++m) {
            uint32_t const n = 1u << m;
            std::vector<RtFloat2> xi(n);
            for (uint32_t i = 0; i < n; ++i) {
                RixRNG::SampleCtx ctx{pixel, i, 0, -1.0f};
                xi[i] = RixRNG::Sample2D(ctx);
            }
            for (int a = 0; a <= m; ++a) {
                std::set<uint32_t> boxes;
                for (RtFloat2 const& p : xi)
                    boxes.insert((static_cast<uint32_t>(p.x * static_cast<float>(1u << a)) << (m - a)) |
                                 static_cast<uint32_t>(p.y * static_cast<float>(1u << (m - a))));
                INFO("pixel " << pixel << ", m " << m << ", a " << a);
                CHECK(boxes.size() == n);
            }
        }
}

TEST_CASE("shading basis is orthonormal for any tangent, including degenerate ones", "[api][hard]") {
    RtNormal3 N(0.0f, 0.6f, 0.8f);
    RtVector3 TX, TY;
    auto tangent = GENERATE(RtVector3(1, 0, 0), RtVector3(0, 0, 0), RtVector3(0, 3, 4), RtVector3(5, 0, 0),
                            RtVector3(0, 0.6f, 0.8f + 1e-7f));
    RixComputeShadingBasis(N, tangent, TX, TY);
    checkOrthonormal(N, TX, TY);
    RtNormal3 down(0, 0, -1);
    RixComputeShadingBasis(down, tangent, TX, TY);
    checkOrthonormal(down, TX, TY);
}

TEST_CASE("CreateOrthonormalBasis: a right-handed frame around any unit vector, the poles included", "[api][hard]") {
    // RenderMan's RtFloat3 member, which studio Bxdfs sample around the normal with.
    auto n = GENERATE(RtNormal3(0, 0, 1), RtNormal3(0, 0, -1), RtNormal3(0.0f, 0.6f, 0.8f), RtNormal3(1, 0, 0),
                      RtNormal3(0.0f, 1e-4f, -1.0f), RtNormal3(-0.48f, 0.6f, -0.64f));
    RtNormal3 const N = Normalize(n);
    RtVector3 s, t;
    N.CreateOrthonormalBasis(s, t);
    checkOrthonormal(N, s, t);
    RtFloat3 const handed = s.Cross(t);
    CHECK(handed.Dot(N) == Approx(1.0f).margin(1e-5));
}

TEST_CASE("hemisphere samplers: unit directions above the surface, also at xi = 0 and 1 - 2^-24", "[api][hard]") {
    RtNormal3 N(0.0f, 0.0f, 1.0f);
    float const last = 1.0f - 0x1p-24f;
    for (float u : {0.0f, 0.25f, last})
        for (float v : {0.0f, 0.5f, last}) {
            RtVector3 out;
            float cosTheta;
            RixCosDirectionalDistribution(RtFloat2(u, v), N, out, cosTheta);
            CHECK(out.Length() == Approx(1.0f).epsilon(1e-5));
            CHECK(cosTheta > 0.0f);
            CHECK(out.Dot(N) == Approx(cosTheta).epsilon(1e-5));
            RixUniformDirectionalDistribution(RtFloat2(u, v), N, out, cosTheta);
            CHECK(out.Length() == Approx(1.0f).epsilon(1e-5));
            CHECK(cosTheta > 0.0f);
        }
}

TEST_CASE("samplers have the stated densities: E[cos] is 2/3 for cosine, 1/2 for uniform", "[api]") {
    // Under pdf cos/pi, E[cos] = integral of cos^2 / pi over the hemisphere = 2/3;
    // under the uniform pdf 1/(2 pi) it is 1/2. A wrong mapping moves these means.
    double cosineMean = 0.0, uniformMean = 0.0;
    const int n = 1 << 16;
    for (int i = 0; i < n; ++i) {
        RixRNG::SampleCtx ctx{99u, static_cast<uint32_t>(i), 0, -1.0f};
        RtFloat2 xi = RixRNG::Sample2D(ctx);
        RtVector3 out;
        float cosTheta;
        RixCosDirectionalDistribution(xi, RtNormal3(0, 0, 1), out, cosTheta);
        cosineMean += out.z;
        RixUniformDirectionalDistribution(xi, RtNormal3(0, 0, 1), out, cosTheta);
        uniformMean += out.z;
    }
    CHECK(cosineMean / n == Approx(2.0 / 3.0).epsilon(1e-3));
    CHECK(uniformMean / n == Approx(0.5).epsilon(1e-3));
}

TEST_CASE("Fresnel: normal incidence, grazing, and total internal reflection", "[api][hard]") {
    float Kr;
    RixFresnelDielectric(1.0f, 1.0f / 1.5f, &Kr);
    CHECK(Kr == Approx(0.04f).epsilon(1e-4));  // ((1 - 1.5) / (1 + 1.5))^2
    RixFresnelDielectric(0.0f, 1.0f / 1.5f, &Kr);
    CHECK(Kr == Approx(1.0f).epsilon(1e-4));
    RixFresnelDielectric(0.2f, 1.5f, &Kr);  // from inside glass at 78 degrees: beyond the critical angle
    CHECK(Kr == 1.0f);

    RtVector3 V = Normalize(RtVector3(0.3f, 0.0f, 1.0f));
    RtNormal3 N(0, 0, 1);
    RtVector3 R, T;
    RixFresnelDielectric(V, N, 1.0f / 1.5f, &Kr, &R, &T);
    CHECK(R.z == Approx(V.z));
    CHECK(R.x == Approx(-V.x));
    CHECK(T.z < 0.0f);  // into the surface
    CHECK(T.x < 0.0f);  // and onward, away from V's side: the eye ray -V bent, ready to trace
    CHECK(T.Length() == Approx(1.0f).epsilon(1e-5));
    // Snell: sin(theta_t) = eta sin(theta_i)
    CHECK(std::sqrt(1 - T.z * T.z) == Approx(std::sqrt(1 - V.z * V.z) / 1.5f).epsilon(1e-4));
    RtVector3 grazingInside = Normalize(RtVector3(1.0f, 0.0f, 0.1f));
    RixFresnelDielectric(grazingInside, N, 1.5f, &Kr, &R, &T);
    CHECK(Kr == 1.0f);
    CHECK(T.IsZero());
}

TEST_CASE("reflect and forward-facing normals", "[api]") {
    RtVector3 I(1, 0, -1);
    RtVector3 R = RixReflect(I, RtNormal3(0, 0, 1));
    CHECK((R.x == 1.0f && R.z == 1.0f));
    RtNormal3 N(0, 0, 1);
    float NdV;
    RtNormal3 f = RixGetForwardFacingNormal(RtVector3(0, 0, -1), N, &NdV);
    CHECK(f.z == -1.0f);
    CHECK(NdV == 1.0f);
    CHECK(RixGetBackwardFacingNormal(RtVector3(0, 0, 1), N).z == -1.0f);
}

TEST_CASE("the shading memory pool does not grow when batches repeat", "[memory]") {
    // A batch that needs more than one block, and a request larger than a block,
    // repeated many times under marks and resets: what the arena holds settles.
    bxdflab::MemoryArena arena(4096);
    auto oneBatch = [&] {
        bxdflab::MemoryArena::Mark outer = arena.mark();
        for (int k = 0; k < 5; ++k) arena.allocate(1000, 16);
        bxdflab::MemoryArena::Mark inner = arena.mark();
        arena.allocate(20000, 16);  // larger than a block
        arena.allocate(3000, 64);
        arena.release(inner);
        arena.allocate(20000, 16);
        arena.release(outer);
    };
    for (int k = 0; k < 3; ++k) oneBatch();
    arena.reset();
    size_t settled = arena.bytesHeld();
    for (int k = 0; k < 1000; ++k) {
        oneBatch();
        if (k % 10 == 0) arena.reset();
    }
    CHECK(arena.bytesHeld() <= settled);
    // A released large allocation is handed out again rather than fetched anew.
    arena.reset();
    void* first = arena.allocate(20000, 16);
    arena.reset();
    CHECK(arena.allocate(20000, 16) == first);
    // Requests that keep growing do not leave a trail of too-small spares behind.
    for (size_t size = 10000; size < 200000; size += 5000) {
        arena.reset();
        arena.allocate(size, 16);
    }
    arena.reset();
    CHECK(arena.bytesHeld() <= 4096 * 4 + 200000 + 64);
    // Memory handed out is aligned and usable.
    auto* p = static_cast<double*>(arena.allocate(sizeof(double) * 8, 64));
    CHECK(reinterpret_cast<uintptr_t>(p) % 64 == 0);
}

TEST_CASE("a shading context's memory lasts as long as the context, even when asked for inside a deeper mark",
          "[memory]") {
    bxdflab::MemoryArena arena(4096);
    bxdflab::MemoryArena::Mark batch = arena.mark();
    CHECK(arena.depth() == 1);
    bxdflab::BatchMemory context(arena);
    int* early = context.allocArray<int>(100);  // asked for at the context's own depth
    for (int k = 0; k < 100; ++k) early[k] = k;
    bxdflab::MemoryArena::Mark deeper = arena.mark();  // a bounce traced from this batch
    CHECK(arena.depth() == 2);
    int* late = context.allocArray<int>(100);  // the context asked again from inside it
    auto* bounce = static_cast<char*>(arena.allocate(64, 16));
    CHECK(reinterpret_cast<std::uintptr_t>(late) % alignof(std::max_align_t) == 0);
    for (int k = 0; k < 100; ++k) late[k] = -k;
    CHECK((bounce < reinterpret_cast<char*>(late) || bounce >= reinterpret_cast<char*>(late + 100)));
    arena.release(deeper);
    CHECK(arena.depth() == 1);
    // What the arena hands out next reuses what the deeper mark freed, and not the context's.
    for (int round = 0; round < 64; ++round) {
        auto* reused = static_cast<int*>(arena.allocate(50 * sizeof(int), 16));
        std::fill(reused, reused + 50, 7777);
    }
    bool intact = true;
    for (int k = 0; k < 100; ++k) intact = intact && early[k] == k && late[k] == -k;
    CHECK(intact);
    arena.release(batch);
    CHECK(arena.depth() == 0);
}

TEST_CASE("lobes are told apart by kind and light path expression id, as in RenderMan", "[api]") {
    // Named lookups give each name of a kind its own id, the same every time.
    bxdflab::LobeTable& table = bxdflab::LobeTable::instance();
    unsigned char specular = table.GetLpeIdByName(true, false, "Specular");
    unsigned char clearcoat = table.GetLpeIdByName(true, false, "Clearcoat");
    CHECK(specular != clearcoat);
    CHECK(table.GetLpeIdByName(true, false, "Specular") == specular);
    CHECK(table.GetLpeIdByName(false, false, "Emission") == 0);
    // Two specular lobes with their own lpeIds have their own weights; the same lpeId shares them.
    RtColorRGB storage[RixBXLobeWeights::k_numSlots * 4];
    RixBXLobeWeights W(4, storage);
    RixBXLobeSampled first(false, true, true, false, 1, 0), second(false, true, true, false, 2, 0),
        again(false, true, true, false, 1, 5);
    RtColorRGB* a = W.AddActiveLobe(first);
    RtColorRGB* b = W.AddActiveLobe(second);
    CHECK(a != b);
    CHECK(W.AddActiveLobe(again) == a);  // lobeId is the plugin's own label; lpeId decides
    CHECK(W.GetNumActiveLobes() == 2);
    CHECK((RixBXLobeTraits(first) & RixBXLobeTraits(second)).HasAny() == false);
}
