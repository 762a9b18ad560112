#include "scene/shapes/Shape.h"

namespace bxdflab {

namespace {
/// The hit carried back by `back`, the inverse of `move` (see Shape::unmoved).
HitRecord carriedBack(HitRecord const& hit, Mat4 const& move, Mat4 const& back) {
    HitRecord out = hit;
    // The ray keeps its parameter t: the transforms are affine, so org + t dir maps to its image.
    out.org = transformPoint(back, hit.org);
    out.dir = transformVector(back, hit.dir);
    out.Ng = transformNormal(move, hit.Ng);
    return out;
}
}  // namespace

HitRecord Shape::unmoved(HitRecord const& hit) const {
    if (!motion) return hit;
    Mat4 const move = motion->at(hit.time);
    return carriedBack(hit, move, glm::inverse(move));
}

SurfaceBasics Shape::basics(HitRecord const& hit) const {
    if (!motion) return basicsUnmoved(hit);
    Mat4 const move = motion->at(hit.time);
    Mat4 const back = glm::inverse(move);
    SurfaceBasics out = basicsUnmoved(carriedBack(hit, move, back));
    Vec3 const magnitude = glm::abs(out.P) + out.pError;
    out.P = transformPoint(move, out.P);
    out.Ng = safeNormalize(transformNormal(back, out.Ng));
    out.N = safeNormalize(transformNormal(back, out.N));
    // The bound grows with the transform's scale, plus the rounding of applying it.
    Mat3 const linear(move);
    Mat3 const absolute(glm::abs(linear[0]), glm::abs(linear[1]), glm::abs(linear[2]));
    out.pError = absolute * out.pError + 4e-6f * (absolute * magnitude + glm::abs(Vec3(move[3])));
    return out;
}

SurfaceTangents Shape::tangents(HitRecord const& hit) const {
    if (!motion) return tangentsUnmoved(hit);
    Mat4 const move = motion->at(hit.time);
    SurfaceTangents out = tangentsUnmoved(carriedBack(hit, move, glm::inverse(move)));
    return {transformVector(move, out.dPdu), transformVector(move, out.dPdv)};
}

Vec3 Shape::velocity(HitRecord const& hit) const {
    if (!moves()) return Vec3(0.0f);
    HitRecord const atOpen = unmoved(hit);
    Vec3 const change = velocityUnmoved(atOpen);
    if (!motion) return change;
    // P = move(time) P0(time), so dP/dtime = rate(time) P0 + move(time) dP0/dtime.
    Vec3 const P0 = basicsUnmoved(atOpen).P;
    return Vec3(motion->rate(hit.time) * Vec4(P0, 1.0f)) + transformVector(motion->at(hit.time), change);
}

}  // namespace bxdflab
