// A light in the shape of polygons: the Polygon, PointsPolygons or bilinear
// Patch that follows an AreaLightSource (RenderMan 19-20, classic files) or a
// Light "PxrMeshLight" (RenderMan 21+). Its triangles are kept in world space;
// points are sampled uniformly by area over all of them, so the solid-angle
// pdf toward a point is distance^2 / (|cos| * total area).
//
// It emits from both faces, as a two-sided surface does (RIB's default,
// Sides 2); under Sides 1 only from the front, the side its shading normal
// faces (the mesh's orientation rules).
#pragma once

#include <vector>

#include "scene/lights/ShapedLight.h"
#include "scene/shapes/TriangleMesh.h"

namespace bxdflab {

class MeshLight final : public ShapedLight {
public:
    /// Lights with more triangles than this stay glowing geometry: every
    /// camera and Bxdf-sampled ray tests each triangle of a light.
    static constexpr size_t kMaxTriangles = 256;

    /// A mesh in world space. `orientation` is +1 or -1: the sign that turns
    /// (p1 - p0) x (p2 - p0) into the front normal, as the mesh shades it; where
    /// the mesh has normals (N), each triangle's front is the side they face.
    MeshLight(MeshData const& mesh, float orientation, bool twoSided);
    const char* kind() const override { return "PxrMeshLight"; }
    LightSample sample(Vec3 const& P, Vec2 const& xi) const override;
    bool intersect(Vec3 const& org, Vec3 const& dir, float& distance, RtColorRGB& radiance, float& pdf) const override;
    bool sampleEmission(Vec2 const& xiPosition, Vec2 const& xiDirection, LightEmission& out) const override;
    EmissionDensity emissionDensity(Vec3 const& point, Vec3 const& dir) const override;

private:
    struct Triangle {
        Vec3 p0, edge1, edge2;
        Vec3 normal;  ///< unit, toward the front
    };
    /// A point chosen uniformly by area (xi in [0,1)^2), and its triangle's front normal.
    Vec3 samplePoint(Vec2 const& xi, Vec3& normal) const;
    /// The cosine that counts for emission toward -towardLight, or 0 where the light sends nothing.
    float emittingCosine(Vec3 const& normal, Vec3 const& towardLight) const;

    std::vector<Triangle> m_triangles;
    std::vector<float> m_cumulativeArea;  ///< running sum of the triangles' areas
    bool m_twoSided;
};

}  // namespace bxdflab
