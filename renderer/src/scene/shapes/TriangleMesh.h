// A triangle mesh in world space: what polygons, subdivided patches and the
// teapot become. Vertex attributes other than P are optional:
//   N            smooth shading normals (else the facet normal is used)
//   uv           surface parameters (else the barycentric coordinates)
//   st           texture coordinates (else uv)
//   dPdu, dPdv   exact derivatives of a parametric surface (else derived from uv per triangle)
#pragma once

#include <vector>

#include "scene/shapes/Shape.h"
#include "scene/shapes/TrimCurves.h"

namespace bxdflab {

struct MeshData {
    std::vector<Vec3> P;
    std::vector<unsigned> indices;  ///< three per triangle
    std::vector<Vec3> N;
    std::vector<Vec2> uv;
    std::vector<Vec2> st;
    std::vector<Vec3> dPdu;
    std::vector<Vec3> dPdv;
    /// Primvars that vary over the mesh: Varying ones hold a value per mesh
    /// vertex, Uniform ones a value per triangle, or either is read at the
    /// mesh's uv (a patch mesh's, whose "st" then gives s and t).
    PrimvarSet primvars;
    /// A NuPatch's trim curves, in the (u, v) of `uv` (no loops: untrimmed).
    Trim trim;

    size_t triangleCount() const { return indices.size() / 3; }
    /// Appends another mesh with the same attributes.
    void append(MeshData const& other) {
        unsigned base = static_cast<unsigned>(P.size());
        P.insert(P.end(), other.P.begin(), other.P.end());
        for (unsigned i : other.indices) indices.push_back(base + i);
        N.insert(N.end(), other.N.begin(), other.N.end());
        uv.insert(uv.end(), other.uv.begin(), other.uv.end());
        st.insert(st.end(), other.st.begin(), other.st.end());
        dPdu.insert(dPdu.end(), other.dPdu.begin(), other.dPdu.end());
        dPdv.insert(dPdv.end(), other.dPdv.begin(), other.dPdv.end());
    }
    /// Appends one vertex with whichever attributes this mesh carries.
    unsigned addVertex(Vec3 const& p) {
        P.push_back(p);
        return static_cast<unsigned>(P.size() - 1);
    }
};

class TriangleMesh final : public Shape {
public:
    /// `kindName` names the RIB primitive it came from. When `flipNormals` is
    /// set the facet normals point the other way (ReverseOrientation, or a
    /// transform that mirrors space).
    TriangleMesh(MeshData data, const char* kindName, bool flipNormals);

    const char* kind() const override { return m_kind; }
    void accept(ShapeVisitor& visitor) const override { visitor.visit(*this); }
    SurfaceBasics basicsUnmoved(HitRecord const& hit) const override;
    SurfaceTangents tangentsUnmoved(HitRecord const& hit) const override;
    /// (u, v) from the mesh's uv (else the barycentric coordinates), (s, t) from its st (else u, v).
    SurfaceParameters parametersUnmoved(HitRecord const& hit) const override;
    void primvarUnmoved(Primvar const& var, HitRecord const& hit, float* out) const override;
    MeshData const& data() const { return m_data; }

    bool samePointsAs(Shape const& other) const override;
    std::vector<Vec3> const* points() const override { return &m_data.P; }
    void deform(std::shared_ptr<PointSteps const> steps) override;
    /// +1 or -1: the sign that turns (p1 - p0) x (p2 - p0) into the facet normal.
    float orientation() const { return m_orientation; }
    /// Whether the mesh's trim curves cut away the point at barycentric (b1, b2) of triangle prim
    /// (the ray tracer refuses hits there).
    bool trimmedAway(unsigned prim, float b1, float b2) const {
        return m_data.trim.loops && !m_data.trim.keeps(uvAt(prim, b1, b2));
    }

private:
    template <typename T>
    T interpolate(std::vector<T> const& values, unsigned prim, float b1, float b2) const {
        unsigned const* tri = &m_data.indices[3 * prim];
        return (1.0f - b1 - b2) * values[tri[0]] + b1 * values[tri[1]] + b2 * values[tri[2]];
    }
    Vec2 uvAt(unsigned prim, float b1, float b2) const;
    /// The corners of triangle prim at shutter time `time`.
    void corners(unsigned prim, float time, Vec3& p0, Vec3& p1, Vec3& p2) const;
    Vec3 velocityUnmoved(HitRecord const& hit) const override;

    MeshData m_data;
    const char* m_kind;
    float m_orientation;
};

}  // namespace bxdflab
