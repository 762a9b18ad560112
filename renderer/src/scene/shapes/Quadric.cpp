#include "scene/shapes/Quadric.h"

#include <algorithm>
#include <cmath>

#include "scene/shapes/QuadricMath.h"

namespace bxdflab {
namespace {

// Embree callbacks: the geometry's user pointer is the Quadric.
void quadricBounds(const RTCBoundsFunctionArguments* args) {
    auto const* quadric = static_cast<Quadric const*>(args->geometryUserPtr);
    Vec3 lo, hi;
    quadric->boundsLocal(lo, hi);
    Vec3 worldLo(kInfinity), worldHi(-kInfinity);
    for (int corner = 0; corner < 8; ++corner) {
        Vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
        Vec3 w = transformPoint(quadric->objectToWorld(), p);
        worldLo = glm::min(worldLo, w);
        worldHi = glm::max(worldHi, w);
    }
    // Pad by a relative epsilon so rays grazing the box are not lost.
    Vec3 pad = 1e-5f * (glm::abs(worldLo) + glm::abs(worldHi)) + Vec3(1e-6f);
    worldLo -= pad;
    worldHi += pad;
    args->bounds_o->lower_x = worldLo.x;
    args->bounds_o->lower_y = worldLo.y;
    args->bounds_o->lower_z = worldLo.z;
    args->bounds_o->upper_x = worldHi.x;
    args->bounds_o->upper_y = worldHi.y;
    args->bounds_o->upper_z = worldHi.z;
}

struct LocalRay {
    DVec3 org, dir;
};

LocalRay toObjectSpace(Mat4 const& worldToObject, RTCRayN* ray, unsigned n, unsigned i) {
    glm::dmat4 m(worldToObject);
    DVec3 org(RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i));
    DVec3 dir(RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i));
    return {DVec3(m * glm::dvec4(org, 1.0)), glm::dmat3(m) * dir};
}

void quadricIntersect(const RTCIntersectFunctionNArguments* args) {
    auto const* quadric = static_cast<Quadric const*>(args->geometryUserPtr);
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    Mat4 const& worldToObject = quadric->worldToObject();
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        LocalRay local = toObjectSpace(worldToObject, ray, args->N, i);
        auto found = quadric->intersectLocal(local.org, local.dir, RTCRayN_tnear(ray, args->N, i),
                                             RTCRayN_tfar(ray, args->N, i));
        if (!found) continue;
        RTCRayN_tfar(ray, args->N, i) = static_cast<float>(found->t);
        RTCHitN_Ng_x(hit, args->N, i) = 0.0f;  // the shading context recomputes normals
        RTCHitN_Ng_y(hit, args->N, i) = 0.0f;
        RTCHitN_Ng_z(hit, args->N, i) = 1.0f;
        RTCHitN_u(hit, args->N, i) = found->u;
        RTCHitN_v(hit, args->N, i) = found->v;
        RTCHitN_primID(hit, args->N, i) = args->primID;
        RTCHitN_geomID(hit, args->N, i) = args->geomID;
        RTCHitN_instID(hit, args->N, i, 0) = args->context->instID[0];
    }
}

void quadricOccluded(const RTCOccludedFunctionNArguments* args) {
    auto const* quadric = static_cast<Quadric const*>(args->geometryUserPtr);
    Mat4 const& worldToObject = quadric->worldToObject();
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        LocalRay local = toObjectSpace(worldToObject, args->ray, args->N, i);
        if (quadric->intersectLocal(local.org, local.dir, RTCRayN_tnear(args->ray, args->N, i),
                                    RTCRayN_tfar(args->ray, args->N, i)))
            RTCRayN_tfar(args->ray, args->N, i) = -kInfinity;
    }
}


}  // namespace

Quadric::Quadric(Mat4 const& objectToWorld, bool reverseOrientation)
    : m_objectToWorld(objectToWorld),
      m_worldToObject(glm::inverse(objectToWorld)),
      m_orientation(reverseOrientation ? -1.0f : 1.0f) {}

double Quadric::azimuth(double x, double y) {
    double phi = std::atan2(y, x);
    return phi < 0.0 ? phi + quadric::kTwoPi : phi;
}

RTCGeometry Quadric::build(RTCDevice device) const {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, 1);
    rtcSetGeometryUserData(geometry, const_cast<Quadric*>(this));
    rtcSetGeometryBoundsFunction(geometry, quadricBounds, nullptr);
    rtcSetGeometryIntersectFunction(geometry, quadricIntersect);
    rtcSetGeometryOccludedFunction(geometry, quadricOccluded);
    rtcCommitGeometry(geometry);
    return geometry;
}

SurfaceBasics Quadric::basics(HitRecord const& hit) const {
    LocalSurface local = surfaceLocal(hit.u, hit.v);
    SurfaceBasics out;
    out.P = transformPoint(m_objectToWorld, local.P);
    out.Ng = m_orientation * safeNormalize(transformNormal(m_worldToObject, local.N));
    out.N = out.Ng;
    // P is evaluated from (u, v) on the exact surface; its error is a few ulps
    // of the magnitudes involved in the transform. Bound it generously.
    Mat3 linear(m_objectToWorld);
    Mat3 absolute(glm::abs(linear[0]), glm::abs(linear[1]), glm::abs(linear[2]));
    Vec3 magnitude = absolute * glm::abs(local.P) + glm::abs(Vec3(m_objectToWorld[3]));
    out.pError = 4e-6f * magnitude + Vec3(1e-7f);
    out.u = hit.u;
    out.v = hit.v;
    out.s = hit.u;
    out.t = hit.v;
    return out;
}

SurfaceTangents Quadric::tangents(HitRecord const& hit) const {
    LocalSurface local = surfaceLocal(hit.u, hit.v);
    return {transformVector(m_objectToWorld, local.dPdu), transformVector(m_objectToWorld, local.dPdv)};
}

}  // namespace bxdflab
