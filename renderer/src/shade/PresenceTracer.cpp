#include "shade/PresenceTracer.h"

#include <cstring>

#include "RixRNG.h"

namespace bxdflab {
namespace {

/// Enough for any stack of leaves; the bound only stops a degenerate pile of
/// coincident cut-outs from looping (the ray then stops at the last one).
constexpr int kMaxLayers = 64;

uint32_t bitsOf(float f) {
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    return bits;
}

}  // namespace

float PresenceTracer::presenceDraw(HitRecord const& hit) {
    uint32_t h = RixRNG::Hash(hit.geomID * 0x9e3779b9u ^ hit.primID);
    for (float f : {hit.org.x, hit.org.y, hit.org.z, hit.dir.x, hit.dir.y, hit.dir.z, hit.t})
        h = RixRNG::Hash(h ^ bitsOf(f));
    return static_cast<float>(h >> 8) * 0x1p-24f;
}

HitRecord PresenceTracer::intersect(Vec3 const& org, Vec3 const& dir, float tnear, float tfar, float time,
                                    RayKind kind, RayCounts& counts, MemoryArena& arena) const {
    HitRecord hit = m_tracer.intersect(org, dir, tnear, tfar, time, kind, counts);
    if (m_active) passAbsent(&hit, 1, &tfar, kind, counts, arena);
    return hit;
}

void PresenceTracer::passAbsent(HitRecord* hits, int count, float const* tfar, RayKind kind, RayCounts& counts,
                                MemoryArena& arena) const {
    if (!m_active || count <= 0) return;
    MemoryArena::Mark mark = arena.mark();
    size_t const size = static_cast<size_t>(count);
    // pending[0..n): the rays whose latest hit has not yet been asked.
    int* pending = arena.allocArray<int>(size);
    int n = 0;
    for (int i = 0; i < count; ++i)
        if (hits[i].hit()) pending[n++] = i;
    HitRecord* asked = arena.allocArray<HitRecord>(size);
    float* presence = arena.allocArray<float>(size);
    for (int layer = 0; layer < kMaxLayers && n > 0; ++layer) {
        for (int j = 0; j < n; ++j) asked[j] = hits[pending[j]];
        m_shader.presence(asked, n, arena, presence);
        int still = 0;
        for (int j = 0; j < n; ++j) {
            int const i = pending[j];
            if (presence[j] >= 1.0f || presenceDraw(hits[i]) < presence[j]) continue;  // the ray stops here
            hits[i] = m_tracer.continuePast(hits[i], tfar ? tfar[i] : kInfinity, kind, counts);
            if (hits[i].hit()) pending[still++] = i;
        }
        n = still;
    }
    arena.release(mark);
}

bool PresenceTracer::occluded(Vec3 const& org, Vec3 const& dir, float tnear, float tfar, float time,
                              RayCounts& counts, MemoryArena& arena) const {
    if (!m_active) return m_tracer.occluded(org, dir, tnear, tfar, time, counts);
    // Any hit will not do: the first one may be a hole.
    return intersect(org, dir, tnear, tfar, time, RayKind::Shadow, counts, arena).hit();
}

void PresenceTracer::occludedStream(Vec3 const* org, Vec3 const* dir, float const* tfar, float const* time, int count,
                                    bool* blocked, RayCounts& counts, MemoryArena& arena) const {
    if (!m_active) {
        m_tracer.occludedStream(org, dir, tfar, time, count, blocked, counts);
        return;
    }
    if (count <= 0) return;
    MemoryArena::Mark mark = arena.mark();
    HitRecord* hits = arena.allocArray<HitRecord>(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i)
        hits[i] = m_tracer.intersect(org[i], dir[i], 0.0f, tfar[i], time ? time[i] : 0.0f, RayKind::Shadow, counts);
    passAbsent(hits, count, tfar, RayKind::Shadow, counts, arena);
    for (int i = 0; i < count; ++i) blocked[i] = hits[i].hit();
    arena.release(mark);
}

}  // namespace bxdflab
