#include "scene/lights/MeshLight.h"

#include <algorithm>
#include <cmath>

namespace bxdflab {

MeshLight::MeshLight(MeshData const& mesh, float orientation, bool twoSided) : m_twoSided(twoSided) {
    Vec3 lower(kInfinity), upper(-kInfinity);
    for (size_t k = 0; k + 2 < mesh.indices.size(); k += 3) {
        unsigned const* corner = &mesh.indices[k];
        Vec3 const& p0 = mesh.P[corner[0]];
        Triangle t{p0, mesh.P[corner[1]] - p0, mesh.P[corner[2]] - p0, Vec3(0.0f)};
        Vec3 const cross = glm::cross(t.edge1, t.edge2);
        float const area = 0.5f * glm::length(cross);
        if (!(area > 0.0f)) continue;  // a degenerate triangle emits nothing and is never sampled
        t.normal = orientation * cross / (2.0f * area);
        if (!mesh.N.empty() &&
            glm::dot(t.normal, mesh.N[corner[0]] + mesh.N[corner[1]] + mesh.N[corner[2]]) < 0.0f)
            t.normal = -t.normal;
        m_triangles.push_back(t);
        m_area += area;
        m_cumulativeArea.push_back(m_area);
        for (Vec3 const& p : {p0, p0 + t.edge1, p0 + t.edge2}) {
            lower = glm::min(lower, p);
            upper = glm::max(upper, p);
        }
    }
    if (!m_triangles.empty()) {
        m_center = 0.5f * (lower + upper);
        m_boundingRadius = 0.5f * glm::length(upper - lower);
    }
}

Vec3 MeshLight::samplePoint(Vec2 const& xi, Vec3& normal) const {
    // The triangle by its share of the area, then xi.x reused within it.
    float const target = xi.x * m_area;
    size_t i =
        static_cast<size_t>(std::upper_bound(m_cumulativeArea.begin(), m_cumulativeArea.end(), target) -
                            m_cumulativeArea.begin());
    i = std::min(i, m_triangles.size() - 1);
    float const before = i == 0 ? 0.0f : m_cumulativeArea[i - 1];
    float const share = m_cumulativeArea[i] - before;
    float const u = std::clamp((target - before) / share, 0.0f, 1.0f);
    // Uniform over the triangle: the square root spreads points evenly toward the far edge.
    float const root = std::sqrt(u);
    Triangle const& t = m_triangles[i];
    normal = t.normal;
    return t.p0 + root * (1.0f - xi.y) * t.edge1 + root * xi.y * t.edge2;
}

float MeshLight::emittingCosine(Vec3 const& normal, Vec3 const& towardLight) const {
    float const cosine = -glm::dot(towardLight, normal);
    return m_twoSided ? std::fabs(cosine) : std::max(0.0f, cosine);
}

LightSample MeshLight::sample(Vec3 const& P, Vec2 const& xi) const {
    LightSample s;
    if (m_triangles.empty()) return s;
    Vec3 normal;
    Vec3 const toLight = samplePoint(xi, normal) - P;
    s.distance = glm::length(toLight);
    if (!(s.distance > 0.0f)) return s;
    s.wi = toLight / s.distance;
    float const cosine = emittingCosine(normal, s.wi);
    if (!(cosine > 0.0f)) return s;
    s.pdf = s.distance * s.distance / (cosine * m_area);
    s.radiance = color;
    return s;
}

bool MeshLight::intersect(Vec3 const& org, Vec3 const& dir, float& distance, RtColorRGB& radiance,
                          float& pdf) const {
    if (m_triangles.empty()) return false;
    // Most rays pass far from a light: test its bounding sphere first.
    Vec3 const oc = org - m_center;
    float const b = glm::dot(oc, dir);
    if (b * b - (glm::dot(oc, oc) - m_boundingRadius * m_boundingRadius) < 0.0f) return false;

    Triangle const* nearest = nullptr;
    float nearestT = kInfinity;
    for (Triangle const& t : m_triangles) {
        // Moller-Trumbore.
        Vec3 const pvec = glm::cross(dir, t.edge2);
        float const det = glm::dot(t.edge1, pvec);
        if (std::fabs(det) < 1e-20f) continue;
        float const inverse = 1.0f / det;
        Vec3 const tvec = org - t.p0;
        float const u = glm::dot(tvec, pvec) * inverse;
        if (u < 0.0f || u > 1.0f) continue;
        Vec3 const qvec = glm::cross(tvec, t.edge1);
        float const v = glm::dot(dir, qvec) * inverse;
        if (v < 0.0f || u + v > 1.0f) continue;
        float const hitT = glm::dot(t.edge2, qvec) * inverse;
        if (hitT > 0.0f && hitT < nearestT) {
            nearestT = hitT;
            nearest = &t;
        }
    }
    if (!nearest) return false;
    distance = nearestT;
    float const cosine = emittingCosine(nearest->normal, dir);
    // The back of a one-sided light: hit, but dark (as a rect light's back is).
    pdf = cosine > 0.0f ? nearestT * nearestT / (cosine * m_area) : 0.0f;
    radiance = pdf > 0.0f ? color : RtColorRGB(0.0f);
    return true;
}

// Light subpaths leave a point chosen uniformly by area, cosine-weighted about
// the face they leave from; a two-sided light picks its face with even odds.
bool MeshLight::sampleEmission(Vec2 const& xiPosition, Vec2 const& xiDirection, LightEmission& out) const {
    if (color.IsBlack() || !(m_area > 0.0f)) return false;
    Vec3 normal;
    out.origin = samplePoint(xiPosition, normal);
    Vec2 xi = xiDirection;
    float sideChance = 1.0f;
    if (m_twoSided) {
        sideChance = 0.5f;
        if (xi.x < 0.5f) {
            xi.x *= 2.0f;
        } else {
            xi.x = std::min(2.0f * xi.x - 1.0f, 0x1.fffffep-1f);
            normal = -normal;
        }
    }
    out.normal = normal;
    out.dir = cosineDirection(normal, xi);
    out.radiance = color;
    out.pdfArea = 1.0f / m_area;
    out.pdfDir = sideChance * std::max(0.0f, glm::dot(out.dir, normal)) / kPi;
    return out.pdfDir > 0.0f;
}

EmissionDensity MeshLight::emissionDensity(Vec3 const& point, Vec3 const& dir) const {
    if (m_triangles.empty()) return {};
    // The normal of the triangle whose plane the point lies nearest.
    Triangle const* on = &m_triangles.front();
    float closest = kInfinity;
    for (Triangle const& t : m_triangles) {
        float const offPlane = std::fabs(glm::dot(point - t.p0, t.normal));
        if (offPlane < closest) {
            closest = offPlane;
            on = &t;
        }
    }
    float const cosine = glm::dot(dir, on->normal);
    float const pdfDir = m_twoSided ? 0.5f * std::fabs(cosine) / kPi : std::max(0.0f, cosine) / kPi;
    return {1.0f / m_area, pdfDir, std::fabs(cosine)};
}

}  // namespace bxdflab
