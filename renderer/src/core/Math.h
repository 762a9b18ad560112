// Math types used inside the renderer (GLM), and conversions to the Rix API's
// value types at the plugin boundary.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>

#include "RiTypesHelper.h"

namespace bxdflab {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Mat3 = glm::mat3;
using Mat4 = glm::mat4;
using Vec4 = glm::vec4;
using DVec3 = glm::dvec3;

constexpr float kPi = 3.14159265358979323846f;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

inline RtFloat3 toRt(Vec3 const& v) { return RtFloat3(v.x, v.y, v.z); }
inline Vec3 toVec3(RtFloat3 const& v) { return Vec3(v.x, v.y, v.z); }

inline Vec3 transformPoint(Mat4 const& m, Vec3 const& p) {
    glm::vec4 r = m * glm::vec4(p, 1.0f);
    return Vec3(r) / r.w;
}
inline Vec3 transformVector(Mat4 const& m, Vec3 const& v) { return Mat3(m) * v; }
/// Normals transform with the inverse transpose (pass the already-inverted matrix).
inline Vec3 transformNormal(Mat4 const& inverse, Vec3 const& n) { return glm::transpose(Mat3(inverse)) * n; }

inline bool isFinite(Vec3 const& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

inline Vec3 safeNormalize(Vec3 const& v) {
    float len = glm::length(v);
    return len > 0.0f ? v / len : Vec3(0.0f);
}

/// Any unit vector perpendicular to the unit vector n (Duff et al. 2017).
inline void orthonormalBasis(Vec3 const& n, Vec3& b1, Vec3& b2) {
    float sign = std::copysign(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float b = n.x * n.y * a;
    b1 = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    b2 = Vec3(b, sign + n.y * n.y * a, -n.y);
}

/// Maps [0,1)^2 to the unit disk preserving area and stratification (Shirley-Chiu).
inline Vec2 concentricDisk(Vec2 const& xi) {
    Vec2 o = 2.0f * xi - Vec2(1.0f);
    if (o.x == 0.0f && o.y == 0.0f) return Vec2(0.0f);
    float r, theta;
    if (std::fabs(o.x) > std::fabs(o.y)) {
        r = o.x;
        theta = 0.25f * kPi * (o.y / o.x);
    } else {
        r = o.y;
        theta = 0.5f * kPi - 0.25f * kPi * (o.x / o.y);
    }
    return r * Vec2(std::cos(theta), std::sin(theta));
}

/// A direction about unit n with density cos(theta) / pi (Malley: a disk sample lifted up).
inline Vec3 cosineDirection(Vec3 const& n, Vec2 const& xi) {
    Vec2 d = concentricDisk(xi);
    Vec3 b1, b2;
    orthonormalBasis(n, b1, b2);
    return d.x * b1 + d.y * b2 + std::sqrt(std::max(0.0f, 1.0f - glm::dot(d, d))) * n;
}

/// A direction uniformly inside the cone of unit axis and cos(half-angle) cosMax
/// (cosMax = -1: the whole sphere); density 1 / (2 pi (1 - cosMax)).
inline Vec3 uniformConeDirection(Vec3 const& axis, float cosMax, Vec2 const& xi) {
    float cosTheta = 1.0f - xi.x * (1.0f - cosMax);
    float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = 2.0f * kPi * xi.y;
    Vec3 b1, b2;
    orthonormalBasis(axis, b1, b2);
    return sinTheta * std::cos(phi) * b1 + sinTheta * std::sin(phi) * b2 + cosTheta * axis;
}

}  // namespace bxdflab
