// SubdivisionMesh "catmull-clark": Embree's own subdivision geometry, with
// RenderMan's tags (crease, corner, hole, interpolateboundary). Embree
// tessellates the limit surface adaptively for intersection; shading reads
// the exact limit surface (P derivatives, hence the smooth normal) at the hit.
#pragma once

#include <vector>

#include "scene/shapes/Shape.h"

namespace bxdflab {

/// A primvar that varies over a subdivision surface, interpolated by the ray
/// tracer's own subdivision of it (uniform ones are one value per face and need none).
struct SubdivisionPrimvar {
    /// vertex: subdivided as P is; varying: linear over each face; facevarying
    /// (and facevertex): subdivided per face corner, with seams where a point's
    /// corners carry different values (a UV layout's island borders).
    enum class Rate { Vertex, Varying, FaceVarying };
    Primvar var;  ///< values: one per point, or one per distinct corner value (facevarying)
    Rate rate = Rate::Vertex;
    std::vector<unsigned> cornerValues;  ///< facevarying: each face corner's index into var.values
};

struct SubdivisionData {
    std::vector<Vec3> P;               ///< control points, world space
    std::vector<unsigned> faceSizes;   ///< vertices per face
    std::vector<unsigned> indices;     ///< face vertex indices, face after face
    std::vector<unsigned> creaseEdges; ///< pairs of vertex indices
    std::vector<float> creaseWeights;  ///< one per pair
    std::vector<unsigned> corners;     ///< vertex indices
    std::vector<float> cornerWeights;  ///< one per corner
    std::vector<unsigned> holes;       ///< face indices, sorted, each once
    enum class Boundary { None, EdgesAndCorners, Edges } boundary = Boundary::None;
    /// How facevarying values behave along their seams and the mesh's border
    /// (the "facevaryinginterpolateboundary" tag; RenderMan's default pins the corners).
    enum class FaceVaryingBoundary { Smooth, PinCorners, PinBoundary, Linear } faceVaryingBoundary =
        FaceVaryingBoundary::PinCorners;
    std::vector<SubdivisionPrimvar> primvars;
};

/// Takes the vertex, varying, facevarying and facevertex primvars of a
/// SubdivisionMesh's parameters into `data` (its faces and points already
/// read), and returns its uniform ones (one value per face). Values of the
/// wrong count are an error at the parameter.
PrimvarSet readSubdivisionPrimvars(ParamList const& params, SubdivisionData& data);

class SubdivisionSurface final : public Shape {
public:
    SubdivisionSurface(SubdivisionData data, bool flipNormals);
    /// Its primvars read through it: it stays where it was made.
    SubdivisionSurface(SubdivisionSurface const&) = delete;
    SubdivisionSurface& operator=(SubdivisionSurface const&) = delete;

    const char* kind() const override { return "SubdivisionMesh"; }
    void accept(ShapeVisitor& visitor) const override { visitor.visit(*this); }
    SurfaceBasics basicsUnmoved(HitRecord const& hit) const override;
    SurfaceTangents tangentsUnmoved(HitRecord const& hit) const override;
    /// A primvar's value on the limit surface (slot: its index in data().primvars).
    void limitValue(unsigned slot, unsigned face, float u, float v, float* out, unsigned count) const {
        m_evaluator->evaluateAttribute(slot, face, u, v, out, count);
    }
    void primvarUnmoved(Primvar const& var, HitRecord const& hit, float* out) const override;
    SubdivisionData const& data() const { return m_data; }
    bool samePointsAs(Shape const& other) const override;
    std::vector<Vec3> const* points() const override { return &m_data.P; }
    void deform(std::shared_ptr<PointSteps const> steps) override;
    /// The limit surface as the ray tracer built it (evaluated at hits).
    void attach(std::shared_ptr<SurfaceEvaluator const> evaluator) const { m_evaluator = std::move(evaluator); }

private:
    SubdivisionData m_data;
    float m_orientation;
    mutable std::shared_ptr<SurfaceEvaluator const> m_evaluator;
};

}  // namespace bxdflab
