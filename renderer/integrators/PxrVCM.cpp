// PxrVCM: bidirectional path tracing (Veach 1997, ch. 10; the "vertex
// connection" half of RenderMan's vertex connection and merging).
//
// A path tracer builds every path from the camera, so light that reaches a
// diffuse surface only through a mirror or glass (a caustic) is found only when
// a Bxdf sample happens to hit the light: very noisy for small lights. Here
// each camera vertex z also gets a light subpath y0 (on a light), y1, y2, ...
// traced from the light with the Bxdfs' own sampling, and z is connected to
// every yj by a shadow ray. One full path x0 (camera) ... xk (light) can then
// be made in several ways ("strategies"), one per edge where the camera and
// light halves meet, and multiple importance sampling weights each way by the
// balance-of-squares (power) heuristic over all the ways that could have made
// it:
//     w = p_s^2 / sum_i p_i^2,
// where p_i is the density (per unit area of every vertex) of making the path
// with strategy i. Those densities need, at every vertex, the pdf of the step
// that made it (FPdf) and of the step in the opposite direction: that is what
// a Bxdf's RPdf is for. A wrong RPdf leaves every image unbiased, since the
// weights still add up to one, but puts noise where a strategy is poor.
//
// Strategies made here, for a path of surfaces x1 ... x(k-1) and light point xk:
//   s = 0   the camera path hits the light (a Bxdf sample that reaches it);
//   s = 1   next-event estimation at a camera vertex (one sample per light);
//   s >= 2  a camera vertex joined to vertex y(s-1) of a light subpath.
// Not made: light subpaths joined to the camera itself (t = 1), which would
// add to other pixels than the one being shaded, and photon merging. Lights at
// infinity (dome, distant) do not start light subpaths: paths that end on them
// weigh next-event estimation against Bxdf sampling, as PxrPathTracer does.
// Emissive surfaces (EmitLocal) add what they emit when a camera path meets them.
//
// The connection across one edge uses reciprocity: the light vertex's Bxdf is
// evaluated with its V toward the previous light vertex and L toward the camera
// vertex, which is f(L -> V) for a reciprocal Bxdf.
//
// Parameters
//   int maxPathLength  [10]  surfaces a path may visit (as PxrPathTracer); it alone bounds
//                            the paths: the objects' trace depths (Attribute "trace") are not read
//   int connectPaths   [1]   RenderMan's; connection is always on here
//   int mergePaths     [0]   RenderMan's vertex merging: not implemented (a warning if 1)
// RenderMan's others, which exporters write in full, are read so that they pass without a warning
// where they change nothing this integrator does: mergeRadius, timeRadius and photonGuiding* belong to
// merging; rouletteDepth and rouletteThreshold to Russian roulette, which changes a render's noise, not
// its mean (these paths end at maxPathLength only); specularCurvatureFilter to RenderMan's own noise
// filtering. A numLightSamples or numBxdfSamples other than 1, and a clampLuminance above 0 (clamping
// would darken bright paths; it is not done here), are warned about.
#include <climits>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "RixBxdfScratch.h"
#include "common/DirectLighting.h"
#include "common/Params.h"


using namespace bxdflab;

namespace {

/// A vertex of a subpath as the MIS weights see it.
struct PathVertex {
    RtPoint3 P;
    RtNormal3 Ng;          ///< unit geometric normal; zero for a point light (its "cosine" is 1)
    float pdfFwd = 0.0f;   ///< density (per unit area) of this vertex, made from the previous one of its subpath
    float pdfRev = 0.0f;   ///< density had it been made from the next one, from the other end
    bool delta = false;    ///< its step to the next vertex was a discrete (mirror) sample: no connection here
};

/// One depth of a subpath for every point of a batch: vertex[i] continues
/// parent->vertex[parentIndex[i]]. The root level has no parent.
struct SubpathLevel {
    PathVertex* vertex = nullptr;
    int const* parentIndex = nullptr;
    SubpathLevel const* parent = nullptr;
};

/// A light subpath vertex waiting to be joined to the camera vertex it was traced for.
struct Connection {
    bool valid = false;
    RtPoint3 P;               ///< the light vertex
    float cosine = 0.0f;      ///< |Ng . direction to the camera vertex| there
    RtColorRGB carried;       ///< light subpath throughput times the light vertex's W toward the camera vertex
    float pdfRevCamera = 0.0f;  ///< density of the camera vertex, made from the light vertex
    float lightSum = 0.0f;    ///< the light side's sum of squared ratios, over remap(p of the light vertex)^2
};

float remapZero(float pdf) { return pdf != 0.0f ? pdf : 1.0f; }

/// A solid-angle density at `from` toward `to`, per unit area at `to`.
float toArea(float pdfDir, RtPoint3 const& from, PathVertex const& to) {
    RtVector3 d = to.P - from;
    float distSq = d.LengthSq();
    if (!(distSq > 0.0f)) return 0.0f;
    float cosine = to.Ng.IsZero() ? 1.0f : std::fabs(to.Ng.Dot(d)) / std::sqrt(distSq);
    return pdfDir * cosine / distSq;
}

/// Sum of squared density ratios p_i / p_s over the strategies that would put
/// the join nearer the camera, walking the camera subpath down from vertex
/// `index` of `level` (the join vertex), whose own reverse density is revTop and
/// whose predecessor's is revNext (both depend on the join). ri starts at the
/// ratio already accumulated above the walk. The last strategy joins the first
/// surface to the camera itself (light tracing), when the camera allows it.
float cameraSideSum(SubpathLevel const* level, int index, float revTop, float revNext, bool deltaTop, float ri,
                    bool cameraJoins) {
    float sum = 0.0f;
    for (int step = 0;; ++step) {
        PathVertex const& v = level->vertex[index];
        float rev = step == 0 ? revTop : step == 1 ? revNext : v.pdfRev;
        ri *= remapZero(rev) / remapZero(v.pdfFwd);
        bool deltaHere = step == 0 ? deltaTop : v.delta;
        if (!level->parent) {
            if (!deltaHere && cameraJoins) sum += ri * ri;
            return sum;
        }
        int parentIndex = level->parentIndex[index];
        if (!deltaHere && !level->parent->vertex[parentIndex].delta) sum += ri * ri;
        level = level->parent;
        index = parentIndex;
    }
}

/// The same toward the light, walking the light subpath down from the join
/// vertex to the light point. The join vertex's own reverse density (made from
/// the camera vertex) is left out: the caller multiplies the sum by its square.
/// neeOverEmit: how much likelier next-event estimation from the first light
/// vertex finds the light point than the light subpath's start did (the ratio
/// for the strategy s = 1, whose light point is chosen by SampleLight).
float lightSideSum(SubpathLevel const* level, int index, float revNext, bool deltaLight, float neeOverEmit) {
    float sum = 0.0f, ri = 1.0f;
    for (int step = 0;; ++step) {
        PathVertex const& v = level->vertex[index];
        float rev = step == 0 ? 1.0f : step == 1 ? revNext : v.pdfRev;
        ri *= remapZero(rev) / remapZero(v.pdfFwd);
        bool deltaHere = step == 0 ? false : v.delta;
        bool deltaBelow = level->parent ? level->parent->vertex[level->parentIndex[index]].delta : deltaLight;
        bool nextEvent = level->parent && !level->parent->parent;  // joining this vertex to the light point
        if (!deltaHere && !deltaBelow) sum += nextEvent ? ri * ri * neeOverEmit * neeOverEmit : ri * ri;
        if (!level->parent) return sum;
        index = level->parentIndex[index];
        level = level->parent;
    }
}

bool finite(RtVector3 const& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

/// Where the batch's points are, as the root or next level of a subpath.
void placeVertices(RixShadingContext const& ctx, PathVertex* vertex) {
    RtPoint3 const* P;
    RtNormal3 const* Ngn;
    ctx.GetBuiltinVar(RixShadingContext::k_P, &P);
    ctx.GetBuiltinVar(RixShadingContext::k_Ngn, &Ngn);
    for (int i = 0; i < ctx.numPts; ++i) {
        vertex[i] = PathVertex();
        vertex[i].P = P[i];
        vertex[i].Ng = Ngn[i];
    }
}

class BidirectionalPathTracer : public RixIntegrator {
public:
    explicit BidirectionalPathTracer(int maxPathLength) : m_maxPathLength(maxPathLength) {}

    bool WantsLightTracing() const override { return true; }

    void DescribeEffects(int numLights, RixEffects& effects) const override {
        effects.Simulate("camera rays");
        effects.Simulate("emission (EmitLocal) at every camera path vertex");
        if (numLights == 0) {
            effects.Skip("light sampling, light subpaths and connections", "the scene has no lights");
        } else {
            effects.Simulate("light sampling (1 per light per camera vertex)");
            effects.Simulate("light subpaths from the lights at a finite distance, joined to every camera vertex");
            effects.Simulate("shadow rays");
        }
        effects.Simulate("bxdf sampling (MIS over all strategies that make a path)");
        effects.Simulate(("indirect rays (paths of up to " + std::to_string(m_maxPathLength) + " surfaces)").c_str());
        effects.Simulate("caustics");
        effects.Simulate("light subpaths joined to the camera (light tracing; perspective cameras)");
        effects.Skip("vertex merging (photon density estimation)", "bidirectional path tracing only");
    }

    void Integrate(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                   RtColorRGB* radiance) override {
        int const n = ctx.numPts;
        RixShadingContext::Allocator pool(&ctx);
        RtColorRGB* throughput = pool.AllocFor<RtColorRGB>(n);
        SubpathLevel level;
        level.vertex = pool.AllocFor<PathVertex>(n);
        placeVertices(ctx, level.vertex);
        for (int i = 0; i < n; ++i) throughput[i] = RtColorRGB(1.0f);
        Emitters emitters;
        emitters.lightTracing = ictx.CanConnectCamera();
        if (emitters.lightTracing)
            for (int i = 0; i < n; ++i) level.vertex[i].pdfFwd = ictx.ConnectCamera(ctx, i, false).pdfArea;
        for (int light = 0; light < ictx.GetNumLights(); ++light)
            if (ictx.CanEmit(light)) emitters.lights.push_back(light);
        emitters.choicePdf = emitters.lights.empty() ? 0.0f : 1.0f / static_cast<float>(emitters.lights.size());
        cameraVertex(ctx, bxdf, rng, ictx, emitters, level, throughput, radiance, 1);
    }

private:
    /// What the light subpaths of one camera batch share.
    struct LightPath {
        SubpathLevel const& camera;   ///< the camera vertices they are joined to
        Connection* joins;            ///< [cameraPoint * maxSurfaces + lightDepth - 1]
        int maxSurfaces;              ///< light vertices joined to the camera vertices
        int maxDepth;                 ///< light vertices traced
        bool lightTracing;            ///< also joined to the camera (light tracing)
        bool const* deltaLight;       ///< per camera point: its light is a point light
        int const* lightIndex;        ///< per camera point: the light its subpath starts on
        RixLightEmission const* emitted;  ///< per camera point: the ray leaving that light
        float* neeOverEmit;           ///< per camera point: see lightSideSum (set at the first light vertex)
    };

    /// The lights that start light subpaths, each chosen with probability choicePdf.
    struct Emitters {
        std::vector<int> lights;
        float choicePdf = 0.0f;
        bool lightTracing = false;  ///< light subpaths are joined to the camera too (a pinhole camera)
    };

    /// The reverse density of the camera vertex before `index` (its predecessor), made from the
    /// join vertex with solid-angle density rpdf toward it; 0 at the first surface (unused there).
    static float revOfPrevious(SubpathLevel const& level, int index, float rpdf, bool discrete) {
        if (!level.parent || discrete) return 0.0f;
        return toArea(rpdf, level.vertex[index].P, level.parent->vertex[level.parentIndex[index]]);
    }

    /// Shades one depth of the camera subpaths: throughput[i] is the path's weight so far.
    void cameraVertex(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                      Emitters const& emitters, SubpathLevel const& level, RtColorRGB const* throughput, RtColorRGB* radiance, int depth) {
        int const n = ctx.numPts;
        RixShadingContext::Allocator pool(&ctx);

        // s = 0 for emissive surfaces: nothing else can make these paths.
        if (!addEmission(ctx, bxdf, ictx, throughput, radiance)) return;

        RixBxdfScratch q(ctx);
        if (ictx.GetNumLights() > 0) lightSamples(ctx, bxdf, rng, ictx, emitters, q, level, throughput, radiance);
        // Light subpaths: joined to this vertex, and (from the first surface) to the camera.
        bool const lightTracing = emitters.lightTracing && depth == 1;
        if (lightTracing) ictx.CountLightPaths(n);
        if (!emitters.lights.empty() && (depth < m_maxPathLength || lightTracing))
            lightSubpaths(ctx, bxdf, rng, ictx, emitters, q, level, throughput, radiance, m_maxPathLength - depth,
                          lightTracing);
        continuePaths(ctx, bxdf, rng, ictx, emitters, q, level, throughput, radiance, depth);
    }

    /// s = 1: one sample on every light (next-event estimation).
    void lightSamples(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                      Emitters const& emitters, RixBxdfScratch& q, SubpathLevel const& level, RtColorRGB const* throughput, RtColorRGB* radiance) {
        int const n = ctx.numPts;
        RixShadingContext::Allocator pool(&ctx);
        // Needed only during this call: on the heap, so that deeper bounces do not stack them up.
        std::vector<RtFloat2> xiStorage(static_cast<size_t>(n));
        std::vector<RixLightSample> sampleStorage(static_cast<size_t>(n));
        RtFloat2* xi = xiStorage.data();
        RixLightSample* sample = sampleStorage.data();
        std::vector<RtPoint3> P(static_cast<size_t>(n));
        for (int i = 0; i < n; ++i) P[i] = level.vertex[i].P;
        ShadowRays shadow(pool, n);
        for (int light = 0; light < ictx.GetNumLights(); ++light) {
            bool const emits = ictx.CanEmit(light);
            sampleLight(ctx, bxdf, rng, ictx, light, P.data(), xi, sample, q, shadow);
            // The shadow rays of all points at once.
            ictx.Unoccluded(ctx, shadow.count, shadow.point, shadow.dir, shadow.distance, shadow.clear);
            for (int k = 0; k < shadow.count; ++k) {
                if (!shadow.clear[k]) continue;
                int const i = shadow.point[k];
                RixLightSample const& ls = sample[i];
                RtColorRGB const f = shadow.weight[k].litBy(ls.diffuse, ls.specular);
                float weight;
                if (!emits) {
                    // A light at infinity: only Bxdf sampling competes.
                    weight = ls.delta ? 1.0f : RixPowerHeuristic(1.0f, ls.pdf, 1.0f, q.FPdf[i]);
                } else {
                    RtPoint3 onLight = level.vertex[i].P + ls.wi * ls.distance;
                    RixEmissionPdf e = ictx.EmissionPdf(light, onLight, level.vertex[i].P);
                    float distSq = ls.distance * ls.distance;
                    // This strategy found the light point with SampleLight's density; those that
                    // start a light subpath there, with the light choice times SampleEmission's.
                    float nextEvent = ls.delta ? 1.0f : ls.pdf * e.cosine / distSq;
                    float emitted = emitters.choicePdf * e.pdfArea;
                    float revCamera = toArea(e.pdfDir, onLight, level.vertex[i]);
                    float revPrevious = revOfPrevious(level, i, q.RPdf[i], false);
                    float toEmitted = remapZero(emitted) / remapZero(nextEvent);
                    float sum = cameraSideSum(&level, i, revCamera, revPrevious, false, toEmitted, emitters.lightTracing);
                    if (!ls.delta) {
                        // s = 0: the camera vertex's Bxdf sample reaching the same point.
                        float ri = remapZero(q.FPdf[i] * e.cosine / distSq) / remapZero(nextEvent);
                        sum += ri * ri;
                    }
                    weight = 1.0f / (1.0f + sum);
                }
                accumulate(ictx, radiance[i], throughput[i] * f * ls.radiance * (weight / ls.pdf));
            }
        }
    }

    /// What lightSubpaths needs for one camera batch, per point, only while it runs.
    struct PerPoint {
        explicit PerPoint(int n)
            : rays(static_cast<size_t>(n)), samples(static_cast<size_t>(n)), xiPosition(static_cast<size_t>(n)),
              xiDirection(static_cast<size_t>(n)), xiLight(static_cast<size_t>(n)), deltaLight(new bool[static_cast<size_t>(n)]),
              lightIndex(static_cast<size_t>(n)), neeOverEmit(static_cast<size_t>(n)), carried(static_cast<size_t>(n)),
              root(static_cast<size_t>(n)), cameraIndex(static_cast<size_t>(n)), pdfDir(static_cast<size_t>(n)) {}
        std::vector<RixLightEmission> rays;
        std::vector<RixRNG::SampleCtx> samples;
        std::vector<RtFloat2> xiPosition, xiDirection;
        std::vector<float> xiLight;
        std::unique_ptr<bool[]> deltaLight;
        std::vector<int> lightIndex;
        std::vector<float> neeOverEmit;
        std::vector<RtColorRGB> carried;
        std::vector<PathVertex> root;
        std::vector<int> cameraIndex;
        std::vector<float> pdfDir;
    };

    /// s >= 2: a light subpath for every point, each of its vertices joined to the point.
    void lightSubpaths(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                       Emitters const& emitters, RixBxdfScratch& q, SubpathLevel const& level, RtColorRGB const* throughput,
                       RtColorRGB* radiance, int maxLightSurfaces, bool lightTracing) {
        int const n = ctx.numPts;
        RixShadingContext::Allocator pool(&ctx);
        // Everything the joins need is allocated now: the light subpaths are
        // traced (and their memory released) before the camera Bxdf is asked.
        // The joins themselves are the largest array and are not needed once
        // joined: they live only as long as this call, not as long as the batch
        // (the deeper bounces' batches would otherwise stack them up).
        std::vector<Connection> joinStorage(static_cast<size_t>(RixMax(1, n * maxLightSurfaces)));
        Connection* joins = joinStorage.data();
        PerPoint scratch(n);
        RixLightEmission* rays = scratch.rays.data();
        RixRNG::SampleCtx* samples = scratch.samples.data();
        RtFloat2* xiPosition = scratch.xiPosition.data();
        RtFloat2* xiDirection = scratch.xiDirection.data();
        float* xiLight = scratch.xiLight.data();
        bool* deltaLight = scratch.deltaLight.get();
        int* lightIndex = scratch.lightIndex.data();
        float* neeOverEmit = scratch.neeOverEmit.data();
        RtColorRGB* carried = scratch.carried.data();
        SubpathLevel root;
        root.vertex = scratch.root.data();
        int* cameraIndex = scratch.cameraIndex.data();

        rng.DrawSamples1D(xiLight);
        rng.DrawSamples2D(xiPosition);
        rng.DrawSamples2D(xiDirection);
        float const choice = emitters.choicePdf;
        for (int i = 0; i < n; ++i) {
            int const count = static_cast<int>(emitters.lights.size());
            int pick = RixMin(static_cast<int>(xiLight[i] * static_cast<float>(count)), count - 1);
            RixLightEmission& e = rays[i];
            lightIndex[i] = emitters.lights[static_cast<size_t>(pick)];
            neeOverEmit[i] = 1.0f;
            e = ictx.SampleEmission(lightIndex[i], xiPosition[i], xiDirection[i]);
            samples[i] = rng.sampleCtxArray[i].NewDomain(0x5bd1e995u);
            cameraIndex[i] = i;
            deltaLight[i] = e.deltaPosition;
            PathVertex& y0 = root.vertex[i];
            y0 = PathVertex();
            y0.P = e.P;
            y0.Ng = e.N;
            y0.pdfFwd = choice * e.pdfArea;
            carried[i] = RtColorRGB(0.0f);
            if (!e.valid) continue;
            float cosine = e.N.IsZero() ? 1.0f : std::fabs(e.N.Dot(e.dir));
            carried[i] = e.radiance * (cosine / (choice * e.pdfArea * e.pdfDir));
        }
        LightPath path{level,        joins,      maxLightSurfaces, lightTracing ? m_maxPathLength : maxLightSurfaces,
                       lightTracing, deltaLight, lightIndex,       rays,
                       neeOverEmit};
        float* pdfDir = scratch.pdfDir.data();
        for (int i = 0; i < n; ++i) pdfDir[i] = rays[i].pdfDir;
        ictx.TraceEmitted(n, rays, samples, [&](RixShadeBatch& batch) {
            lightVertex(batch, ictx, path, root, nullptr, cameraIndex, carried, pdfDir, 1);
        });

        // The joins, one round per light subpath depth: the camera Bxdf toward
        // each light vertex, and a shadow ray between them.
        RtPoint3 const* P = nullptr;
        ctx.GetBuiltinVar(RixShadingContext::k_P, &P);
        ShadowRays shadow(pool, n);
        for (int round = 0; round < maxLightSurfaces; ++round) {
            bool any = false;
            for (int i = 0; i < n; ++i) {
                Connection const& c = joins[i * maxLightSurfaces + round];
                q.Ln[i] = c.valid ? Normalize(c.P - P[i]) : RtVector3(0.0f, 0.0f, 1.0f);
                any = any || c.valid;
            }
            if (!any) continue;
            q.evaluate(bxdf, rng, ictx);
            // A shadow ray for every join, all traced at once.
            shadow.count = 0;
            for (int i = 0; i < n; ++i) {
                Connection const& c = joins[i * maxLightSurfaces + round];
                if (!c.valid) continue;
                LobeWeight const f = LobeWeight::at(q.W, i);
                if (f.all.IsBlack()) continue;
                RtVector3 toLight = c.P - P[i];
                float distance = std::sqrt(toLight.LengthSq());
                shadow.add(i, toLight / distance, distance, f);
            }
            ictx.Unoccluded(ctx, shadow.count, shadow.point, shadow.dir, shadow.distance, shadow.clear);
            for (int k = 0; k < shadow.count; ++k) {
                if (!shadow.clear[k]) continue;
                int const i = shadow.point[k];
                Connection const& c = joins[i * maxLightSurfaces + round];
                RtVector3 toLight = c.P - P[i];
                float distSq = toLight.LengthSq();
                float revLightVertex = q.FPdf[i] * c.cosine / distSq;
                float revPrevious = revOfPrevious(level, i, q.RPdf[i], false);
                float sum = cameraSideSum(&level, i, c.pdfRevCamera, revPrevious, false, 1.0f, emitters.lightTracing) +
                            remapZero(revLightVertex) * remapZero(revLightVertex) * c.lightSum;
                accumulate(ictx, radiance[i],
                           throughput[i] * shadow.weight[k].all * c.carried * (1.0f / ((1.0f + sum) * distSq)));
            }
        }
    }


    /// One depth of light subpaths: record the vertices, prepare their joins, carry on.
    /// Point j of the batch continues ray batch.source[j] of the previous depth, which left
    /// point rayPoint[ray] of `parent` (rayPoint null: ray k left point k); carried and
    /// pdfDir are per ray (throughput, and the solid-angle pdf of its direction, 0 if discrete).
    void lightVertex(RixShadeBatch& batch, RixIntegratorContext& ictx, LightPath const& path,
                     SubpathLevel const& parent, int const* rayPoint, int const* parentCameraIndex,
                     RtColorRGB const* rayCarried, float const* rayPdfDir, int depth) {
        RixShadingContext const& ctx = batch.ctx;
        int const m = ctx.numPts;
        RixShadingContext::Allocator pool(&ctx);
        PathVertex* vertex = pool.AllocFor<PathVertex>(m);
        int* parentIndex = pool.AllocFor<int>(m);
        int* cameraIndex = pool.AllocFor<int>(m);
        RtColorRGB* carried = pool.AllocFor<RtColorRGB>(m);
        placeVertices(ctx, vertex);
        for (int j = 0; j < m; ++j) {
            int ray = batch.source[j];
            parentIndex[j] = rayPoint ? rayPoint[ray] : ray;
            cameraIndex[j] = parentCameraIndex[parentIndex[j]];
            carried[j] = rayCarried[ray];
            vertex[j].pdfFwd = toArea(rayPdfDir[ray], parent.vertex[parentIndex[j]].P, vertex[j]);
        }
        SubpathLevel level;
        level.vertex = vertex;
        level.parentIndex = parentIndex;
        level.parent = &parent;
        if (depth == 1) {
            // How likely next-event estimation from here finds the light point (strategy s = 1).
            for (int j = 0; j < m; ++j) {
                int const i = cameraIndex[j];
                PathVertex const& y0 = parent.vertex[parentIndex[j]];
                RixEmissionPdf e = ictx.EmissionPdf(path.lightIndex[i], y0.P, vertex[j].P);
                float distSq = (vertex[j].P - y0.P).LengthSq();
                float nextEvent = path.deltaLight[i] ? 1.0f : e.pdfLightSample * e.cosine / distSq;
                path.neeOverEmit[i] = remapZero(nextEvent) / remapZero(y0.pdfFwd);
                // Light linking: a light subpath whose first surface the light does not light carries
                // nothing, as next-event estimation and the camera paths that reach the light from there do.
                if (!ictx.Illuminates(path.lightIndex[i], ctx, j)) carried[j] = RtColorRGB(0.0f);
            }
        }
        if (!batch.bxdf.GetAllLobeTraits().HasAny()) return;
        RixBxdfScratch q(ctx);
        // The light's diffuse and specular multipliers weigh what the first surface takes of it.
        auto bxdfWeight = [&](int j) {
            if (depth != 1) return q.W.SumAtPoint(j);
            RixLightEmission const& from = path.emitted[cameraIndex[j]];
            return LobeWeight::at(q.W, j).litBy(from.diffuse, from.specular);
        };
        if (path.lightTracing) splatToCamera(batch, ictx, q, path, level, cameraIndex, carried, bxdfWeight);

        // Join each vertex to its camera vertex: this Bxdf toward the camera vertex.
        for (int j = 0; j < m && depth <= path.maxSurfaces; ++j) {
            RtVector3 toCamera = path.camera.vertex[cameraIndex[j]].P - vertex[j].P;
            q.Ln[j] = toCamera.IsZero() ? RtVector3(0.0f, 0.0f, 1.0f) : Normalize(toCamera);
        }
        if (depth <= path.maxSurfaces) q.evaluate(batch.bxdf, batch.rng, ictx);
        for (int j = 0; j < m && depth <= path.maxSurfaces; ++j) {
            RtColorRGB f = bxdfWeight(j);
            if (f.IsBlack() || carried[j].IsBlack()) continue;
            int const i = cameraIndex[j];
            Connection& c = path.joins[i * path.maxSurfaces + depth - 1];
            c.valid = true;
            c.P = vertex[j].P;
            c.cosine = std::fabs(vertex[j].Ng.Dot(q.Ln[j]));
            c.carried = carried[j] * f;
            c.pdfRevCamera = toArea(q.FPdf[j], vertex[j].P, path.camera.vertex[i]);
            float revPrevious = toArea(q.RPdf[j], vertex[j].P, parent.vertex[parentIndex[j]]);
            c.lightSum = lightSideSum(&level, j, revPrevious, path.deltaLight[i], path.neeOverEmit[i]);
        }
        if (depth >= path.maxDepth) return;

        // Carry on: sample this Bxdf (its V faces the light's side) for the next vertex.
        q.generate(batch.bxdf, batch.rng, ictx);
        int* index = pool.AllocFor<int>(m);
        RtVector3* dir = pool.AllocFor<RtVector3>(m);
        bool* shade = pool.AllocFor<bool>(m);
        RixRNG::SampleCtx* samples = pool.AllocFor<RixRNG::SampleCtx>(m);
        RtColorRGB* nextCarried = pool.AllocFor<RtColorRGB>(m);
        float* nextPdfDir = pool.AllocFor<float>(m);
        int rays = 0;
        for (int j = 0; j < m; ++j) {
            if (!q.lobeSampled[j].GetValid() || !finite(q.Ln[j]) || q.Ln[j].IsZero()) continue;
            RtColorRGB f = bxdfWeight(j);
            if (f.IsBlack()) continue;
            bool discrete = q.lobeSampled[j].GetDiscrete();
            vertex[j].delta = discrete;
            PathVertex& previous = parent.vertex[parentIndex[j]];
            previous.pdfRev = discrete ? 0.0f : toArea(q.RPdf[j], vertex[j].P, previous);
            index[rays] = j;
            dir[rays] = Normalize(q.Ln[j]);
            shade[rays] = true;
            samples[rays] = batch.rng.sampleCtxArray[j];
            nextCarried[rays] = carried[j] * f / q.FPdf[j];
            nextPdfDir[rays] = discrete ? 0.0f : q.FPdf[j];
            ++rays;
        }
        if (rays == 0) return;
        // Lights add nothing to a light subpath; it ends at one where a camera subpath would.
        ictx.TraceIndirect(ctx, rays, index, dir, shade, samples, nullptr, [&](RixShadeBatch& child) {
            lightVertex(child, ictx, path, level, index, cameraIndex, nextCarried, nextPdfDir, depth + 1);
        });
    }

    /// t = 1: each light vertex joined to the camera, added to the pixel it lands in.
    /// bxdfWeight(j): q's weight at point j, as light that reached it along its subpath is weighed.
    template <class BxdfWeight>
    void splatToCamera(RixShadeBatch& batch, RixIntegratorContext& ictx, RixBxdfScratch& q, LightPath const& path,
                       SubpathLevel const& level, int const* cameraIndex, RtColorRGB const* carried,
                       BxdfWeight const& bxdfWeight) {
        RixShadingContext const& ctx = batch.ctx;
        int const m = ctx.numPts;
        RixShadingContext::Allocator pool(&ctx);
        RixCameraConnection* eye = pool.AllocFor<RixCameraConnection>(m);
        bool any = false;
        for (int j = 0; j < m; ++j) {
            eye[j] = carried[j].IsBlack() ? RixCameraConnection() : ictx.ConnectCamera(ctx, j, true);
            q.Ln[j] = eye[j].hit ? eye[j].dir : RtVector3(0.0f, 0.0f, 1.0f);
            any = any || eye[j].hit;
        }
        if (!any) return;
        q.evaluate(batch.bxdf, batch.rng, ictx);
        for (int j = 0; j < m; ++j) {
            if (!eye[j].hit) continue;
            RtColorRGB f = bxdfWeight(j);
            if (f.IsBlack()) continue;
            PathVertex const& previous = level.parent->vertex[level.parentIndex[j]];
            float revPrevious = toArea(q.RPdf[j], level.vertex[j].P, previous);
            float C = remapZero(eye[j].pdfArea);
            float sum = C * C * lightSideSum(&level, j, revPrevious, path.deltaLight[cameraIndex[j]], path.neeOverEmit[cameraIndex[j]]);
            RtColorRGB value = carried[j] * f * (eye[j].importance / (1.0f + sum));
            if (std::isfinite(value.r) && std::isfinite(value.g) && std::isfinite(value.b))
                ictx.SplatCamera(eye[j], value);
            else
                ictx.CountNonFinite();
        }
    }

    /// s = 0 and the path's next vertex: one Bxdf sample per point. One that reaches a light
    /// adds it (weighted against the strategies that join it); one that reaches a surface
    /// continues the camera subpath there.
    void continuePaths(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                       Emitters const& emitters, RixBxdfScratch& q, SubpathLevel const& level, RtColorRGB const* throughput,
                       RtColorRGB* radiance, int depth) {
        int const n = ctx.numPts;
        RixShadingContext::Allocator pool(&ctx);
        int* index = pool.AllocFor<int>(n);
        RtVector3* dir = pool.AllocFor<RtVector3>(n);
        bool* shade = pool.AllocFor<bool>(n);
        RixRNG::SampleCtx* samples = pool.AllocFor<RixRNG::SampleCtx>(n);
        LobeWeight* weight = pool.AllocFor<LobeWeight>(n);   // f / FPdf
        float* pdfDir = pool.AllocFor<float>(n);             // FPdf, 0 if discrete
        float* revPrevious = pool.AllocFor<float>(n);
        bool* discrete = pool.AllocFor<bool>(n);
        int rays = 0;
        q.generate(bxdf, rng, ictx);
        for (int i = 0; i < n; ++i) {
            if (!q.lobeSampled[i].GetValid()) continue;
            if (!finite(q.Ln[i]) || q.Ln[i].IsZero()) {
                ictx.CountNonFinite();
                continue;
            }
            LobeWeight const f = LobeWeight::at(q.W, i);
            if (f.all.IsBlack()) continue;
            bool isDiscrete = q.lobeSampled[i].GetDiscrete();
            level.vertex[i].delta = isDiscrete;
            revPrevious[i] = revOfPrevious(level, i, q.RPdf[i], isDiscrete);
            if (level.parent) level.parent->vertex[level.parentIndex[i]].pdfRev = revPrevious[i];
            index[rays] = i;
            dir[rays] = Normalize(q.Ln[i]);
            shade[rays] = depth < m_maxPathLength;
            samples[rays] = rng.sampleCtxArray[i];
            weight[rays] = f / q.FPdf[i];
            pdfDir[rays] = isDiscrete ? 0.0f : q.FPdf[i];
            discrete[rays] = isDiscrete;
            ++rays;
        }
        if (rays == 0) return;

        RixLightHit* lightHits = pool.AllocFor<RixLightHit>(rays);
        ictx.TraceIndirect(ctx, rays, index, dir, shade, samples, lightHits, [&](RixShadeBatch& batch) {
            int const m = batch.ctx.numPts;
            RixShadingContext::Allocator childPool(&batch.ctx);
            SubpathLevel child;
            child.vertex = childPool.AllocFor<PathVertex>(m);
            int* parentIndex = childPool.AllocFor<int>(m);
            child.parentIndex = parentIndex;
            child.parent = &level;
            placeVertices(batch.ctx, child.vertex);
            RtColorRGB* childThroughput = childPool.AllocFor<RtColorRGB>(m);
            RtColorRGB* childRadiance = childPool.AllocFor<RtColorRGB>(m);
            for (int j = 0; j < m; ++j) {
                int ray = batch.source[j];
                parentIndex[j] = index[ray];
                child.vertex[j].pdfFwd = toArea(pdfDir[ray], level.vertex[index[ray]].P, child.vertex[j]);
                childThroughput[j] = throughput[index[ray]] * weight[ray].all;
                childRadiance[j] = RtColorRGB(0.0f);
            }
            cameraVertex(batch.ctx, batch.bxdf, batch.rng, ictx, emitters, child, childThroughput, childRadiance, depth + 1);
            for (int j = 0; j < m; ++j) radiance[parentIndex[j]] += childRadiance[j];
        });

        for (int k = 0; k < rays; ++k) {
            RixLightHit const& hit = lightHits[k];
            if (!hit.hit) continue;
            int const i = index[k];
            float w;
            if (!ictx.CanEmit(hit.light)) {
                w = discrete[k] ? 1.0f : RixPowerHeuristic(1.0f, pdfDir[k], 1.0f, hit.pdf);
            } else {
                // The path ends at the light point: weigh it against joining it anywhere.
                RtPoint3 onLight = level.vertex[i].P + dir[k] * hit.distance;
                RixEmissionPdf e = ictx.EmissionPdf(hit.light, onLight, level.vertex[i].P);
                float distSq = hit.distance * hit.distance;
                float fwd = pdfDir[k] * e.cosine / distSq;
                float nextEvent = remapZero(hit.pdf * e.cosine / distSq) / remapZero(fwd);
                float sum = discrete[k] ? 0.0f : nextEvent * nextEvent;  // s = 1: next-event estimation from here
                float ri = remapZero(emitters.choicePdf * e.pdfArea) / remapZero(fwd);  // s >= 2 start at the light
                float revCamera = toArea(e.pdfDir, onLight, level.vertex[i]);
                sum += cameraSideSum(&level, i, revCamera, revPrevious[i], discrete[k], ri, emitters.lightTracing);
                w = 1.0f / (1.0f + sum);
            }
            accumulate(ictx, radiance[i], throughput[i] * weight[k].litBy(hit.diffuse, hit.specular) * hit.radiance * w);
        }
    }

    int m_maxPathLength;
};

/// Reads RenderMan's PxrVCM parameters that change nothing here, and warns about those that would.
void readRenderManParameters(RixParameterList const* params, RixMessages* messages) {
    for (char const* unneeded : {"mergeRadius", "timeRadius", "photonGuiding", "photonGuidingBBoxMin",
                                 "photonGuidingBBoxMax", "rouletteDepth", "rouletteThreshold", "clampDepth",
                                 "specularCurvatureFilter"})
        HasParam(params, unneeded);
    for (char const* count : {"numLightSamples", "numBxdfSamples"}) {
        int samples = 1;
        if (HasParam(params, count) && ReadInt(params, messages, count, 1, 0, INT_MAX, samples) && samples != 1)
            messages->Warning("%s %d: each camera vertex takes one light sample and one Bxdf sample here", count,
                              samples);
    }
    if (HasParam(params, "clampLuminance") && ReadFloat(params, "clampLuminance", 10.0f) > 0.0f)
        messages->Warning("clampLuminance is not applied: bright paths are not clamped, so what a clamped render "
                          "would darken stays bright");
}

}  // namespace

RIX_INTEGRATORCREATE {
    // RenderMan's PxrVCM also merges vertices (photon density estimation) when
    // mergePaths is 1; this one only connects them, and says so.
    int maxPathLength, connectPaths, mergePaths;
    if (!ReadInt(params, messages, "maxPathLength", 10, 1, 1000, maxPathLength) ||
        !ReadInt(params, messages, "connectPaths", 1, 0, 1, connectPaths) ||
        !ReadInt(params, messages, "mergePaths", 0, 0, 1, mergePaths))
        return nullptr;
    if (mergePaths != 0)
        messages->Warning("mergePaths 1: vertex merging is not implemented here; paths are joined by connection only");
    if (connectPaths == 0)
        messages->Warning("connectPaths 0: paths are joined by connection all the same (the only way implemented here)");
    readRenderManParameters(params, messages);
    return new BidirectionalPathTracer(maxPathLength);
}

RIX_INTEGRATORDESTROY { delete integrator; }
