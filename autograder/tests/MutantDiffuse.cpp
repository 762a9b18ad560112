// A Lambertian Bxdf built many times, each with one planted change, to test
// the autograder itself. MUTATION selects what is planted:
//   mutants (must fail, on the named check):
//     1 pdf twice too large (normalisation)        -> values, chi2
//     2 uniform pdf while sampling cosine           -> values, chi2, consistency
//     3 N.V instead of N.L in W                     -> values, reciprocity
//     4 missing 1/pi in W                           -> values, energy
//     5 samples below the horizon marked valid      -> chi2
//     6 NaN at grazing angles                       -> hardcases
//     7 samples never set valid                     -> chi2 (no valid samples)
//     8 RPdf = FPdf                                 -> values, reciprocity
//     9 negative pdf at grazing angles              -> hardcases
//    10 albedo squared                              -> values (a white albedo hides it)
//    11 RPdf left at zero                           -> values, reciprocity
//    12 no forward-facing normal (V below breaks)   -> hardcases, values
//   variants (must pass every check):
//     101 uniform sampling with its own (correct) pdf: passes all but values (its pdfs differ by design)
//     102 one extra random number drawn first (different RNG consumption)
//     103 the same formula written another way
//     104 cosine directions by a different mapping (Shirley-Chiu disk, then lift)
//   hostile (grading must survive and report):
//     201 segfault in GenerateSample   202 abort   203 endless loop   204 huge allocation
//     205 throws an exception           206 floods stdout (contained: output is capped)
//     207 a fork bomb (bounded to 64 sleeping children, in case containment ever failed)
//     208 tries to change files outside its scratch folder: the folder named by
//         $RIXGRADE_TEST_OUTSIDE and its own plugin folder; then works correctly
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <new>
#include <stdexcept>
#include <vector>

#include "RixBxdf.h"
#include "RixShadingUtils.h"

#ifndef MUTATION
#define MUTATION 0
#endif

namespace {

RixBXLobeSampled g_lobe;
RixBXLobeTraits g_traits;

class Mutant : public RixBxdf {
public:
    Mutant(RixShadingContext const* sc, RixBxdfFactory* f, RtColorRGB const* albedo) : RixBxdf(sc, f), m_albedo(albedo) {
        sc->GetBuiltinVar(RixShadingContext::k_Nn, &m_Nn);
        sc->GetBuiltinVar(RixShadingContext::k_Vn, &m_Vn);
    }
    RixBXEvaluateDomain GetEvaluateDomain() override { return k_RixBXReflect; }
    void GetAggregateLobeTraits(RixBXLobeTraits* t) override { *t = g_traits; }

    void GenerateSample(RixBXTransportTrait, RixBXLobeTraits const*, RixRNG* rng, RixBXLobeSampled* sampled, RtVector3* Ln,
                        RixBXLobeWeights& W, float* FPdf, float* RPdf, RtColorRGB*) override {
        hostile();
        RtColorRGB* w = W.AddActiveLobe(g_lobe);
        int n = shadingCtx->numPts;
        if (MUTATION == 102) {
            std::vector<float> extra(static_cast<size_t>(n));
            rng->DrawSamples1D(extra.data());
        }
        for (int i = 0; i < n; ++i) {
            RtNormal3 N = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i]);
            float cosTheta;
            if (MUTATION == 101) {
                RixUniformDirectionalDistribution(rng->DrawSample2D(i), N, Ln[i], cosTheta);
            } else if (MUTATION == 104) {
                RtFloat2 xi = rng->DrawSample2D(i);
                // Concentric map of the square onto the disk, lifted to the hemisphere (Malley).
                float a = 2 * xi.x - 1, b = 2 * xi.y - 1, r, phi;
                if (a == 0 && b == 0) { r = 0; phi = 0; }
                else if (std::fabs(a) > std::fabs(b)) { r = a; phi = F_PIDIV4 * (b / a); }
                else { r = b; phi = F_PIDIV2 - F_PIDIV4 * (a / b); }
                RtVector3 TX, TY;
                RixComputeShadingBasis(N, RtVector3(0, 0, 0), TX, TY);
                float x = r * std::cos(phi), y = r * std::sin(phi);
                cosTheta = std::sqrt(RixMax(0.0f, 1 - x * x - y * y));
                Ln[i] = TX * x + TY * y + N * cosTheta;
            } else
                RixCosDirectionalDistribution(rng->DrawSample2D(i), N, Ln[i], cosTheta);
            if (MUTATION == 5 && i % 4 == 0) Ln[i] = -Ln[i];
            sampled[i].SetValid(false);
            bool ok = evaluate(i, Ln[i], w[i], FPdf[i], RPdf[i]);
            if (MUTATION == 5 && i % 4 == 0) {
                FPdf[i] = RPdf[i] = 0.25f;
                w[i] = RtColorRGB(0.1f);
                ok = true;
            }
            if (!ok) continue;
            sampled[i] = g_lobe;
            sampled[i].SetValid(MUTATION != 7);
        }
    }
    void EvaluateSample(RixBXTransportTrait, RixBXLobeTraits const*, RixRNG*, RixBXLobeTraits* evaluated,
                        RtVector3 const* Ln, RixBXLobeWeights& W, float* FPdf, float* RPdf) override {
        RtColorRGB* w = W.AddActiveLobe(g_lobe);
        for (int i = 0; i < shadingCtx->numPts; ++i) {
            evaluated[i].SetNone();
            if (evaluate(i, Ln[i], w[i], FPdf[i], RPdf[i], MUTATION == 2)) {
                evaluated[i] = g_traits;
                evaluated[i].SetValid(true);
            }
        }
    }
    void EvaluateSamplesAtIndex(RixBXTransportTrait, RixBXLobeTraits const&, RixRNG*, int index, int numSamples,
                                RixBXLobeTraits* evaluated, RtVector3 const* Ln, RixBXLobeWeights& W, float* FPdf,
                                float* RPdf) override {
        RtColorRGB* w = W.AddActiveLobe(g_lobe);
        for (int s = 0; s < numSamples; ++s) {
            evaluated[s].SetNone();
            if (evaluate(index, Ln[s], w[s], FPdf[s], RPdf[s], MUTATION == 2)) {
                evaluated[s] = g_traits;
                evaluated[s].SetValid(true);
            }
        }
    }

private:
    bool evaluate(int i, RtVector3 const& L, RtColorRGB& w, float& fpdf, float& rpdf, bool uniformPdf = false) const {
        float NdV;
        RtNormal3 N = RixGetForwardFacingNormal(m_Vn[i], m_Nn[i], &NdV);
        if (MUTATION == 12) {
            N = m_Nn[i];
            NdV = N.Dot(m_Vn[i]);
        }
        float NdL = N.Dot(L);
        w = RtColorRGB(0.0f);
        fpdf = rpdf = 0.0f;
        if (MUTATION == 6 && NdL < 0.05f) {
            w = RtColorRGB(std::nanf(""));
            return true;
        }
        if (NdL <= 0.0f) return false;
        bool uniform = MUTATION == 101;
        fpdf = uniform || uniformPdf ? F_INVTWOPI : NdL * F_INVPI;
        rpdf = uniform || uniformPdf ? F_INVTWOPI : RixMax(NdV, 0.0f) * F_INVPI;
        if (MUTATION == 1) fpdf *= 2.0f;
        if (MUTATION == 8) rpdf = fpdf;
        if (MUTATION == 9 && NdL < 0.1f) fpdf = -fpdf;
        if (MUTATION == 11) rpdf = 0.0f;
        float cosine = MUTATION == 3 ? NdV : NdL;
        float scale = MUTATION == 4 ? 1.0f : F_INVPI;
        if (MUTATION == 10) scale *= m_albedo[i].g;
        w = MUTATION == 103 ? RtColorRGB(m_albedo[i].r * cosine / F_PI, m_albedo[i].g * cosine / F_PI, m_albedo[i].b * cosine / F_PI)
                            : m_albedo[i] * (cosine * scale);
        return true;
    }
    void hostile() const {
        switch (MUTATION) {
            case 201: {  // an invalid address that is not null, so UBSan's null check does not catch it first
                volatile std::uintptr_t address = 16;  // volatile: the compiler cannot see it coming
                *reinterpret_cast<volatile int*>(address) = 1;
                break;
            }
            case 202: std::abort();
            case 203: for (volatile unsigned k = 0;; k = k + 1) {}  // unsigned: wrapping is defined
            case 204: { std::vector<char> huge(static_cast<size_t>(64) << 30); huge[0] = 1; std::printf("%d", huge[0]); break; }
            case 205: throw std::runtime_error("a student's exception");
            case 206: for (int k = 0; k < 10000000; ++k) std::printf("spam spam spam spam\n"); break;
            case 207:
                for (int k = 0; k < 64; ++k) {
                    pid_t child = fork();
                    if (child == 0) {
                        pause();
                        _exit(0);
                    }
                    if (child < 0) break;
                }
                break;
            case 208: {
                static bool tried = false;
                if (tried) break;
                tried = true;
                for (const char* variable : {"RIXGRADE_TEST_OUTSIDE", "RIXCHECK_PLUGIN_DIR"})
                    if (const char* folder = std::getenv(variable)) vandalise(folder);
                break;
            }
            default: break;
        }
    }
    /// Every way of changing a folder's files a plugin might try (each should fail).
    static void vandalise(std::string const& folder) {
        std::string const canary = folder + "/canary.txt";
        if (FILE* f = std::fopen(canary.c_str(), "w")) {  // truncate and overwrite
            std::fputs("overwritten", f);
            std::fclose(f);
        }
        if (FILE* f = std::fopen(canary.c_str(), "a")) std::fclose(f);
        if (FILE* f = std::fopen((folder + "/planted.txt").c_str(), "w")) std::fclose(f);
        if (truncate(canary.c_str(), 0) == 0) std::fputs("truncated\n", stderr);
        if (unlink(canary.c_str()) == 0) std::fputs("removed\n", stderr);
        if (rename(canary.c_str(), (folder + "/moved.txt").c_str()) == 0) std::fputs("renamed\n", stderr);
        if (mkdir((folder + "/planted-folder").c_str(), 0755) == 0) std::fputs("made a folder\n", stderr);
        if (symlink("/etc/passwd", (folder + "/planted-link").c_str()) == 0) std::fputs("linked\n", stderr);
        if (chmod(canary.c_str(), 0777) == 0) std::fputs("changed a mode\n", stderr);
        if (utimensat(AT_FDCWD, canary.c_str(), nullptr, 0) == 0) std::fputs("touched\n", stderr);
    }
    RtColorRGB const* m_albedo;
    RtNormal3 const* m_Nn;
    RtVector3 const* m_Vn;
};

class MutantFactory : public RixBxdfFactory {
public:
    int Init(RixContext&, RtUString const) override { return 0; }
    void Finalize(RixContext&) override {}
    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("diffuseColor"), k_RixSCColor, k_RixSCScatterInput),
                                         RixSCParamInfo(RtUString("samplingMode"), k_RixSCInteger, k_RixSCScatterInput),
                                         RixSCParamInfo()};
        return table;
    }
    void Synchronize(RixContext& ctx, RixSCSyncMsg msg, RixParameterList const*) override {
        if (msg != k_RixSCRenderBegin) return;
        g_lobe = RixBXLookupLobeByName(ctx, false, false, true, false, 0, "Diffuse");
        g_traits = RixBXLobeTraits(g_lobe);
    }
    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const&, RixSCShadingMode, void*, RtPointer) override {
        RtColorRGB const* albedo;
        sCtx->EvalParam(0, -1, &albedo, &m_default, true);
        RixShadingContext::Allocator pool(sCtx);
        return new (pool.AllocForBxdf<Mutant>(1)) Mutant(sCtx, this, albedo);
    }
    void EndScatter(RixBxdf*) override {}

private:
    RtColorRGB m_default{0.8f, 0.8f, 0.8f};
};

}  // namespace

RIX_BXDFPLUGINCREATE {
    PIXAR_ARGUSED(hint);
    return new MutantFactory();
}
RIX_BXDFPLUGINDESTROY { delete static_cast<MutantFactory*>(bxdf); }
