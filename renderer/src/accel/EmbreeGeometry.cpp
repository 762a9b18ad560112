#include "accel/EmbreeGeometry.h"

#include <algorithm>
#include <cstring>
#include <optional>
#include <vector>

#include "scene/shapes/Curves.h"
#include "scene/shapes/Quadric.h"
#include "scene/shapes/SubdivisionSurface.h"
#include "scene/shapes/TriangleMesh.h"

namespace bxdflab {
namespace {

// Embree callbacks: the geometry's user pointer is the Quadric.
void quadricBounds(const RTCBoundsFunctionArguments* args) {
    auto const* quadric = static_cast<Quadric const*>(args->geometryUserPtr);
    Vec3 lo, hi;
    quadric->boundsLocal(lo, hi);
    // A moving quadric is bounded at each step of its motion (Embree blends the boxes between).
    Mat4 const toWorld = quadric->motion ? quadric->motion->steps[args->timeStep] * quadric->objectToWorld()
                                         : quadric->objectToWorld();
    Vec3 worldLo(kInfinity), worldHi(-kInfinity);
    for (int corner = 0; corner < 8; ++corner) {
        Vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
        Vec3 w = transformPoint(toWorld, p);
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

/// Ray i of a packet in the quadric's object space. A moving quadric is first carried back to
/// where it stood when the shutter opened, at the ray's time.
LocalRay toObjectSpace(Quadric const& quadric, RTCRayN* ray, unsigned n, unsigned i) {
    DVec3 org(RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i));
    DVec3 dir(RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i), RTCRayN_dir_z(ray, n, i));
    glm::dmat4 const& worldToObject = quadric.worldToObjectExact();
    if (!quadric.motion) return {DVec3(worldToObject * glm::dvec4(org, 1.0)), glm::dmat3(worldToObject) * dir};
    glm::dmat4 const m = worldToObject * glm::inverse(glm::dmat4(quadric.motion->at(RTCRayN_time(ray, n, i))));
    return {DVec3(m * glm::dvec4(org, 1.0)), glm::dmat3(m) * dir};
}

void quadricIntersect(const RTCIntersectFunctionNArguments* args) {
    auto const* quadric = static_cast<Quadric const*>(args->geometryUserPtr);
    RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
    RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        LocalRay local = toObjectSpace(*quadric, ray, args->N, i);
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
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        LocalRay local = toObjectSpace(*quadric, args->ray, args->N, i);
        if (quadric->hitsLocal(local.org, local.dir, RTCRayN_tnear(args->ray, args->N, i),
                               RTCRayN_tfar(args->ray, args->N, i)))
            RTCRayN_tfar(args->ray, args->N, i) = -kInfinity;
    }
}

/// RenderMan's subdivision holes are not rendered but still shape the faces
/// around them (exporters split a mesh into pieces, each holding its
/// neighbours as holes, and the pieces meet). Embree's holes leave the
/// topology instead, so the faces stay in the mesh and their hits are refused.
void refuseHoleHits(const RTCFilterFunctionNArguments* args) {
    auto const* holes = static_cast<std::vector<unsigned> const*>(args->geometryUserPtr);  // sorted
    for (unsigned i = 0; i < args->N; ++i)
        if (args->valid[i] == -1 && std::binary_search(holes->begin(), holes->end(), RTCHitN_primID(args->hit, args->N, i)))
            args->valid[i] = 0;
}

/// A trimmed NuPatch is tessellated whole; hits where its trim curves cut it away are refused, so
/// its edges follow the curves exactly, for every kind of ray.
void refuseTrimmedHits(const RTCFilterFunctionNArguments* args) {
    auto const* mesh = static_cast<TriangleMesh const*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i)
        if (args->valid[i] == -1 && mesh->trimmedAway(RTCHitN_primID(args->hit, args->N, i),
                                                       RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i)))
            args->valid[i] = 0;
}

/// Embree subdivides each face until its edges span about this many segments
/// on screen-independent terms: enough for smooth silhouettes at course sizes.
constexpr float kTessellationRate = 6.0f;

template <typename T>
void copyBuffer(RTCGeometry geometry, RTCBufferType type, RTCFormat format, std::vector<T> const& values,
                size_t components = 1) {
    if (values.empty()) return;
    size_t count = values.size() / components;
    void* buffer = rtcSetNewGeometryBuffer(geometry, type, 0, format, sizeof(T) * components, count);
    std::memcpy(buffer, values.data(), values.size() * sizeof(T));
}

/// How many evenly spaced moments of the shutter a shape's vertices are given at: 1 when it holds
/// still, else those of its transformation motion or of its deformation.
unsigned motionStepCount(Shape const& shape) {
    if (shape.deformation()) return static_cast<unsigned>(shape.deformation()->steps.size());
    return shape.motion ? static_cast<unsigned>(shape.motion->steps.size()) : 1u;
}

/// Shutter time of step `step` of `count`.
float stepTime(unsigned step, unsigned count) {
    return count > 1 ? static_cast<float>(step) / static_cast<float>(count - 1) : 0.0f;
}

/// Sets the vertex buffers of a geometry with `count` vertices (each starting with its position),
/// and `padding` zero vertices after them: one buffer for a shape that holds still, else one at
/// each step of its motion. fill(vertices) writes the vertices as the shape was made; a deforming
/// shape's points at each step replace their positions, a moving shape's positions are moved there.
template <typename Vertex, typename Fill>
void setMovingVertices(RTCGeometry geometry, Shape const& shape, unsigned steps, RTCFormat format, size_t count,
                       size_t padding, Fill const& fill) {
    if (steps > 1) rtcSetGeometryTimeStepCount(geometry, steps);
    for (unsigned step = 0; step < steps; ++step) {
        auto* vertices = static_cast<Vertex*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, step, format, sizeof(Vertex), count + padding));
        float const time = stepTime(step, steps);
        fill(vertices);
        for (size_t i = count; i < count + padding; ++i) vertices[i] = Vertex(0.0f);
        if (PointSteps const* deformation = shape.deformation()) {
            for (size_t i = 0; i < count; ++i)
                for (int k = 0; k < 3; ++k) vertices[i][k] = deformation->steps[step][i][k];
            continue;
        }
        if (!shape.motion) continue;
        Mat4 const move = shape.motion->at(time);
        for (size_t i = 0; i < count; ++i) {
            Vec3 const moved = transformPoint(move, Vec3(vertices[i]));
            for (int k = 0; k < 3; ++k) vertices[i][k] = moved[k];
        }
    }
}

RTCGeometry pointGeometry(RTCDevice device, RTCGeometryType type, Shape const& shape, std::vector<Vec4> const& points) {
    RTCGeometry geometry = rtcNewGeometry(device, type);
    setMovingVertices<Vec4>(geometry, shape, motionStepCount(shape), RTC_FORMAT_FLOAT4, points.size(), 0,
                            [&](Vec4* vertices) { std::copy(points.begin(), points.end(), vertices); });
    return geometry;
}

/// The normals of oriented disks and ribbons, at every step of the shape's motion, turned as
/// setMovingVertices moves its points.
void setMovingNormals(RTCGeometry geometry, Shape const& shape, std::vector<Vec3> const& normals) {
    unsigned const steps = motionStepCount(shape);
    for (unsigned step = 0; step < steps; ++step) {
        auto* out = static_cast<Vec3*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_NORMAL, step, RTC_FORMAT_FLOAT3, sizeof(Vec3), normals.size()));
        Mat4 const inverseMove =
            shape.motion ? glm::inverse(shape.motion->at(stepTime(step, steps))) : Mat4(1.0f);
        for (size_t i = 0; i < normals.size(); ++i)
            out[i] = safeNormalize(transformNormal(inverseMove, normals[i]));
    }
}

/// rtcInterpolate on a geometry it keeps alive: what curves and subdivision
/// surfaces evaluate their exact surface with.
class EmbreeEvaluator final : public SurfaceEvaluator {
public:
    /// `steps`: how many moments of the shutter the geometry's vertices were given at.
    EmbreeEvaluator(RTCGeometry geometry, unsigned steps) : m_geometry(geometry), m_steps(steps) {
        rtcRetainGeometry(m_geometry);
    }
    ~EmbreeEvaluator() override { rtcReleaseGeometry(m_geometry); }
    EmbreeEvaluator(EmbreeEvaluator const&) = delete;
    EmbreeEvaluator& operator=(EmbreeEvaluator const&) = delete;
    void evaluate(unsigned primID, float u, float v, float time, float* value, float* dPdu, float* dPdv,
                  unsigned count) const override {
        if (m_steps < 2 || time <= 0.0f) {
            rtcInterpolate1(m_geometry, primID, u, v, RTC_BUFFER_TYPE_VERTEX, 0, value, dPdu, dPdv, count);
            return;
        }
        // Each step's vertices are a buffer slot of their own: blend the two around `time`.
        size_t step;
        float f;
        shutterStep(time, m_steps, step, f);
        float later[3][4];
        rtcInterpolate1(m_geometry, primID, u, v, RTC_BUFFER_TYPE_VERTEX, static_cast<unsigned>(step), value, dPdu,
                        dPdv, count);
        rtcInterpolate1(m_geometry, primID, u, v, RTC_BUFFER_TYPE_VERTEX, static_cast<unsigned>(step + 1), later[0],
                        dPdu ? later[1] : nullptr, dPdv ? later[2] : nullptr, count);
        float* const outputs[3] = {value, dPdu, dPdv};
        for (int k = 0; k < 3; ++k)
            if (outputs[k])
                for (unsigned c = 0; c < count; ++c) outputs[k][c] = (1.0f - f) * outputs[k][c] + f * later[k][c];
    }
    void evaluateAttribute(unsigned slot, unsigned primID, float u, float v, float* value,
                           unsigned count) const override {
        rtcInterpolate1(m_geometry, primID, u, v, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, slot, value, nullptr, nullptr, count);
    }

private:
    RTCGeometry m_geometry;
    unsigned m_steps;
};

class GeometryBuilder final : public ShapeVisitor {
public:
    GeometryBuilder(RTCDevice device, bool embreeSpheres) : m_device(device), m_embreeSpheres(embreeSpheres) {}
    RTCGeometry geometry() const { return m_geometry; }

    void visit(TriangleMesh const& mesh) override {
        MeshData const& data = mesh.data();
        m_geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
        // Embree may read 16 bytes at the last vertex; one vertex of padding keeps that in bounds.
        setMovingVertices<Vec3>(m_geometry, mesh, motionStepCount(mesh), RTC_FORMAT_FLOAT3, data.P.size(), 1,
                                [&](Vec3* vertices) { std::copy(data.P.begin(), data.P.end(), vertices); });
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            m_geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), data.triangleCount()));
        std::memcpy(indices, data.indices.data(), data.indices.size() * sizeof(unsigned));
        if (data.trim.loops) {
            rtcSetGeometryUserData(m_geometry, const_cast<TriangleMesh*>(&mesh));
            rtcSetGeometryIntersectFilterFunction(m_geometry, refuseTrimmedHits);
            rtcSetGeometryOccludedFilterFunction(m_geometry, refuseTrimmedHits);
        }
        rtcCommitGeometry(m_geometry);
    }

    void visit(Quadric const& quadric) override {
        // Embree's sphere primitive does not move; a moving sphere is intersected by its own code.
        std::optional<Vec4> ball = m_embreeSpheres && !quadric.motion ? quadric.placedSphere() : std::nullopt;
        if (ball) {
            m_geometry = pointGeometry(m_device, RTC_GEOMETRY_TYPE_SPHERE_POINT, quadric, {*ball});
            rtcCommitGeometry(m_geometry);
            return;
        }
        m_geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(m_geometry, 1);
        if (quadric.motion) rtcSetGeometryTimeStepCount(m_geometry, motionStepCount(quadric));
        rtcSetGeometryUserData(m_geometry, const_cast<Quadric*>(&quadric));
        rtcSetGeometryBoundsFunction(m_geometry, quadricBounds, nullptr);
        rtcSetGeometryIntersectFunction(m_geometry, quadricIntersect);
        rtcSetGeometryOccludedFunction(m_geometry, quadricOccluded);
        rtcCommitGeometry(m_geometry);
    }

    void visit(Curves const& curves) override {
        CurveData const& data = curves.data();
        RTCGeometryType const type = !data.normals.empty() ? RTC_GEOMETRY_TYPE_NORMAL_ORIENTED_BEZIER_CURVE
                                     : data.cubic          ? RTC_GEOMETRY_TYPE_ROUND_BEZIER_CURVE
                                                           : RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE;
        m_geometry = pointGeometry(m_device, type, curves, data.points);
        if (!data.normals.empty()) setMovingNormals(m_geometry, curves, data.normals);
        void* index = rtcSetNewGeometryBuffer(m_geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned),
                                              data.segments.size());
        std::memcpy(index, data.segments.data(), data.segments.size() * sizeof(unsigned));
        rtcCommitGeometry(m_geometry);
        curves.attach(std::make_shared<EmbreeEvaluator>(m_geometry, motionStepCount(curves)));
    }

    void visit(Points const& points) override {
        std::vector<Vec3> const& normals = points.normals();
        m_geometry = pointGeometry(
            m_device,
            normals.empty() ? RTC_GEOMETRY_TYPE_SPHERE_POINT : RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT, points,
            points.particles());
        if (!normals.empty()) setMovingNormals(m_geometry, points, normals);
        rtcCommitGeometry(m_geometry);
    }

    void visit(SubdivisionSurface const& surface) override {
        SubdivisionData const& data = surface.data();
        m_geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_SUBDIVISION);
        copyBuffer(m_geometry, RTC_BUFFER_TYPE_FACE, RTC_FORMAT_UINT, data.faceSizes);
        copyBuffer(m_geometry, RTC_BUFFER_TYPE_INDEX, RTC_FORMAT_UINT, data.indices);
        // Embree reads each vertex as four floats and checks all four are finite:
        // a 16-byte stride with a zero fourth float keeps those reads inside the data.
        setMovingVertices<Vec4>(m_geometry, surface, motionStepCount(surface), RTC_FORMAT_FLOAT3, data.P.size(), 0,
                                [&](Vec4* vertices) {
                                    for (size_t i = 0; i < data.P.size(); ++i) vertices[i] = Vec4(data.P[i], 0.0f);
                                });
        copyBuffer(m_geometry, RTC_BUFFER_TYPE_EDGE_CREASE_INDEX, RTC_FORMAT_UINT2, data.creaseEdges, 2);
        copyBuffer(m_geometry, RTC_BUFFER_TYPE_EDGE_CREASE_WEIGHT, RTC_FORMAT_FLOAT, data.creaseWeights);
        copyBuffer(m_geometry, RTC_BUFFER_TYPE_VERTEX_CREASE_INDEX, RTC_FORMAT_UINT, data.corners);
        copyBuffer(m_geometry, RTC_BUFFER_TYPE_VERTEX_CREASE_WEIGHT, RTC_FORMAT_FLOAT, data.cornerWeights);
        if (!data.holes.empty()) {
            rtcSetGeometryUserData(m_geometry, const_cast<std::vector<unsigned>*>(&data.holes));
            rtcSetGeometryIntersectFilterFunction(m_geometry, refuseHoleHits);
            rtcSetGeometryOccludedFilterFunction(m_geometry, refuseHoleHits);
        }
        // RenderMan drops the faces along a boundary unless interpolateboundary says otherwise.
        RTCSubdivisionMode mode = data.boundary == SubdivisionData::Boundary::EdgesAndCorners ? RTC_SUBDIVISION_MODE_PIN_CORNERS
                                  : data.boundary == SubdivisionData::Boundary::Edges        ? RTC_SUBDIVISION_MODE_SMOOTH_BOUNDARY
                                                                                             : RTC_SUBDIVISION_MODE_NO_BOUNDARY;
        rtcSetGeometrySubdivisionMode(m_geometry, 0, mode);
        setPrimvars(data, mode);
        rtcSetGeometryTessellationRate(m_geometry, kTessellationRate);
        rtcCommitGeometry(m_geometry);
        surface.attach(std::make_shared<EmbreeEvaluator>(m_geometry, motionStepCount(surface)));
    }

private:
    /// A subdivision surface's primvars as vertex attributes, one slot each (in
    /// their order), each with the topology its rate calls for: vertex ones
    /// share P's; varying ones share one that is linear over every face; each
    /// facevarying one has its own, whose seams are its own.
    void setPrimvars(SubdivisionData const& data, RTCSubdivisionMode vertexMode) {
        if (data.primvars.empty()) return;
        unsigned topologies = 1, linearTopology = 0;
        std::vector<unsigned> topologyOf;
        for (SubdivisionPrimvar const& sub : data.primvars) {
            if (sub.rate == SubdivisionPrimvar::Rate::Vertex) {
                topologyOf.push_back(0);
            } else if (sub.rate == SubdivisionPrimvar::Rate::Varying) {
                if (linearTopology == 0) linearTopology = topologies++;
                topologyOf.push_back(linearTopology);
            } else {
                topologyOf.push_back(topologies++);
            }
        }
        rtcSetGeometryTopologyCount(m_geometry, topologies);
        rtcSetGeometryVertexAttributeCount(m_geometry, static_cast<unsigned>(data.primvars.size()));
        if (linearTopology != 0) {
            setIndices(linearTopology, data.indices);
            rtcSetGeometrySubdivisionMode(m_geometry, linearTopology, RTC_SUBDIVISION_MODE_PIN_ALL);
        }
        RTCSubdivisionMode const seams =
            data.faceVaryingBoundary == SubdivisionData::FaceVaryingBoundary::Smooth        ? vertexMode
            : data.faceVaryingBoundary == SubdivisionData::FaceVaryingBoundary::PinBoundary ? RTC_SUBDIVISION_MODE_PIN_BOUNDARY
            : data.faceVaryingBoundary == SubdivisionData::FaceVaryingBoundary::Linear      ? RTC_SUBDIVISION_MODE_PIN_ALL
                                                                                            : RTC_SUBDIVISION_MODE_PIN_CORNERS;
        for (size_t slot = 0; slot < data.primvars.size(); ++slot) {
            SubdivisionPrimvar const& sub = data.primvars[slot];
            unsigned const topology = topologyOf[slot];
            if (sub.rate == SubdivisionPrimvar::Rate::FaceVarying) {
                setIndices(topology, sub.cornerValues);
                rtcSetGeometrySubdivisionMode(m_geometry, topology, seams);
            }
            rtcSetGeometryVertexAttributeTopology(m_geometry, static_cast<unsigned>(slot), topology);
            // Four floats a value (Embree may read 16 bytes at any of them), up to 3 of them used.
            size_t const c = static_cast<size_t>(sub.var.components), count = sub.var.values.size() / c;
            static RTCFormat const formats[] = {RTC_FORMAT_FLOAT, RTC_FORMAT_FLOAT2, RTC_FORMAT_FLOAT3};
            auto* values = static_cast<Vec4*>(rtcSetNewGeometryBuffer(m_geometry, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE,
                                                                      static_cast<unsigned>(slot), formats[c - 1],
                                                                      sizeof(Vec4), count));
            for (size_t i = 0; i < count; ++i) {
                values[i] = Vec4(0.0f);
                for (size_t k = 0; k < c; ++k) values[i][static_cast<int>(k)] = sub.var.values[i * c + k];
            }
        }
    }
    void setIndices(unsigned topology, std::vector<unsigned> const& indices) {
        void* buffer = rtcSetNewGeometryBuffer(m_geometry, RTC_BUFFER_TYPE_INDEX, topology, RTC_FORMAT_UINT,
                                               sizeof(unsigned), indices.size());
        std::memcpy(buffer, indices.data(), indices.size() * sizeof(unsigned));
    }

    RTCDevice m_device;
    bool m_embreeSpheres;
    RTCGeometry m_geometry = nullptr;
};

}  // namespace

RTCGeometry buildEmbreeGeometry(RTCDevice device, Shape const& shape, bool embreeSpheres) {
    GeometryBuilder builder(device, embreeSpheres);
    shape.accept(builder);
    return builder.geometry();
}

}  // namespace bxdflab
