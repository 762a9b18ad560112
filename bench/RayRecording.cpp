#include "RayRecording.h"

#include <algorithm>

namespace bxdflab {
namespace {

RTCRay embreeRay(RayRecording::Ray const& r) {
    RTCRay ray;
    ray.org_x = r.org.x;
    ray.org_y = r.org.y;
    ray.org_z = r.org.z;
    ray.tnear = r.tnear;
    ray.dir_x = r.dir.x;
    ray.dir_y = r.dir.y;
    ray.dir_z = r.dir.z;
    ray.time = 0.0f;
    ray.tfar = r.tfar;
    ray.mask = 0xffffffffu;
    ray.id = 0;
    ray.flags = 0;
    return ray;
}

}  // namespace

size_t RayRecording::occlusionRays() const {
    return static_cast<size_t>(std::count_if(m_rays.begin(), m_rays.end(), [](Ray const& r) { return r.occlusion; }));
}

size_t RayRecording::replay(RayTracer const& tracer) const {
    size_t hits = 0;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (Ray const& r : m_rays) {
        if (r.occlusion) {
            RTCRay ray = embreeRay(r);
            rtcOccluded1(tracer.embreeScene(RayKind::Shadow), &context, &ray);
            hits += ray.tfar < 0.0f;
        } else {
            RTCRayHit rayhit;
            rayhit.ray = embreeRay(r);
            rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(tracer.embreeScene(r.kind), &context, &rayhit);
            hits += rayhit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
    }
    return hits;
}

}  // namespace bxdflab
