#include "scene/shapes/Curves.h"

#include <cmath>
#include <cstring>

namespace bxdflab {
namespace {

/// P and its error bound where a ray met a surface that has no parameterisation of its own to evaluate.
void pointOnRay(HitRecord const& hit, SurfaceBasics& out) {
    out.P = hit.org + hit.t * hit.dir;
    out.pError = 3e-5f * (glm::abs(hit.org) + glm::abs(hit.t * hit.dir)) + Vec3(1e-7f);
    Vec3 n = safeNormalize(hit.Ng);
    out.Ng = out.N = n == Vec3(0.0f) ? -hit.dir : n;
}

RTCGeometry pointGeometry(RTCDevice device, RTCGeometryType type, std::vector<Vec4> const& points) {
    RTCGeometry geometry = rtcNewGeometry(device, type);
    void* buffer = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, sizeof(Vec4),
                                           points.size());
    std::memcpy(buffer, points.data(), points.size() * sizeof(Vec4));
    return geometry;
}

}  // namespace

Curves::~Curves() {
    if (m_geometry) rtcReleaseGeometry(m_geometry);
}

RTCGeometry Curves::build(RTCDevice device) const {
    RTCGeometry geometry = pointGeometry(
        device, m_data.cubic ? RTC_GEOMETRY_TYPE_ROUND_BEZIER_CURVE : RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE, m_data.points);
    void* index = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned),
                                          m_data.segments.size());
    std::memcpy(index, m_data.segments.data(), m_data.segments.size() * sizeof(unsigned));
    rtcCommitGeometry(geometry);
    rtcRetainGeometry(geometry);
    if (m_geometry) rtcReleaseGeometry(m_geometry);
    m_geometry = geometry;
    return geometry;
}

SurfaceBasics Curves::basics(HitRecord const& hit) const {
    SurfaceBasics out;
    pointOnRay(hit, out);
    // Embree's curve intersection is approximate near the surface: keep new
    // rays a small fraction of the radius away, or they can hit the same tube.
    float P[4];
    rtcInterpolate1(m_geometry, hit.primID, hit.u, hit.v, RTC_BUFFER_TYPE_VERTEX, 0, P, nullptr, nullptr, 4);
    out.pError = glm::max(out.pError, Vec3(0.02f * std::abs(P[3])));
    out.u = out.s = hit.u;  // along the segment
    out.v = out.t = hit.v;
    return out;
}

SurfaceTangents Curves::tangents(HitRecord const& hit) const {
    float P[4], dPdu[4];
    rtcInterpolate1(m_geometry, hit.primID, hit.u, hit.v, RTC_BUFFER_TYPE_VERTEX, 0, P, dPdu, nullptr, 4);
    Vec3 along(dPdu[0], dPdu[1], dPdu[2]);
    Vec3 N = safeNormalize(hit.Ng);
    return {along, glm::cross(N, along)};
}

RTCGeometry Points::build(RTCDevice device) const {
    RTCGeometry geometry = pointGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT, m_spheres);
    rtcCommitGeometry(geometry);
    return geometry;
}

SurfaceBasics Points::basics(HitRecord const& hit) const {
    SurfaceBasics out;
    pointOnRay(hit, out);
    // The exact sphere normal, from the centre (Embree's is the same up to rounding).
    Vec4 const& s = m_spheres[hit.primID];
    Vec3 n = safeNormalize(out.P - Vec3(s));
    if (n != Vec3(0.0f)) out.Ng = out.N = n;
    out.u = out.s = hit.u;
    out.v = out.t = hit.v;
    return out;
}

SurfaceTangents Points::tangents(HitRecord const&) const {
    return {};  // a particle has no parameterisation: plugins build a frame from N alone
}

}  // namespace bxdflab
