// A surface the renderer can intersect and shade.
//
// A shape holds its geometry (accel/ turns it into Embree's) and, given a
// hit, computes the differential geometry the shading context hands to
// plugins. The work is
// split in two so that the expensive part (tangents) is only done when a
// plugin asks for it:
//   basics()    P, geometric and shading normals, u, v, s, t, error bound of P
//   tangents()  dPdu, dPdv
#pragma once

#include <memory>
#include <string>

#include "RiTypesHelper.h"
#include "core/Error.h"
#include "core/Math.h"
#include "scene/shapes/Primvars.h"
#include "scene/shapes/ShapeMotion.h"

namespace bxdflab {

/// Which kinds of rays see an object (RIB: Attribute "visibility").
struct Visibility {
    bool camera = true;
    bool indirect = true;
    bool transmission = true;
    bool any() const { return camera || indirect || transmission; }
};

/// What the ray tracer reports for a hit, plus the ray that made it.
struct HitRecord {
    static constexpr unsigned kNoGeometry = ~0u;  ///< geomID of a miss
    Vec3 org{0.0f};
    Vec3 dir{0.0f};
    float t = 0.0f;
    unsigned geomID = kNoGeometry;
    unsigned primID = 0;
    float u = 0.0f;  ///< barycentric (triangles) or surface parameter (quadrics)
    float v = 0.0f;
    Vec3 Ng{0.0f};   ///< Embree's geometric normal, not normalized (used by curves and points)
    float time = 0.0f;  ///< when the ray was traced: 0 as the shutter opens, 1 as it closes
    bool hit() const { return geomID != kNoGeometry; }
    /// Makes this a miss (a light in front of the surface, say): nothing to shade.
    void forget() { geomID = kNoGeometry; }
};

struct SurfaceBasics {
    Vec3 P{0.0f};
    Vec3 Ng{0.0f, 0.0f, 1.0f};  ///< unit geometric normal, pointing "outside"
    Vec3 N{0.0f, 0.0f, 1.0f};   ///< unit shading normal
    Vec3 pError{0.0f};          ///< conservative per-axis bound on the error in P
};

/// Where a hit lies on its surface: the surface parameters (u, v) and the
/// texture coordinates (s, t), which are (u, v) unless the shape has its own.
struct SurfaceParameters {
    float u = 0.0f, v = 0.0f, s = 0.0f, t = 0.0f;
};

struct SurfaceTangents {
    Vec3 dPdu{0.0f};
    Vec3 dPdv{0.0f};
};

class TriangleMesh;
class Quadric;
class Curves;
class Points;
class SubdivisionSurface;

/// Does something for each kind of shape (accel/ builds Embree geometry this way).
class ShapeVisitor {
public:
    virtual ~ShapeVisitor() = default;
    virtual void visit(TriangleMesh const& mesh) = 0;
    virtual void visit(Quadric const& quadric) = 0;
    virtual void visit(Curves const& curves) = 0;
    virtual void visit(Points const& points) = 0;
    virtual void visit(SubdivisionSurface const& surface) = 0;
};

/// A surface only the ray tracer's own geometry defines exactly (a subdivision
/// limit surface, a curve's tube): accel/ attaches one to such shapes when it
/// builds their geometry, so shading can evaluate them at a hit.
class SurfaceEvaluator {
public:
    virtual ~SurfaceEvaluator() = default;
    /// The vertex data interpolated at (u, v) of primitive primID, with its
    /// derivatives in u and v (each `count` floats; dPdu and dPdv may be null),
    /// as it is at shutter time `time` where the vertices were given at several.
    virtual void evaluate(unsigned primID, float u, float v, float time, float* value, float* dPdu, float* dPdv,
                          unsigned count) const = 0;
    /// One of the surface's other vertex attributes (slot `slot`, `count` floats) at (u, v).
    virtual void evaluateAttribute(unsigned slot, unsigned primID, float u, float v, float* value,
                                   unsigned count) const = 0;
};

class Shape {
public:
    virtual ~Shape() = default;
    /// A short name for messages ("sphere", "polygon mesh", ...).
    virtual const char* kind() const = 0;
    virtual void accept(ShapeVisitor& visitor) const = 0;

    /// What shading needs at a hit, where the shape stands at the hit's time: the shape answers
    /// as it stands when the shutter opens (the ...Unmoved functions below) and its motion, if it
    /// has one, carries the answer to the hit's time.
    SurfaceBasics basics(HitRecord const& hit) const;
    SurfaceTangents tangents(HitRecord const& hit) const;
    /// (u, v, s, t) at a hit.
    SurfaceParameters parameters(HitRecord const& hit) const { return parametersUnmoved(unmoved(hit)); }
    /// The value of one of this shape's primvars at a hit (`out` receives var.components floats).
    void primvar(Primvar const& var, HitRecord const& hit, float* out) const { primvarUnmoved(var, unmoved(hit), out); }
    /// How fast the surface point at a hit moves, per unit of shutter time (zero when it holds still).
    Vec3 velocity(HitRecord const& hit) const;

    /// Transformation motion blur: where the shape goes while the shutter is open (null: it holds still).
    std::shared_ptr<ShapeMotion const> motion;
    /// Whether the shape moves or changes while the shutter is open.
    bool moves() const { return motion || m_deformation; }

    /// Deformation motion blur, for shapes made of points (polygons, patches, subdivision meshes):
    /// whether `other` is this shape with its points elsewhere (the same topology)...
    virtual bool samePointsAs(Shape const&) const { return false; }
    /// ...its points, as it was made...
    virtual std::vector<Vec3> const* points() const { return nullptr; }
    /// ...and its points over the shutter (any transformation motion folded in, so `motion` stays
    /// null). The shape takes the first step's points as its own; with one step it keeps them.
    virtual void deform(std::shared_ptr<PointSteps const> steps) {
        m_deformation = steps->steps.size() >= 2 ? std::move(steps) : nullptr;
    }
    PointSteps const* deformation() const { return m_deformation.get(); }

protected:
    /// The hit carried back to where the shape stands when the shutter opens (the hit itself if it
    /// holds still): its ray and normal move, its primitive and (u, v) stay.
    HitRecord unmoved(HitRecord const& hit) const;

    virtual SurfaceBasics basicsUnmoved(HitRecord const& hit) const = 0;
    virtual SurfaceTangents tangentsUnmoved(HitRecord const& hit) const = 0;
    /// How the point at a hit moves by changing shape (deformation) rather than by the transform.
    virtual Vec3 velocityUnmoved(HitRecord const&) const { return Vec3(0.0f); }
    /// By default the (u, v) the hit carries, for both, unless an st among the shape's laid-out
    /// primvars gives s and t.
    virtual SurfaceParameters parametersUnmoved(HitRecord const& hit) const {
        SurfaceParameters at{hit.u, hit.v, hit.u, hit.v};
        if (m_primvarST) {
            float st[2];
            m_primvarST->at(hit.primID, hit.u, hit.v, st);
            at.s = st[0];
            at.t = st[1];
        }
        return at;
    }
    /// By default read from the primvar's values laid out over the shape's pieces (the hit's
    /// primitive) and parameters, else interpolated over (u, v) between its corners. Shapes with
    /// per-vertex or per-face values override it.
    virtual void primvarUnmoved(Primvar const& var, HitRecord const& hit, float* out) const {
        SurfaceParameters at = parametersUnmoved(hit);
        if (var.parametric)
            var.parametric->at(hit.primID, at.u, at.v, out);
        else
            primvarAtCorners(var, at.u, at.v, out);
    }

public:
    int material = -1;  ///< index into Scene::materials
    /// Light linking (Illuminate, classic light lists): the Scene::lightLinks entry that says which
    /// lights light this shape, or -1 when every light does.
    int lightLink = -1;
    PrimvarSet primvars;
    /// TextureCoordinates s1 t1 s2 t2 s3 t3 s4 t4: (s, t) at the corners (u, v) =
    /// (0,0) (1,0) (0,1) (1,1) of a parametric surface, interpolated between.
    bool hasTextureCoordinates = false;
    float textureCoordinates[8] = {0, 0, 1, 0, 0, 1, 1, 1};
    Visibility visibility;
    RixTraceDepth traceDepth;  ///< Attribute "trace": how many bounces a path may take on from here
    /// Sides 1: only the outside is visible, so camera rays pass through the
    /// back of it (a room's near wall seen from outside, say). Other rays see both sides.
    bool oneSided = false;
    std::string name;  ///< Attribute "identifier" "name"
    SourceLocation where;
    /// The transform in effect where the shape was written: its "object" space.
    Mat4 objectToWorld{1.0f};

protected:
    /// Once the shape's primvars are in place: an "st" (or "s" and "t") among
    /// those laid out over it gives its s and t from then on.
    void takeSTFromPrimvars() { m_primvarST = parametricTextureCoordinates(primvars); }
    std::shared_ptr<ParametricValues const> m_primvarST;
    std::shared_ptr<PointSteps const> m_deformation;
};

}  // namespace bxdflab
