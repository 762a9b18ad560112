#include "scene/shapes/TriangleMesh.h"

#include <cstring>

namespace bxdflab {

TriangleMesh::TriangleMesh(MeshData data, const char* kindName, bool flipNormals)
    : m_data(std::move(data)), m_kind(kindName), m_orientation(flipNormals ? -1.0f : 1.0f) {
    primvars = std::move(m_data.primvars);
    m_data.primvars = PrimvarSet();
    takeSTFromPrimvars();
}

void TriangleMesh::primvarUnmoved(Primvar const& var, HitRecord const& hit, float* out) const {
    size_t const c = static_cast<size_t>(var.components);
    if (var.parametric) {
        Vec2 const uv = uvAt(hit.primID, hit.u, hit.v);
        var.parametric->at(hit.primID, uv.x, uv.y, out);
        return;
    }
    if (var.detail == Primvar::Detail::Uniform && var.values.size() >= (hit.primID + 1) * c) {
        for (size_t k = 0; k < c; ++k) out[k] = var.values[hit.primID * c + k];
        return;
    }
    if (var.detail == Primvar::Detail::Varying && var.values.size() == m_data.P.size() * c) {
        unsigned const* tri = &m_data.indices[3 * hit.primID];
        float b1 = hit.u, b2 = hit.v, b0 = 1.0f - b1 - b2;
        for (size_t k = 0; k < c; ++k)
            out[k] = b0 * var.values[tri[0] * c + k] + b1 * var.values[tri[1] * c + k] + b2 * var.values[tri[2] * c + k];
        return;
    }
    for (size_t k = 0; k < c; ++k) out[k] = var.values[k];
}

Vec2 TriangleMesh::uvAt(unsigned prim, float b1, float b2) const {
    if (!m_data.uv.empty()) return interpolate(m_data.uv, prim, b1, b2);
    return Vec2(b1, b2);
}

bool TriangleMesh::samePointsAs(Shape const& other) const {
    auto const* mesh = dynamic_cast<TriangleMesh const*>(&other);
    return mesh && mesh->m_data.P.size() == m_data.P.size() && mesh->m_data.indices == m_data.indices;
}

void TriangleMesh::deform(std::shared_ptr<PointSteps const> steps) {
    m_data.P = steps->steps.front();
    Shape::deform(std::move(steps));
}

void TriangleMesh::corners(unsigned prim, float time, Vec3& p0, Vec3& p1, Vec3& p2) const {
    unsigned const* tri = &m_data.indices[3 * prim];
    if (!m_deformation) {
        p0 = m_data.P[tri[0]];
        p1 = m_data.P[tri[1]];
        p2 = m_data.P[tri[2]];
        return;
    }
    // Embree moves each vertex in a straight line from step to step; so do we.
    p0 = m_deformation->at(tri[0], time);
    p1 = m_deformation->at(tri[1], time);
    p2 = m_deformation->at(tri[2], time);
}

Vec3 TriangleMesh::velocityUnmoved(HitRecord const& hit) const {
    if (!m_deformation) return Vec3(0.0f);
    unsigned const* tri = &m_data.indices[3 * hit.primID];
    float const b[3] = {1.0f - hit.u - hit.v, hit.u, hit.v};
    Vec3 change(0.0f);
    for (int k = 0; k < 3; ++k) change += b[k] * m_deformation->rate(tri[k], hit.time);
    return change;
}

SurfaceBasics TriangleMesh::basicsUnmoved(HitRecord const& hit) const {
    Vec3 p0, p1, p2;
    corners(hit.primID, hit.time, p0, p1, p2);
    float b1 = hit.u, b2 = hit.v, b0 = 1.0f - b1 - b2;

    SurfaceBasics out;
    out.P = b0 * p0 + b1 * p1 + b2 * p2;
    // Interpolating the vertices (rather than org + t dir) bounds the error
    // by a few ulps of the vertex magnitudes (pbrt-v4, section 6.8).
    out.pError = 1e-5f * (glm::abs(b0 * p0) + glm::abs(b1 * p1) + glm::abs(b2 * p2)) + Vec3(1e-8f);
    out.Ng = m_orientation * safeNormalize(glm::cross(p1 - p0, p2 - p0));
    if (!m_data.N.empty()) {
        out.N = safeNormalize(interpolate(m_data.N, hit.primID, b1, b2));
        if (out.N == Vec3(0.0f)) out.N = out.Ng;
        // The geometric normal follows the shading normal's side, so that
        // "outside" agrees with the normals the model was authored with.
        if (glm::dot(out.Ng, out.N) < 0.0f) out.Ng = -out.Ng;
    } else {
        out.N = out.Ng;
    }
    return out;
}

SurfaceParameters TriangleMesh::parametersUnmoved(HitRecord const& hit) const {
    Vec2 uv = uvAt(hit.primID, hit.u, hit.v);
    Vec2 st = m_data.st.empty() ? uv : interpolate(m_data.st, hit.primID, hit.u, hit.v);
    if (m_primvarST) {
        float value[2];
        m_primvarST->at(hit.primID, uv.x, uv.y, value);
        st = Vec2(value[0], value[1]);
    }
    return {uv.x, uv.y, st.x, st.y};
}

SurfaceTangents TriangleMesh::tangentsUnmoved(HitRecord const& hit) const {
    if (!m_data.dPdu.empty())
        return {interpolate(m_data.dPdu, hit.primID, hit.u, hit.v), interpolate(m_data.dPdv, hit.primID, hit.u, hit.v)};
    // Solve [p1-p0, p2-p0] = [dPdu dPdv] * [[du1, du2],[dv1, dv2]] for the
    // triangle's (u, v) parameterisation (pbrt-v4, section 6.5.3).
    unsigned const* tri = &m_data.indices[3 * hit.primID];
    Vec3 p0, p1, p2;
    corners(hit.primID, hit.time, p0, p1, p2);
    Vec2 uv0 = m_data.uv.empty() ? Vec2(0, 0) : m_data.uv[tri[0]];
    Vec2 uv1 = m_data.uv.empty() ? Vec2(1, 0) : m_data.uv[tri[1]];
    Vec2 uv2 = m_data.uv.empty() ? Vec2(0, 1) : m_data.uv[tri[2]];
    Vec2 duv02 = uv0 - uv2, duv12 = uv1 - uv2;
    Vec3 dp02 = p0 - p2, dp12 = p1 - p2;
    float determinant = duv02.x * duv12.y - duv02.y * duv12.x;
    if (std::fabs(determinant) < 1e-12f) return {Vec3(0.0f), Vec3(0.0f)};
    float inv = 1.0f / determinant;
    return {(duv12.y * dp02 - duv02.y * dp12) * inv, (duv02.x * dp12 - duv12.x * dp02) * inv};
}

}  // namespace bxdflab
