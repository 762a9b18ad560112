#include "accel/RayTracer.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "accel/EmbreeGeometry.h"
#include "core/Error.h"

namespace bxdflab {

static_assert(HitRecord::kNoGeometry == RTC_INVALID_GEOMETRY_ID, "a miss is a miss on both sides");

namespace {

void reportEmbreeError(void* userPtr, RTCError code, const char* message) {
    // Errors are collected and raised after the call that caused them; Embree
    // calls this from inside its own code, where throwing is not allowed.
    auto* last = static_cast<std::string*>(userPtr);
    *last = "Embree error " + std::to_string(static_cast<int>(code)) + ": " + (message ? message : "");
}

std::string g_lastEmbreeError;

void check(RTCDevice device, const char* what) {
    RTCError code = rtcGetDeviceError(device);
    if (code != RTC_ERROR_NONE)
        throw RenderError(std::string("Embree failed to ") + what + ": " +
                          (g_lastEmbreeError.empty() ? "error " + std::to_string(static_cast<int>(code)) : g_lastEmbreeError));
}

RTCRay makeRay(Vec3 const& org, Vec3 const& dir, float tnear, float tfar, float time) {
    RTCRay ray;
    ray.org_x = org.x;
    ray.org_y = org.y;
    ray.org_z = org.z;
    ray.tnear = tnear;
    ray.dir_x = dir.x;
    ray.dir_y = dir.y;
    ray.dir_z = dir.z;
    ray.time = time;
    ray.tfar = tfar;
    ray.mask = 0xffffffffu;
    ray.id = 0;
    ray.flags = 0;
    return ray;
}

}  // namespace

RayTracer::RayTracer(Scene const& scene, WholeSpheres wholeSpheres) {
    m_device = rtcNewDevice(nullptr);
    if (!m_device) throw RenderError("cannot create the Embree device (error " + std::to_string(rtcGetDeviceError(nullptr)) + ")");
    rtcSetDeviceErrorFunction(m_device, reportEmbreeError, &g_lastEmbreeError);

    bool allVisible = true;
    for (auto const& shape : scene.shapes)
        allVisible = allVisible && shape->visibility.camera && shape->visibility.indirect && shape->visibility.transmission;

    m_camera = rtcNewScene(m_device);
    m_indirect = allVisible ? m_camera : rtcNewScene(m_device);
    m_shadow = allVisible ? m_camera : rtcNewScene(m_device);
    for (RTCScene s : {m_camera, m_indirect, m_shadow}) rtcSetSceneFlags(s, RTC_SCENE_FLAG_ROBUST);

    for (size_t id = 0; id < scene.shapes.size(); ++id) {
        Shape const& shape = *scene.shapes[id];
        m_shapes.push_back(&shape);
        m_anyOneSided = m_anyOneSided || (shape.oneSided && shape.visibility.camera);
        RTCGeometry geometry = buildEmbreeGeometry(m_device, shape, wholeSpheres == WholeSpheres::EmbreePrimitive);
        check(m_device, "build a geometry");
        unsigned geomID = static_cast<unsigned>(id);
        if (allVisible) {
            rtcAttachGeometryByID(m_camera, geometry, geomID);
        } else {
            if (shape.visibility.camera) rtcAttachGeometryByID(m_camera, geometry, geomID);
            if (shape.visibility.indirect) rtcAttachGeometryByID(m_indirect, geometry, geomID);
            if (shape.visibility.transmission) rtcAttachGeometryByID(m_shadow, geometry, geomID);
        }
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(m_camera);
    if (!allVisible) {
        rtcCommitScene(m_indirect);
        rtcCommitScene(m_shadow);
    }
    check(m_device, "build the acceleration structure");
}

RayTracer::~RayTracer() {
    if (m_shadow && m_shadow != m_camera) rtcReleaseScene(m_shadow);
    if (m_indirect && m_indirect != m_camera) rtcReleaseScene(m_indirect);
    if (m_camera) rtcReleaseScene(m_camera);
    if (m_device) rtcReleaseDevice(m_device);
}

void RayTracer::cameraBounds(Vec3& lower, Vec3& upper) const {
    RTCBounds b;
    rtcGetSceneBounds(m_camera, &b);
    lower = Vec3(b.lower_x, b.lower_y, b.lower_z);
    upper = Vec3(b.upper_x, b.upper_y, b.upper_z);
}

RTCScene RayTracer::embreeScene(RayKind kind) const {
    switch (kind) {
        case RayKind::Camera: return m_camera;
        case RayKind::Indirect: return m_indirect;
        case RayKind::Shadow: return m_shadow;
    }
    return m_camera;
}

namespace {

RTCRayHit makeRayHit(Vec3 const& org, Vec3 const& dir, float tnear, float tfar, float time) {
    RTCRayHit rayhit;
    rayhit.ray = makeRay(org, dir, tnear, tfar, time);
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.u = rayhit.hit.v = 0.0f;
    rayhit.hit.Ng_x = rayhit.hit.Ng_y = rayhit.hit.Ng_z = 0.0f;
    return rayhit;
}

HitRecord toHitRecord(Vec3 const& org, Vec3 const& dir, RTCRayHit const& rayhit) {
    HitRecord hit;
    hit.org = org;
    hit.dir = dir;
    hit.time = rayhit.ray.time;
    if (rayhit.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
        hit.geomID = rayhit.hit.geomID;
        hit.primID = rayhit.hit.primID;
        hit.u = rayhit.hit.u;
        hit.v = rayhit.hit.v;
        hit.t = rayhit.ray.tfar;
        hit.Ng = Vec3(rayhit.hit.Ng_x, rayhit.hit.Ng_y, rayhit.hit.Ng_z);
    }
    return hit;
}

uint64_t& counterOf(RayCounts& counts, RayKind kind) {
    return kind == RayKind::Camera ? counts.camera : kind == RayKind::Indirect ? counts.indirect : counts.shadow;
}

}  // namespace

HitRecord RayTracer::intersect(Vec3 const& org, Vec3 const& dir, float tnear, float tfar, float time, RayKind kind,
                               RayCounts& counts) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayhit = makeRayHit(org, dir, tnear, tfar, time);
    if (m_observer) m_observer->traced(org, dir, tnear, tfar, kind, false);
    rtcIntersect1(embreeScene(kind), &context, &rayhit);
    ++counterOf(counts, kind);
    return toHitRecord(org, dir, rayhit);
}

void RayTracer::intersectCoherent(Vec3 const* org, Vec3 const* dir, int count, RayKind kind, HitRecord* hits,
                                  RayCounts& counts, float const* tnear, float const* tfar, float const* time) const {
    thread_local std::vector<RTCRayHit> rays;
    rays.resize(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
        float const from = tnear ? tnear[i] : 0.0f, to = tfar ? tfar[i] : kInfinity;
        rays[static_cast<size_t>(i)] = makeRayHit(org[i], dir[i], from, to, time ? time[i] : 0.0f);
        if (m_observer) m_observer->traced(org[i], dir[i], from, to, kind, false);
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcIntersect1M(embreeScene(kind), &context, rays.data(), static_cast<unsigned>(count), sizeof(RTCRayHit));
    counterOf(counts, kind) += static_cast<uint64_t>(count);
    for (int i = 0; i < count; ++i) hits[i] = toHitRecord(org[i], dir[i], rays[static_cast<size_t>(i)]);
    if (kind == RayKind::Camera && m_anyOneSided)
        for (int i = 0; i < count; ++i) passBackFaces(hits[i], counts);
}

void RayTracer::passBackFaces(HitRecord& hit, RayCounts& counts) const {
    // A few layers at most in any real scene; the bound only keeps a
    // degenerate stack of coincident backs from looping.
    for (int layer = 0; layer < 64 && hit.hit(); ++layer) {
        Shape const& shape = *m_shapes[hit.geomID];
        if (!shape.oneSided || glm::dot(shape.basics(hit).Ng, hit.dir) <= 0.0f) return;
        hit = beyond(hit, kInfinity, RayKind::Camera, counts);
    }
    hit.forget();
}

HitRecord RayTracer::beyond(HitRecord const& hit, float tfar, RayKind kind, RayCounts& counts) const {
    // From just beyond the hit (relative to t, as t's rounding is).
    float const tnear = hit.t * (1.0f + 1e-5f) + 1e-7f;
    if (!(tnear < tfar)) {
        HitRecord miss{hit.org, hit.dir};
        miss.time = hit.time;
        return miss;
    }
    return intersect(hit.org, hit.dir, tnear, tfar, hit.time, kind, counts);
}

HitRecord RayTracer::continuePast(HitRecord const& hit, float tfar, RayKind kind, RayCounts& counts) const {
    HitRecord next = beyond(hit, tfar, kind, counts);
    if (kind == RayKind::Camera && m_anyOneSided) passBackFaces(next, counts);
    return next;
}

bool RayTracer::occluded(Vec3 const& org, Vec3 const& dir, float tnear, float tfar, float time,
                         RayCounts& counts) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray = makeRay(org, dir, tnear, tfar, time);
    if (m_observer) m_observer->traced(org, dir, tnear, tfar, RayKind::Shadow, true);
    rtcOccluded1(m_shadow, &context, &ray);
    ++counts.shadow;
    return ray.tfar < 0.0f;
}

void RayTracer::occludedStream(Vec3 const* org, Vec3 const* dir, float const* tfar, float const* time, int count,
                               bool* blocked, RayCounts& counts) const {
    if (count <= 0) return;
    thread_local std::vector<RTCRay> rays;
    rays.resize(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
        rays[static_cast<size_t>(i)] = makeRay(org[i], dir[i], 0.0f, tfar[i], time ? time[i] : 0.0f);
        if (m_observer) m_observer->traced(org[i], dir[i], 0.0f, tfar[i], RayKind::Shadow, true);
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded1M(m_shadow, &context, rays.data(), static_cast<unsigned>(count), sizeof(RTCRay));
    counts.shadow += static_cast<uint64_t>(count);
    for (int i = 0; i < count; ++i) blocked[i] = rays[static_cast<size_t>(i)].tfar < 0.0f;
}

namespace {

/// The next float above x, as std::nextafter(x, +inf), without its call
/// (it is on every shadow ray's path): finite floats of one sign are ordered
/// like their bit patterns.
float nextFloatUp(float x) {
    if (!(x < kInfinity)) return x;  // +inf and NaN stay
    if (x == 0.0f) return std::numeric_limits<float>::denorm_min();
    uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    bits = x > 0.0f ? bits + 1 : bits - 1;
    std::memcpy(&x, &bits, sizeof bits);
    return x;
}
float nextFloatDown(float x) { return -nextFloatUp(-x); }

}  // namespace

Vec3 offsetRayOrigin(Vec3 const& P, float bias, Vec3 const& Ng, Vec3 const& w) {
    Vec3 offset = bias * Ng;
    if (glm::dot(w, Ng) < 0.0f) offset = -offset;
    Vec3 origin = P + offset;
    // Round away from P so the offset is not lost to rounding.
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0.0f)
            origin[i] = nextFloatUp(origin[i]);
        else if (offset[i] < 0.0f)
            origin[i] = nextFloatDown(origin[i]);
    }
    return origin;
}

}  // namespace bxdflab
