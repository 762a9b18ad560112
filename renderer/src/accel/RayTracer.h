// Ray queries on Embree 3: the only place the renderer talks to Embree.
//
// Objects can be hidden from some kinds of rays (Attribute "visibility"), so
// up to three Embree scenes are built over the same geometries: one for
// camera rays, one for indirect rays and one for shadow (transmission) rays.
// When every object is visible to every ray type they are one scene.
#pragma once

#include <embree3/rtcore.h>

#include <atomic>
#include <memory>
#include <vector>

#include "core/Math.h"
#include "scene/Scene.h"

namespace bxdflab {

enum class RayKind { Camera, Indirect, Shadow };

/// Rays traced by one worker, by kind. Workers count locally and merge into
/// the tracer's totals once per batch, so counting costs no shared writes per ray.
struct RayCounts {
    uint64_t camera = 0, indirect = 0, shadow = 0;
};

struct RayCounters {
    std::atomic<uint64_t> camera{0};
    std::atomic<uint64_t> indirect{0};
    std::atomic<uint64_t> shadow{0};
    void add(RayCounts const& c) {
        camera.fetch_add(c.camera, std::memory_order_relaxed);
        indirect.fetch_add(c.indirect, std::memory_order_relaxed);
        shadow.fetch_add(c.shadow, std::memory_order_relaxed);
    }
    void reset() {
        camera = 0;
        indirect = 0;
        shadow = 0;
    }
};

/// How whole spheres (see Quadric::placedSphere) are intersected: by the
/// quadric's own exact code in double precision, as every other quadric is
/// (the default, and the faster on the course scenes), or by Embree's own
/// sphere primitive in single precision; rixbench times the two.
enum class WholeSpheres { Exact, EmbreePrimitive };

class RayTracer {
public:
    /// Builds the acceleration structures; throws RenderError on Embree failure.
    explicit RayTracer(Scene const& scene, WholeSpheres wholeSpheres = WholeSpheres::Exact);
    ~RayTracer();
    RayTracer(RayTracer const&) = delete;
    RayTracer& operator=(RayTracer const&) = delete;

    /// Rays carry a time: 0 as the shutter opens, 1 as it closes (what moving shapes are placed by).
    /// A ray leaving a surface keeps the time of the ray that reached it.

    /// Nearest hit along the ray within (tnear, tfar); hit.geomID is
    /// RTC_INVALID_GEOMETRY_ID on a miss.
    HitRecord intersect(Vec3 const& org, Vec3 const& dir, float tnear, float tfar, float time, RayKind kind,
                        RayCounts& counts) const;
    /// The nearest hits of many coherent rays at once (a stream, as Embree's
    /// rtcIntersect1M traces them: camera rays of neighbouring pixels share
    /// most of their traversal), each within (0, infinity), or (tnear[i], tfar[i]) when those are
    /// given, at time[i] (else 0). hits[i] as intersect() gives it.
    void intersectCoherent(Vec3 const* org, Vec3 const* dir, int count, RayKind kind, HitRecord* hits,
                           RayCounts& counts, float const* tnear = nullptr, float const* tfar = nullptr,
                           float const* time = nullptr) const;
    /// The next hit along hit's ray beyond hit itself (and before tfar): where
    /// a ray goes on when the surface it met lets it through. Camera rays pass
    /// one-sided backs here too. The ray keeps hit's time.
    HitRecord continuePast(HitRecord const& hit, float tfar, RayKind kind, RayCounts& counts) const;
    /// True if anything blocks the segment (tnear, tfar).
    bool occluded(Vec3 const& org, Vec3 const& dir, float tnear, float tfar, float time, RayCounts& counts) const;
    /// Many shadow rays at once (a stream, as Embree's rtcOccluded1M traces
    /// them, without a call per ray): blocked[i] as occluded() gives it for
    /// the segment (0, tfar[i]) of ray i at time[i] (null: all at 0).
    void occludedStream(Vec3 const* org, Vec3 const* dir, float const* tfar, float const* time, int count,
                        bool* blocked, RayCounts& counts) const;

    RayCounters& counters() const { return m_counters; }
    /// True when some shape the camera sees is one-sided (Sides 1), so camera
    /// rays pass the backs they meet.
    bool passesBackFaces() const { return m_anyOneSided; }
    /// World-space bounds of what camera rays can hit (empty: lower > upper).
    void cameraBounds(Vec3& lower, Vec3& upper) const;

    /// Sees every ray as it is traced (tools such as the benchmark record them).
    /// Called on the tracing thread: only for single-threaded renders.
    class Observer {
    public:
        virtual ~Observer() = default;
        virtual void traced(Vec3 const& org, Vec3 const& dir, float tnear, float tfar, RayKind kind,
                            bool occlusion) = 0;
    };
    /// Starts telling `observer` of every ray; null stops.
    void observe(Observer* observer) { m_observer = observer; }
    /// The Embree scene rays of `kind` are traced against (for tracing
    /// outside the renderer, as the benchmark's raw-Embree replay does).
    RTCScene embreeScene(RayKind kind) const;

private:
    /// Camera hits on the back of a one-sided shape (Sides 1) are passed
    /// through: the ray goes on to what lies behind.
    void passBackFaces(HitRecord& hit, RayCounts& counts) const;
    /// The nearest hit along hit's ray past hit, before tfar (a miss if none).
    HitRecord beyond(HitRecord const& hit, float tfar, RayKind kind, RayCounts& counts) const;

    RTCDevice m_device = nullptr;
    RTCScene m_camera = nullptr, m_indirect = nullptr, m_shadow = nullptr;
    std::vector<Shape const*> m_shapes;  ///< by geomID
    bool m_anyOneSided = false;
    mutable RayCounters m_counters;
    Observer* m_observer = nullptr;
};

/// The origin for a ray leaving surface point P (unit geometric normal Ng) in
/// direction w: pushed `bias` along Ng, to the side w goes to, and rounded
/// away from P, so the ray cannot re-hit the surface it starts on. `bias` is
/// P's error bound projected on Ng (the k_biasR builtin; pbrt-v4, section 6.8.6).
Vec3 offsetRayOrigin(Vec3 const& P, float bias, Vec3 const& Ng, Vec3 const& w);

}  // namespace bxdflab
