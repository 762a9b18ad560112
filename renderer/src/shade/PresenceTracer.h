// Ray queries that see through absent surfaces: RenderMan's presence, the
// cut-outs a Bxdf asks for with k_ComputesPresence (RixOpacity).
//
// A scene without such a Bxdf pays nothing: every query is the RayTracer's
// own. Otherwise each hit on a cut-out Bxdf is asked how present it is (in
// batches, through BatchShader::presence), a random number decides whether
// the ray stops there, and a ray that does not stop goes on to the next
// surface along it, which is asked in turn. Camera, indirect and shadow rays
// all see the same holes, so a leaf's shadow has the leaf's shape.
#pragma once

#include "accel/RayTracer.h"
#include "shade/BatchShader.h"
#include "shade/MemoryArena.h"

namespace bxdflab {

class PresenceTracer {
public:
    PresenceTracer(RayTracer const& tracer, BatchShader const& shader)
        : m_tracer(tracer), m_shader(shader), m_active(shader.anyPresence()) {}

    /// Whether some Bxdf computes presence (otherwise nothing here does more than the tracer).
    bool active() const { return m_active; }
    RayTracer const& tracer() const { return m_tracer; }

    /// The nearest present hit along the ray within (tnear, tfar).
    HitRecord intersect(Vec3 const& org, Vec3 const& dir, float tnear, float tfar, float time, RayKind kind,
                        RayCounts& counts, MemoryArena& arena) const;
    /// Moves each of hits[0..count) (with its ray) on past the absent surfaces
    /// it meets, staying within tfar[i] (kInfinity for every ray when tfar is null).
    void passAbsent(HitRecord* hits, int count, float const* tfar, RayKind kind, RayCounts& counts,
                    MemoryArena& arena) const;
    /// True if a present surface blocks the segment (tnear, tfar).
    bool occluded(Vec3 const& org, Vec3 const& dir, float tnear, float tfar, float time, RayCounts& counts,
                  MemoryArena& arena) const;
    /// blocked[i] as occluded() gives it for the segment (0, tfar[i]) of ray i at time[i].
    void occludedStream(Vec3 const* org, Vec3 const* dir, float const* tfar, float const* time, int count,
                        bool* blocked, RayCounts& counts, MemoryArena& arena) const;

    /// The random number in [0, 1) that decides whether a ray stops at a hit
    /// of fractional presence: a hash of the ray and the hit, so the same
    /// render gives the same image with any number of threads.
    static float presenceDraw(HitRecord const& hit);

private:
    RayTracer const& m_tracer;
    BatchShader const& m_shader;
    bool m_active;
};

}  // namespace bxdflab
