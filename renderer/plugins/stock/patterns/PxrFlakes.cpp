// PxrFlakes — the glints of metallic paint: small flat flakes scattered through the surface, each tilted its
// own way. Space is cut into cells of 1 / flakeFreq object units (or, with a connected manifold, of (s, t));
// each cell holds a flake with probability `density` (0 to 1), centred `jitter` of the way from the cell's
// middle to a random place in it, of diameter `size` cells. Where a point lies in a flake, resultN is the
// surface's normal (or a connected inputNormal) tilted by flakeAmount toward the flake's own random direction
// and resultA is 1; elsewhere resultN is that normal and resultA 0. `octaves` layers of ever finer flakes
// (each at twice the frequency of the one before) lie on top of each other, the finest first. With
// validateNormals a tilted normal that would face away from the viewer is turned back just enough to face it.
// Feed resultN to a Bxdf's bumpNormal:
//   Pattern "PxrFlakes" "flakes" "float flakeFreq" [2500] "float size" [0.9]
//   Bxdf "PxrSurface" "paint" "reference normal bumpNormal" ["flakes:resultN"]
// The flakes are this renderer's own: RenderMan's pattern in kind, not value for value.
#include <algorithm>
#include <cmath>

#include "BentNormals.h"
#include "NoiseLattice.h"

namespace {

/// The flake of the cells around q that q lies in (the nearest such centre), as its hash; false if none.
bool flakeAt(RtPoint3 const& q, bool flat, float density, float jitter, float radius, uint32_t& found) {
    float const cx = std::floor(q.x), cy = std::floor(q.y), cz = std::floor(q.z);
    float nearest = radius;
    bool any = false;
    int const layers = flat ? 0 : 1;
    for (int dz = -layers; dz <= layers; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                int const x = static_cast<int>(cx) + dx, y = static_cast<int>(cy) + dy, z = static_cast<int>(cz) + dz;
                uint32_t h = stockpatterns::latticeHash(x, y, z);
                if (stockpatterns::unitOf(h) >= density) continue;  // this cell has no flake
                float centre[3];
                for (float& c : centre) {
                    h = stockpatterns::nextHash(h);
                    c = 0.5f + jitter * (stockpatterns::unitOf(h) - 0.5f);
                }
                float const ex = static_cast<float>(x) + centre[0] - q.x, ey = static_cast<float>(y) + centre[1] - q.y,
                            ez = flat ? 0.0f : static_cast<float>(z) + centre[2] - q.z;
                float const d = std::sqrt(ex * ex + ey * ey + ez * ez);
                if (d < nearest) {
                    nearest = d;
                    found = stockpatterns::nextHash(h);
                    any = true;
                }
            }
    return any;
}

/// A flake's own direction: a random unit vector drawn from its hash.
RtVector3 flakeDirection(uint32_t h) {
    float const z = 2.0f * stockpatterns::unitOf(h) - 1.0f;
    float const phi = 6.2831853f * stockpatterns::unitOf(stockpatterns::nextHash(h));
    float const r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return RtVector3(r * std::cos(phi), r * std::sin(phi), z);
}

class PxrFlakes : public stockpatterns::StockPattern {
public:
    enum { k_inputNormal, k_flakeAmount, k_flakeFreq, k_density, k_size, k_octaves, k_jitter, k_validateNormals,
           k_manifold, k_resultN, k_resultA };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {RixSCParamInfo(RtUString("inputNormal"), k_RixSCNormal),
                                         RixSCParamInfo(RtUString("flakeAmount"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("flakeFreq"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("density"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("size"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("octaves"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("jitter"), k_RixSCFloat),
                                         RixSCParamInfo(RtUString("validateNormals"), k_RixSCInteger),
                                         RixSCParamInfo(RtUString("manifold"), k_RixSCPoint),
                                         RixSCParamInfo(RtUString("resultN"), k_RixSCNormal, k_RixSCOutput),
                                         RixSCParamInfo(RtUString("resultA"), k_RixSCFloat, k_RixSCOutput),
                                         RixSCParamInfo()};
        return table;
    }

    int ComputeOutputParams(RixShadingContext const* sCtx, RtInt* numOutputs, OutputSpecification** outputs,
                            RtPointer, RixSCParamInfo const*) override {
        RtFloat const half = 0.5f, frequencyDefault = 57.3f, one = 1.0f, threeQuarters = 0.75f;
        RtInt const oneOctave = 1, off = 0;
        RtFloat const *amount, *frequency, *density, *size, *jitter;
        RtInt const *octaves, *validate;
        sCtx->EvalParam(k_flakeAmount, -1, &amount, &half, true);
        sCtx->EvalParam(k_flakeFreq, -1, &frequency, &frequencyDefault, true);
        sCtx->EvalParam(k_density, -1, &density, &one, true);
        sCtx->EvalParam(k_size, -1, &size, &one, true);
        sCtx->EvalParam(k_octaves, -1, &octaves, &oneOctave);
        sCtx->EvalParam(k_jitter, -1, &jitter, &threeQuarters, true);
        sCtx->EvalParam(k_validateNormals, -1, &validate, &off);
        RtNormal3 const *Nn, *input = nullptr;
        RtVector3 const* Vn;
        sCtx->GetBuiltinVar(RixShadingContext::k_Nn, &Nn);
        sCtx->GetBuiltinVar(RixShadingContext::k_Vn, &Vn);
        RtNormal3 const zero(0.0f);
        if (sCtx->EvalParam(k_inputNormal, -1, &input, &zero, true) == k_RixSCInvalidDetail) input = nullptr;
        // A manifold connected: flakes of its (s, t); else of object space, so they stay on a moving object.
        bool const flat = stockpatterns::isConnected(sCtx, k_manifold);
        RtPoint3 const* where = stockpatterns::noisePositions(sCtx, flat ? 0 : 1, k_manifold);
        int const layers = std::clamp(*octaves, 1, 8);

        RixShadingContext::Allocator pool(sCtx);
        OutputSpecification* out = pool.AllocForPattern<OutputSpecification>(2);
        int count = 0;
        RtNormal3* resultN = stockpatterns::addVaryingOutput<RtNormal3>(sCtx, out, count, k_resultN);
        RtFloat* resultA = stockpatterns::addVaryingOutput<RtFloat>(sCtx, out, count, k_resultA);
        for (int i = 0; i < sCtx->numPts; ++i) {
            RtNormal3 const base = input && !input[i].IsZero() ? RtNormal3(Normalize(input[i])) : Nn[i];
            resultN[i] = base;
            resultA[i] = 0.0f;
            float const d = std::clamp(density[i], 0.0f, 1.0f), j = std::clamp(jitter[i], 0.0f, 1.0f);
            float const radius = 0.5f * std::max(size[i], 0.0f);
            uint32_t flake = 0;
            // The finest layer first: it lies on top.
            for (int layer = layers - 1; layer >= 0; --layer) {
                float const f = frequency[i] * static_cast<float>(1 << layer);
                RtPoint3 q = where[i] * f;
                q.x += 17.0f * static_cast<float>(layer);  // each layer its own flakes
                if (!flakeAt(q, flat, d, j, radius, flake)) continue;
                RtVector3 const dir = flakeDirection(flake);
                RtVector3 const tangential = dir - base * base.Dot(dir);
                RtNormal3 n = Normalize(base + tangential * amount[i]);
                if (*validate) n = stockpatterns::facingViewer(n, Nn[i], Vn[i]);
                resultN[i] = n;
                resultA[i] = 1.0f;
                break;
            }
        }
        *numOutputs = count;
        *outputs = out;
        return 0;
    }
};

}  // namespace

STOCK_PATTERN_PLUGIN(PxrFlakes)
