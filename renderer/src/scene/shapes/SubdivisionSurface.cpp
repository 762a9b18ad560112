#include "scene/shapes/SubdivisionSurface.h"

#include <cstring>

namespace bxdflab {
namespace {

/// Embree subdivides each face until its edges span about this many segments
/// on screen-independent terms: enough for smooth silhouettes at course sizes.
constexpr float kTessellationRate = 6.0f;

template <typename T>
void copyBuffer(RTCGeometry geometry, RTCBufferType type, RTCFormat format, std::vector<T> const& values,
                size_t components = 1) {
    if (values.empty()) return;
    size_t count = values.size() / components;
    void* buffer = rtcSetNewGeometryBuffer(geometry, type, 0, format, sizeof(T) * components, count);
    std::memcpy(buffer, values.data(), values.size() * sizeof(T));
}

}  // namespace

SubdivisionSurface::SubdivisionSurface(SubdivisionData data, bool flipNormals)
    : m_data(std::move(data)), m_orientation(flipNormals ? -1.0f : 1.0f) {}

SubdivisionSurface::~SubdivisionSurface() {
    if (m_geometry) rtcReleaseGeometry(m_geometry);
}

RTCGeometry SubdivisionSurface::build(RTCDevice device) const {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SUBDIVISION);
    copyBuffer(geometry, RTC_BUFFER_TYPE_FACE, RTC_FORMAT_UINT, m_data.faceSizes);
    copyBuffer(geometry, RTC_BUFFER_TYPE_INDEX, RTC_FORMAT_UINT, m_data.indices);
    // Embree reads each vertex as four floats and checks all four are finite:
    // a 16-byte stride with a zero fourth float keeps those reads inside the data.
    std::vector<Vec4> padded(m_data.P.size());
    for (size_t i = 0; i < padded.size(); ++i) padded[i] = Vec4(m_data.P[i], 0.0f);
    void* vertices = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(Vec4),
                                             padded.size());
    std::memcpy(vertices, padded.data(), padded.size() * sizeof(Vec4));
    copyBuffer(geometry, RTC_BUFFER_TYPE_EDGE_CREASE_INDEX, RTC_FORMAT_UINT2, m_data.creaseEdges, 2);
    copyBuffer(geometry, RTC_BUFFER_TYPE_EDGE_CREASE_WEIGHT, RTC_FORMAT_FLOAT, m_data.creaseWeights);
    copyBuffer(geometry, RTC_BUFFER_TYPE_VERTEX_CREASE_INDEX, RTC_FORMAT_UINT, m_data.corners);
    copyBuffer(geometry, RTC_BUFFER_TYPE_VERTEX_CREASE_WEIGHT, RTC_FORMAT_FLOAT, m_data.cornerWeights);
    copyBuffer(geometry, RTC_BUFFER_TYPE_HOLE, RTC_FORMAT_UINT, m_data.holes);
    // RenderMan drops the faces along a boundary unless interpolateboundary says otherwise.
    RTCSubdivisionMode mode = m_data.boundary == SubdivisionData::Boundary::EdgesAndCorners ? RTC_SUBDIVISION_MODE_PIN_CORNERS
                              : m_data.boundary == SubdivisionData::Boundary::Edges          ? RTC_SUBDIVISION_MODE_SMOOTH_BOUNDARY
                                                                                              : RTC_SUBDIVISION_MODE_NO_BOUNDARY;
    rtcSetGeometrySubdivisionMode(geometry, 0, mode);
    rtcSetGeometryTessellationRate(geometry, kTessellationRate);
    rtcCommitGeometry(geometry);
    rtcRetainGeometry(geometry);
    if (m_geometry) rtcReleaseGeometry(m_geometry);
    m_geometry = geometry;
    return geometry;
}

SurfaceBasics SubdivisionSurface::basics(HitRecord const& hit) const {
    SurfaceTangents t = tangents(hit);
    SurfaceBasics out;
    // The hit is on Embree's tessellation: P where the ray met it keeps
    // secondary rays off that same surface.
    out.P = hit.org + hit.t * hit.dir;
    out.pError = 3e-5f * (glm::abs(hit.org) + glm::abs(hit.t * hit.dir)) + Vec3(1e-7f);
    Vec3 limitNormal = safeNormalize(glm::cross(t.dPdu, t.dPdv));
    Vec3 facet = safeNormalize(hit.Ng);
    if (facet == Vec3(0.0f)) facet = limitNormal;
    out.Ng = m_orientation * facet;
    out.N = limitNormal == Vec3(0.0f) ? out.Ng : m_orientation * limitNormal;
    if (glm::dot(out.Ng, out.N) < 0.0f) out.Ng = -out.Ng;
    out.u = out.s = hit.u;
    out.v = out.t = hit.v;
    return out;
}

SurfaceTangents SubdivisionSurface::tangents(HitRecord const& hit) const {
    float P[3], dPdu[3], dPdv[3];
    rtcInterpolate1(m_geometry, hit.primID, hit.u, hit.v, RTC_BUFFER_TYPE_VERTEX, 0, P, dPdu, dPdv, 3);
    return {Vec3(dPdu[0], dPdu[1], dPdu[2]), Vec3(dPdv[0], dPdv[1], dPdv[2])};
}

}  // namespace bxdflab
