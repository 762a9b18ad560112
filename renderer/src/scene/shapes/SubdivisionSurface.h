// SubdivisionMesh "catmull-clark": Embree's own subdivision geometry, with
// RenderMan's tags (crease, corner, hole, interpolateboundary). Embree
// tessellates the limit surface adaptively for intersection; shading reads
// the exact limit surface (P derivatives, hence the smooth normal) at the hit.
#pragma once

#include <vector>

#include "scene/shapes/Shape.h"

namespace bxdflab {

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
};

class SubdivisionSurface final : public Shape {
public:
    SubdivisionSurface(SubdivisionData data, bool flipNormals);

    const char* kind() const override { return "SubdivisionMesh"; }
    void accept(ShapeVisitor& visitor) const override { visitor.visit(*this); }
    SurfaceBasics basics(HitRecord const& hit) const override;
    SurfaceTangents tangents(HitRecord const& hit) const override;
    SubdivisionData const& data() const { return m_data; }
    /// The limit surface as the ray tracer built it (evaluated at hits).
    void attach(std::shared_ptr<SurfaceEvaluator const> evaluator) const { m_evaluator = std::move(evaluator); }

private:
    SubdivisionData m_data;
    float m_orientation;
    mutable std::shared_ptr<SurfaceEvaluator const> m_evaluator;
};

}  // namespace bxdflab
