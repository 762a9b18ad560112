#include "integrate/IntegratorServices.h"

#include <algorithm>
#include <cmath>

#include "accel/RayTracer.h"
#include "integrate/ShutterTime.h"

namespace bxdflab {
namespace {

/// Shadow rays stop just short of the light, so a surface touching it does not count.
float shadowReach(float distance) { return std::isinf(distance) ? kInfinity : distance * (1.0f - 1e-4f); }

/// Where and when rays leaving the points of a batch start: pushed off each surface, at the
/// shutter time the point was seen at. Make one before taking a mark of the arena: what the
/// context computes when first asked (its shutter times, most often) then comes from the arena
/// itself, not from the slower memory of its own it takes inside a deeper mark (BatchMemory).
class RayStarts {
public:
    explicit RayStarts(RixShadingContext const& ctx) {
        ctx.GetBuiltinVar(RixShadingContext::k_P, &m_P);
        ctx.GetBuiltinVar(RixShadingContext::k_Ngn, &m_Ngn);
        ctx.GetBuiltinVar(RixShadingContext::k_biasR, &m_biasR);
        ctx.GetBuiltinVar(RixShadingContext::k_time, &m_time);
    }
    /// The start of a ray from point i toward dir.
    Vec3 at(int i, Vec3 const& dir) const { return offsetRayOrigin(toVec3(m_P[i]), m_biasR[i], toVec3(m_Ngn[i]), dir); }
    float time(int i) const { return m_time[i]; }
    /// How far the lights may lie along a shadow ray from `start` (point i's) toward a light
    /// `distance` away from the point: short of that light, whatever the push off the surface.
    float lightReach(int i, Vec3 const& start, float distance) const {
        if (std::isinf(distance)) return kInfinity;
        return (distance - glm::length(start - toVec3(m_P[i]))) * (1.0f - 1e-3f);
    }

private:
    RtPoint3 const* m_P = nullptr;
    RtNormal3 const* m_Ngn = nullptr;
    RtFloat const* m_biasR = nullptr;
    RtFloat const* m_time = nullptr;
};

/// Shadow rays gathered (in arena memory) to be traced as one stream.
class ShadowStream {
public:
    ShadowStream(MemoryArena& arena, size_t capacity)
        : m_from(arena.allocArray<Vec3>(capacity)),
          m_dir(arena.allocArray<Vec3>(capacity)),
          m_reach(arena.allocArray<float>(capacity)),
          m_time(arena.allocArray<float>(capacity)) {}
    /// A ray from start along dir, at shutter time `time`, that must stay clear up to a light
    /// `distance` away.
    void add(Vec3 const& start, Vec3 const& dir, float distance, float time) {
        m_from[m_count] = start;
        m_dir[m_count] = dir;
        m_reach[m_count] = shadowReach(distance);
        m_time[m_count] = time;
        ++m_count;
    }
    int count() const { return m_count; }
    Vec3 const& from(int k) const { return m_from[k]; }
    /// blocked[k]: something lies in the way of ray k.
    void trace(PresenceTracer const& tracer, bool* blocked, RayCounts& counts, MemoryArena& arena) const {
        tracer.occludedStream(m_from, m_dir, m_reach, m_time, m_count, blocked, counts, arena);
    }

private:
    Vec3* m_from;
    Vec3* m_dir;
    float* m_reach;
    float* m_time;
    int m_count = 0;
};

}  // namespace

RixLightSample IntegratorServices::SampleLight(int light, RtPoint3 const& P, RtFloat2 const& xi) const {
    LightSample s = m_lights[static_cast<size_t>(light)]->sample(toVec3(P), Vec2(xi.x, xi.y));
    RixLightSample out;
    out.wi = toRt(s.wi);
    out.distance = s.distance;
    out.radiance = s.radiance;
    out.pdf = s.pdf;
    out.delta = s.delta;
    Light const& source = *m_lights[static_cast<size_t>(light)];
    out.shadows = source.castsShadows;
    out.diffuse = source.diffuseMultiplier;
    out.specular = source.specularMultiplier;
    return out;
}

ShadingContextImpl const* IntegratorServices::batchOf(RixShadingContext const& ctx) const {
    for (auto batch = m_batches.rbegin(); batch != m_batches.rend(); ++batch)
        if (*batch == &ctx) return *batch;
    return nullptr;
}

bool IntegratorServices::Illuminates(int light, RixShadingContext const& ctx, int i) const {
    if (!m_linkedScene) return true;
    ShadingContextImpl const* batch = batchOf(ctx);
    if (!batch) return true;  // not a batch these services shade
    int const link = batch->shape(i).lightLink;
    return link < 0 || m_linkedScene->lightLinks[static_cast<size_t>(link)][static_cast<size_t>(light)];
}

RixTraceDepth IntegratorServices::TraceDepth(RixShadingContext const& ctx, int i) const {
    ShadingContextImpl const* batch = batchOf(ctx);
    return batch ? batch->shape(i).traceDepth : RixTraceDepth();  // else RenderMan's defaults
}

void IntegratorServices::shade(HitRecord const* hits, RixRNG::SampleCtx const* samples, int count,
                               BatchShader::Visitor const& visit) {
    shadeBatches(hits, samples, count, visit);
}

void IntegratorServices::shadeBatches(HitRecord const* hits, RixRNG::SampleCtx const* samples, int count,
                                      BatchShader::Visitor const& visit) {
    m_shader.shade(hits, samples, count, m_arena, [&](ShadeGroup& group) {
        m_batches.push_back(&group.ctx);
        visit(group);
        m_batches.pop_back();
    });
}

bool IntegratorServices::Unoccluded(RixShadingContext const& ctx, int i, RtVector3 const& dir, float distance) {
    if (!(distance > 0.0f)) return true;  // nothing can lie on an empty segment
    RayStarts starts(ctx);
    Vec3 const d = toVec3(dir), from = starts.at(i, d);
    return !m_tracer.occluded(from, d, 0.0f, shadowReach(distance), starts.time(i), m_counts, m_arena) &&
           !lightEmitsAcross(from, d, starts.lightReach(i, from, distance), -d);
}

void IntegratorServices::Unoccluded(RixShadingContext const& ctx, int count, int const* indices,
                                    RtVector3 const* dirs, float const* distances, bool* clear) {
    if (count <= 0) return;
    RayStarts const starts(ctx);
    MemoryArena::Mark mark = m_arena.mark();
    ShadowStream stream(m_arena, static_cast<size_t>(count));
    // Rays of no length (lights without shadows) are clear and not traced: ray[k] is ray k's place in
    // the stream, or -1.
    int* ray = m_arena.allocArray<int>(static_cast<size_t>(count));
    for (int k = 0; k < count; ++k) {
        ray[k] = distances[k] > 0.0f ? stream.count() : -1;
        if (ray[k] < 0) continue;
        Vec3 const d = toVec3(dirs[k]);
        stream.add(starts.at(indices[k], d), d, distances[k], starts.time(indices[k]));
    }
    bool* blocked = m_arena.allocArray<bool>(static_cast<size_t>(std::max(1, stream.count())));
    stream.trace(m_tracer, blocked, m_counts, m_arena);
    for (int k = 0; k < count; ++k) {
        if (ray[k] < 0) {
            clear[k] = true;
            continue;
        }
        // A light whose lit face the ray meets stops it, as it stops the Bxdf's rays.
        clear[k] = !blocked[ray[k]];
        if (!clear[k] || !m_finiteLights) continue;
        Vec3 const d = toVec3(dirs[k]), from = stream.from(ray[k]);
        clear[k] = !lightEmitsAcross(from, d, starts.lightReach(indices[k], from, distances[k]), -d);
    }
    m_arena.release(mark);
}

RixLightHit IntegratorServices::lightAlong(Vec3 const& from, Vec3 const& dir, float maxDistance) const {
    LightAlongRay seen = nearestLightAlong(m_lights, from, dir, maxDistance);
    // A light that sends nothing this way (the back of a rect light) is no hit for MIS.
    if (!seen.light || seen.radiance.IsBlack()) return {};
    return {true, seen.distance, seen.radiance, seen.pdf, seen.index, seen.light->diffuseMultiplier,
            seen.light->specularMultiplier};
}

bool IntegratorServices::lightEmitsAcross(Vec3 const& from, Vec3 const& dir, float maxDistance,
                                          Vec3 const& toward) const {
    if (!m_finiteLights) return false;
    LightAlongRay seen = nearestLightAlong(m_lights, from, dir, maxDistance);
    if (!seen.light || seen.light->isInfinite()) return false;
    return seen.light->emissionDensity(from + seen.distance * dir, toward).pdfDir > 0.0f;
}

RixLightHit IntegratorServices::VisibleLight(RixShadingContext const& ctx, int i, RtVector3 const& dir) {
    RayStarts const starts(ctx);
    Vec3 d = toVec3(dir), from = starts.at(i, d);
    RixLightHit light = lightAlong(from, d, kInfinity);
    if (light.hit && m_tracer.occluded(from, d, 0.0f, shadowReach(light.distance), starts.time(i), m_counts, m_arena))
        light.hit = false;
    unlinkedSendNothing(ctx, i, light);
    return light;
}

void IntegratorServices::VisibleLights(RixShadingContext const& ctx, int count, int const* indices,
                                       RtVector3 const* dirs, RixLightHit* hits) {
    if (count <= 0) return;
    RayStarts const starts(ctx);
    MemoryArena::Mark mark = m_arena.mark();
    size_t const size = static_cast<size_t>(count);
    ShadowStream stream(m_arena, size);
    int* hitOf = m_arena.allocArray<int>(size);  // which of the hits each shadow ray tests
    for (int k = 0; k < count; ++k) {
        Vec3 const d = toVec3(dirs[k]), start = starts.at(indices[k], d);
        hits[k] = lightAlong(start, d, kInfinity);
        if (!hits[k].hit) continue;  // no light that way: no shadow ray
        hitOf[stream.count()] = k;
        stream.add(start, d, hits[k].distance, starts.time(indices[k]));
    }
    bool* blocked = m_arena.allocArray<bool>(size);
    stream.trace(m_tracer, blocked, m_counts, m_arena);
    for (int r = 0; r < stream.count(); ++r)
        if (blocked[r]) hits[hitOf[r]].hit = false;
    for (int k = 0; k < count; ++k) unlinkedSendNothing(ctx, indices[k], hits[k]);
    m_arena.release(mark);
}

void IntegratorServices::TraceIndirect(RixShadingContext const& ctx, int count, int const* indices,
                                       RtVector3 const* dirs, bool const* shade, RixRNG::SampleCtx const* samples,
                                       RixLightHit* lightHits, std::function<void(RixShadeBatch&)> const& visit) {
    RayStarts const starts(ctx);
    MemoryArena::Mark mark = m_arena.mark();
    HitRecord* hits = m_arena.allocArray<HitRecord>(static_cast<size_t>(std::max(1, count)));
    for (int k = 0; k < count; ++k) {
        Vec3 d = glm::normalize(toVec3(dirs[k]));
        hits[k] = m_tracer.tracer().intersect(starts.at(indices[k], d), d, 0.0f, kInfinity, starts.time(indices[k]),
                                              RayKind::Indirect, m_counts);
    }
    m_tracer.passAbsent(hits, count, nullptr, RayKind::Indirect, m_counts, m_arena);
    for (int k = 0; k < count; ++k) {
        HitRecord& hit = hits[k];
        Vec3 const from = hit.org, d = hit.dir;
        // Rays that reach a light first, or that the integrator does not want shaded, end here.
        bool endsAtLight = false;
        if (lightHits) {
            lightHits[k] = lightAlong(from, d, hit.hit() ? hit.t : kInfinity);
            endsAtLight = lightHits[k].hit;
            unlinkedSendNothing(ctx, indices[k], lightHits[k]);  // it still ends there
        } else {
            // It crosses the segment a camera path would cross the other way, and ends
            // where that path would: at a light that emits along the ray.
            endsAtLight = lightEmitsAcross(from, d, hit.hit() ? hit.t : kInfinity, d);
        }
        if (endsAtLight || !shade[k]) hit.forget();
    }
    shadeBatches(hits, samples, count, [&](ShadeGroup& group) {
        RixShadeBatch batch{group.ctx, group.bxdf, group.rng, group.source};
        visit(batch);
    });
    m_arena.release(mark);
}

RixLightEmission IntegratorServices::SampleEmission(int light, RtFloat2 const& xiPosition,
                                                   RtFloat2 const& xiDirection) const {
    Light const& source = *m_lights[static_cast<size_t>(light)];
    LightEmission e;
    RixLightEmission out;
    if (!source.canEmit() || !source.sampleEmission(Vec2(xiPosition.x, xiPosition.y), Vec2(xiDirection.x, xiDirection.y), e))
        return out;
    out.valid = true;
    out.P = toRt(e.origin);
    out.N = RtNormal3(e.normal.x, e.normal.y, e.normal.z);
    out.dir = toRt(e.dir);
    out.radiance = e.radiance;
    out.pdfArea = e.pdfArea;
    out.pdfDir = e.pdfDir;
    out.deltaPosition = source.isDelta();
    out.diffuse = source.diffuseMultiplier;
    out.specular = source.specularMultiplier;
    return out;
}

RixEmissionPdf IntegratorServices::EmissionPdf(int light, RtPoint3 const& P, RtPoint3 const& receiver) const {
    Light const& source = *m_lights[static_cast<size_t>(light)];
    Vec3 const from = toVec3(P), to = toVec3(receiver);
    Vec3 const dir = safeNormalize(to - from);
    EmissionDensity d = source.emissionDensity(from, dir);
    RixEmissionPdf out{d.pdfArea, d.pdfDir, d.cosine, 0.0f};
    if (source.isDelta()) {
        out.pdfLightSample = 1.0f;
    } else {
        float distance, pdf;
        RtColorRGB radiance;
        if (source.intersect(to, -dir, distance, radiance, pdf)) out.pdfLightSample = pdf;
    }
    return out;
}

void IntegratorServices::TraceEmitted(int count, RixLightEmission const* rays, RixRNG::SampleCtx const* samples,
                                      std::function<void(RixShadeBatch&)> const& visit) {
    MemoryArena::Mark mark = m_arena.mark();
    HitRecord* hits = m_arena.allocArray<HitRecord>(static_cast<size_t>(std::max(1, count)));
    for (int k = 0; k < count; ++k) {
        hits[k] = HitRecord();
        Vec3 from = toVec3(rays[k].P), d = safeNormalize(toVec3(rays[k].dir));
        if (!rays[k].valid || !isFinite(from) || glm::dot(d, d) == 0.0f) continue;  // nothing leaves this light
        // A light may sit on a surface (a lamp on a ceiling): start just off the light.
        float const start = 1e-5f * (1.0f + std::max({std::fabs(from.x), std::fabs(from.y), std::fabs(from.z)}));
        hits[k] = m_tracer.intersect(from, d, start, kInfinity, shutterTime(samples[k]), RayKind::Indirect, m_counts,
                                     m_arena);
        // Like a light subpath's later rays, it ends at a light where a camera path would
        // (looked for from the same start, off the light it leaves).
        if (hits[k].hit() && lightEmitsAcross(from + start * d, d, hits[k].t - start, d)) hits[k].forget();
    }
    shadeBatches(hits, samples, count, [&](ShadeGroup& group) {
        RixShadeBatch batch{group.ctx, group.bxdf, group.rng, group.source};
        visit(batch);
    });
    m_arena.release(mark);
}

RixCameraConnection IntegratorServices::ConnectCamera(RixShadingContext const& ctx, int i, bool testVisibility) {
    RixCameraConnection out;
    if (!CanConnectCamera()) return out;
    RtPoint3 const* P;
    RtNormal3 const* Ngn;
    ctx.GetBuiltinVar(RixShadingContext::k_P, &P);
    ctx.GetBuiltinVar(RixShadingContext::k_Ngn, &Ngn);
    float rasterX, rasterY, distance, directionPdf;
    Vec3 toEye;
    if (!m_camera->project(toVec3(P[i]), rasterX, rasterY, toEye, distance, directionPdf)) return out;
    float const distSq = distance * distance;
    out.pixelX = std::min(static_cast<int>(rasterX), m_film ? m_film->width() - 1 : 0);
    out.pixelY = std::min(static_cast<int>(rasterY), m_film ? m_film->height() - 1 : 0);
    out.dir = toRt(toEye);
    out.distance = distance;
    out.pdfArea = directionPdf * std::fabs(glm::dot(toVec3(Ngn[i]), toEye)) / distSq;
    // A pixel averages camera rays spread evenly over its share of the image plane.
    out.importance = directionPdf * static_cast<float>(m_camera->pixelCount()) / distSq;
    RayStarts const starts(ctx);
    out.hit = !testVisibility || !m_tracer.occluded(starts.at(i, toEye), toEye, 0.0f, shadowReach(distance),
                                                    starts.time(i), m_counts, m_arena);
    // A light the camera sees in front of the point hides it, as it does from camera rays:
    // the pixel shows the light (or its dark back), never what lies behind.
    if (out.hit && testVisibility && m_cameraLights) {
        Vec3 const eye = toVec3(P[i]) + distance * toEye;
        if (nearestLightAlong(*m_cameraLights, eye, -toEye, distance).light) out.hit = false;
    }
    return out;
}

void IntegratorServices::SplatCamera(RixCameraConnection const& where, RtColorRGB const& value) {
    if (m_film && where.pixelX >= 0 && where.pixelY >= 0) m_film->addSplat(where.pixelX, where.pixelY, value);
}

}  // namespace bxdflab
