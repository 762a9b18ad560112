// Shapes: the quadrics (intersected exactly), polygons and meshes, patches,
// and the Geometry request. Each becomes a Shape in world space with the
// material and visibility in effect.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/SceneBuilder.h"
#include "scene/shapes/MeshBuilders.h"
#include "scene/shapes/Quadrics.h"

namespace bxdflab {
namespace {

bool mirrors(Mat4 const& m) { return glm::determinant(Mat3(m)) < 0.0f; }

/// A patch's control points, nu x nv of them, from "P", "Pw" (divided by w) or
/// "Pz" (a height field: x and y run evenly over [0, 1] across the mesh).
std::vector<Vec3> patchPoints(ParamList const& params, RequestReader& in, int nu, int nv) {
    std::vector<Vec3> points;
    if (std::vector<float> const* P = params.getFloats("P", ParamType::Point)) {
        if (P->empty() || P->size() % 3 != 0) in.fail(in.where(), "needs a \"P\" parameter with control points");
        for (size_t i = 0; i + 2 < P->size(); i += 3) points.emplace_back((*P)[i], (*P)[i + 1], (*P)[i + 2]);
    } else if (std::vector<float> const* Pw = params.getFloats("Pw", ParamType::HPoint)) {
        for (size_t i = 0; i + 3 < Pw->size(); i += 4) {
            float const w = (*Pw)[i + 3];
            if (w == 0.0f) in.fail(in.where(), "\"Pw\" has a control point with w = 0");
            points.emplace_back((*Pw)[i] / w, (*Pw)[i + 1] / w, (*Pw)[i + 2] / w);
        }
    } else if (std::vector<float> const* Pz = params.getFloats("Pz", ParamType::Float)) {
        if (nu < 2 || nv < 2 || Pz->size() != static_cast<size_t>(nu) * static_cast<size_t>(nv))
            in.fail(in.where(), "\"Pz\" needs one height per control point (" + std::to_string(nu) + " x " + std::to_string(nv) +
                                    "), got " + std::to_string(Pz->size()));
        for (int v = 0; v < nv; ++v)
            for (int u = 0; u < nu; ++u)
                points.emplace_back(static_cast<float>(u) / static_cast<float>(nu - 1),
                                    static_cast<float>(v) / static_cast<float>(nv - 1),
                                    (*Pz)[static_cast<size_t>(v) * static_cast<size_t>(nu) + static_cast<size_t>(u)]);
    }
    if (points.empty()) in.fail(in.where(), "needs control points: a \"P\", \"Pw\" or \"Pz\" parameter");
    return points;
}

/// A bilinear patch's "N": one normal per control point (vertex and varying
/// are the same there), or nothing when the patch has none.
std::optional<std::vector<Vec3>> bilinearNormals(ParamList const& params, RequestReader& in, size_t points) {
    std::vector<float> const* n = params.getNormals("N");
    if (!n) return std::nullopt;
    if (n->size() != 3 * points)
        in.fail(params.find("N")->location, "\"N\" needs one normal per control point (" +
                                                std::to_string(points) + "), got " +
                                                std::to_string(n->size()) + " numbers");
    std::vector<Vec3> normals;
    for (size_t i = 0; i < points; ++i) normals.emplace_back((*n)[3 * i], (*n)[3 * i + 1], (*n)[3 * i + 2]);
    return normals;
}

/// A quadric's radius may be negative: the RI specification turns the surface
/// inside out then, which is the positive radius with the normals reversed.
float radiusOf(float value, bool& reverse) {
    if (value < 0.0f) reverse = !reverse;
    return std::fabs(value);
}

}  // namespace

void SceneBuilder::addShape(std::unique_ptr<Shape> shape, SourceLocation const& where, PrimvarSet constants) {
    if (!m_inWorld) {
        if (m_framesDone > 0) throw RibError(where, "geometry after WorldEnd: shapes must come between WorldBegin and WorldEnd");
        // Read through an archive, the file given to the renderer is the archive to name.
        std::string const archive = m_fileStack.size() > 1 ? "\"" + m_fileStack.front() + "\", which reads this file outside "
                                                               "any world, is itself an archive"
                                                             : "a file of shapes without a world is an archive";
        throw RibError(where, "geometry before any WorldBegin: " + archive + " (read it from a scene with ReadArchive)");
    }
    if (!building()) return;
    if (state().outsideDetailRange) {
        ++m_shapesOutsideDetail;
        return;
    }
    if (m_motion && m_motion->current >= 0) {  // one time of a motion block: kept until its MotionEnd
        m_motion->shapes.back().push_back({std::move(shape), where, std::move(constants)});
        return;
    }
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(state().transform[i][j])) throw RibError(where, "the current transform is not finite");
    if (auto const* mesh = dynamic_cast<TriangleMesh const*>(shape.get()))
        for (Vec3 const& p : mesh->data().P)
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw RibError(where, std::string("a point of this ") + shape->kind() +
                                          " is not finite once transformed to world space (values near the float limit?)");
    for (Primvar& var : constants.all())
        if (!shape->primvars.find(var.name)) shape->primvars.add(std::move(var));
    // TextureCoordinates map the parameters of parametric surfaces (not polygons) to s and t.
    std::string const kind = shape->kind();
    bool const polygonal = kind == "Polygon" || kind == "GeneralPolygon" || kind == "PointsPolygons" ||
                           kind == "PointsGeneralPolygons" || kind == "SubdivisionMesh";
    if (state().textureCoordinatesSet && !polygonal) {
        shape->hasTextureCoordinates = true;
        std::copy(state().textureCoordinates.begin(), state().textureCoordinates.end(), shape->textureCoordinates);
    }
    shape->visibility = state().visibility;
    shape->traceDepth = state().traceDepth;
    // Curves and points face the ray they are seen by: they have no back to hide.
    shape->oneSided = !state().twoSided && kind != "Curves" && kind != "Points";
    shape->name = state().name;
    shape->where = where;
    shape->objectToWorld = state().transform;
    // (A deforming shape has the transform's motion in its points already.)
    if (state().motion && !shape->deformation())
        shape->motion = shapeMotion(*state().motion, m_scene.shutterOpen, m_scene.shutterClose);
    // Polygons under an area light are the light (seen by the rays its visibility allows).
    if (meshAsLight(*shape)) return;
    if (state().volume) {
        m_scene.dropped.push_back(std::string(shape->kind()) + " at " + where.str() + " holds a volume (PxrVolume)");
        return;
    }
    if (!shape->visibility.any()) {
        m_scene.dropped.push_back(std::string(shape->kind()) + " at " + where.str() + " is invisible to every ray type");
        return;
    }
    ++m_worldShapes;
    LightsOff off{{}, m_listedLights, state().lightingSubset, state().lightingExclude};
    for (auto& [handle, use] : m_lightUse) {
        bool on = !state().lightsOff.count(handle) && (!use.listed || state().lightList.count(handle));
        ++(on ? use.shapesOn : use.shapesOff);
        if (!on) off.handles.push_back(handle);  // in handle order: the map is sorted
    }
    auto [known, added] = m_lightsOffIndex.emplace(off, static_cast<int>(m_lightsOff.size()));
    if (added) m_lightsOff.push_back(std::move(off));
    shape->lightLink = known->second;
    // Under an area light the shape glows; else a Bxdf wins over a classic
    // Surface shader (RenderMan's RIS ignores Surface).
    // A shape with its own colours (a "Cs" primvar) and no material gets the
    // classic matte shader, which reads them.
    if (state().areaLight)
        shape->material = emissiveMaterial(where);
    else if (state().material >= 0)
        shape->material = state().material;
    else if (state().surface)
        shape->material = classicMaterial();
    else if (shape->primvars.find("Cs"))
        shape->material = primvarColorMaterial();
    else
        shape->material = defaultMaterial();
    for (Primvar const& var : shape->primvars.all()) m_scene.primvarNames.insert(var.name);
    m_scene.shapes.push_back(std::move(shape));
}

SceneBuilder::QuadricRequest SceneBuilder::readQuadric(RequestReader& in, char const* request, int count,
                                                      char const* arguments, int radiusArgument) {
    QuadricRequest q;
    q.v = in.numbers(static_cast<size_t>(count), arguments);
    ParamList params = in.params();
    q.primvars = shapePrimvars(params, 4);
    params.warnUnused(m_diagnostics, request);
    q.reverse = state().reverseOrientation;
    if (radiusArgument >= 0) q.radius = radiusOf(q.v[static_cast<size_t>(radiusArgument)], q.reverse);
    return q;
}

void SceneBuilder::skipWithoutSurface(RequestReader& in, char const* request, char const* why) {
    warnOnce(std::string("no surface ") + request, in.where(),
             std::string(request) + " with " + why + " describes no surface; skipped");
}

void SceneBuilder::sphere(RequestReader& in) {
    QuadricRequest q = readQuadric(in, "Sphere", 4, "radius zmin zmax thetamax", 0);
    std::vector<float> const& v = q.v;
    if (!(q.radius > 0.0f)) return skipWithoutSurface(in, "Sphere", "radius 0");
    bool whole = v[1] <= -q.radius && v[2] >= q.radius && v[3] >= 360.0f;
    if (whole && shapeAsLight("PxrSphereLight", glm::scale(state().transform, Vec3(2.0f * q.radius)))) return;
    addShape(std::make_unique<Sphere>(q.radius, v[1], v[2], v[3], state().transform, q.reverse), in.where(),
             std::move(q.primvars));
}

void SceneBuilder::cylinder(RequestReader& in) {
    QuadricRequest q = readQuadric(in, "Cylinder", 4, "radius zmin zmax thetamax", 0);
    std::vector<float> const& v = q.v;
    if (!(q.radius > 0.0f)) return skipWithoutSurface(in, "Cylinder", "radius 0");
    addShape(std::make_unique<Cylinder>(q.radius, v[1], v[2], v[3], state().transform, q.reverse), in.where(),
             std::move(q.primvars));
}

void SceneBuilder::disk(RequestReader& in) {
    QuadricRequest q = readQuadric(in, "Disk", 3, "height radius thetamax", 1);
    std::vector<float> const& v = q.v;
    if (!(q.radius > 0.0f)) return skipWithoutSurface(in, "Disk", "radius 0");
    Mat4 diskLight = glm::scale(glm::translate(state().transform, Vec3(0.0f, 0.0f, v[0])),
                                Vec3(2.0f * q.radius, 2.0f * q.radius, 1.0f));
    if (q.reverse) diskLight = glm::scale(diskLight, Vec3(1.0f, -1.0f, -1.0f));  // it emits the other way
    if (v[2] >= 360.0f && shapeAsLight("PxrDiskLight", diskLight)) return;
    addShape(std::make_unique<Disk>(v[0], q.radius, v[2], state().transform, q.reverse), in.where(),
             std::move(q.primvars));
}

void SceneBuilder::cone(RequestReader& in) {
    QuadricRequest q = readQuadric(in, "Cone", 3, "height radius thetamax", 1);
    std::vector<float> const& v = q.v;
    if (!(q.radius > 0.0f)) return skipWithoutSurface(in, "Cone", "radius 0");
    if (v[0] == 0.0f) {
        // A cone of height 0 is the disk it stands on, point for point and (u, v) for (u, v).
        addShape(std::make_unique<Disk>(0.0f, q.radius, v[2], state().transform, q.reverse), in.where(),
                 std::move(q.primvars));
        return;
    }
    addShape(std::make_unique<Cone>(v[0], q.radius, v[2], state().transform, q.reverse), in.where(),
             std::move(q.primvars));
}

void SceneBuilder::paraboloid(RequestReader& in) {
    QuadricRequest q = readQuadric(in, "Paraboloid", 4, "rmax zmin zmax thetamax", 0);
    std::vector<float> const& v = q.v;
    if (!(q.radius > 0.0f)) return skipWithoutSurface(in, "Paraboloid", "rmax 0");
    // The surface runs from z = 0 up to zmax; a span that never rises above 0 holds none of it.
    if (!(std::max(v[1], v[2]) > 0.0f)) return skipWithoutSurface(in, "Paraboloid", "no z above 0");
    addShape(std::make_unique<Paraboloid>(q.radius, v[1], v[2], v[3], state().transform, q.reverse), in.where(),
             std::move(q.primvars));
}

void SceneBuilder::hyperboloid(RequestReader& in) {
    QuadricRequest q = readQuadric(in, "Hyperboloid", 7, "point1 point2 thetamax", -1);
    std::vector<float> const& v = q.v;
    if (v[2] == v[5] && v[0] == v[3] && v[1] == v[4])
        return skipWithoutSurface(in, "Hyperboloid", "both points the same");
    addShape(std::make_unique<Hyperboloid>(Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5]), v[6], state().transform,
                                           q.reverse),
             in.where(), std::move(q.primvars));
}

void SceneBuilder::addTessellated(MeshData mesh, char const* request, RequestReader& in, PrimvarSet primvars) {
    addShape(std::make_unique<TriangleMesh>(std::move(mesh), request, false), in.where(), std::move(primvars));
}

void SceneBuilder::torus(RequestReader& in) {
    QuadricRequest q = readQuadric(in, "Torus", 5, "majorrad minorrad phimin phimax thetamax", -1);
    std::vector<float> const& v = q.v;
    if (v[0] == 0.0f || v[1] == 0.0f) return skipWithoutSurface(in, "Torus", "a radius 0");
    if (!(v[0] > 0.0f) || !(v[1] > 0.0f)) in.fail(in.where(), "radii must be positive");
    bool flip = state().reverseOrientation != mirrors(state().transform);
    addTessellated(buildTorus(v[0], v[1], v[2], v[3], v[4], state().transform, flip), "Torus", in,
                   std::move(q.primvars));
}

void SceneBuilder::addPolygonMesh(char const* request, std::vector<int> const& loops, std::vector<int> const& nverts,
                                  std::vector<int> const& verts, ParamList& params, RequestReader& in) {
    MeshData mesh = buildPolygonMesh(loops, nverts, verts, params, state().transform, in.where());
    PrimvarSet vars = shapePrimvars(params);
    params.warnUnused(m_diagnostics, request);
    addShape(std::make_unique<TriangleMesh>(std::move(mesh), request, state().reverseOrientation), in.where(),
             std::move(vars));
}

void SceneBuilder::polygon(RequestReader& in) {
    ParamList params = in.params();
    std::vector<float> const* P = params.getFloats("P", ParamType::Point);
    if (!P) in.fail(in.where(), "needs a \"P\" parameter with the vertex positions");
    int count = static_cast<int>(P->size() / 3);
    if (count < 3) return skipWithoutSurface(in, "Polygon", "fewer than 3 vertices");
    std::vector<int> indices(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) indices[static_cast<size_t>(i)] = i;
    addPolygonMesh("Polygon", {1}, {count}, indices, params, in);
}

void SceneBuilder::generalPolygon(RequestReader& in) {
    std::vector<int> nverts = in.intArray("nvertices (vertex count per loop)");
    ParamList params = in.params();
    long total = 0;
    for (int n : nverts) {
        if (n < 3) in.fail(in.where(), "every loop needs at least 3 vertices, got " + std::to_string(n));
        total += n;
    }
    std::vector<float> const* P = params.getFloats("P", ParamType::Point);
    if (!P || static_cast<long>(P->size() / 3) != total)
        in.fail(in.where(), "needs a \"P\" parameter with " + std::to_string(total) + " points (the loops' vertex counts added up)");
    std::vector<int> indices(static_cast<size_t>(total));
    for (long i = 0; i < total; ++i) indices[static_cast<size_t>(i)] = static_cast<int>(i);
    addPolygonMesh("GeneralPolygon", {static_cast<int>(nverts.size())}, nverts, indices, params, in);
}

void SceneBuilder::warnEmptyMesh(char const* request, RequestReader& in) {
    warnOnce("empty mesh", in.where(), std::string(request) + " with no polygons; skipped");
}

void SceneBuilder::pointsPolygons(RequestReader& in) {
    std::vector<int> nverts = in.intArray("nvertices (vertex count per face)");
    std::vector<int> verts = in.intArray("vertices (point indices)");
    ParamList params = in.params();
    if (nverts.empty()) return warnEmptyMesh("PointsPolygons", in);
    if (std::any_of(nverts.begin(), nverts.end(), [](int n) { return n >= 0 && n < 3; }))
        skipWithoutSurface(in, "PointsPolygons",
                           "a face of fewer than 3 vertices");  // that face; the rest is drawn
    std::vector<int> loops(nverts.size(), 1);
    addPolygonMesh("PointsPolygons", loops, nverts, verts, params, in);
}

void SceneBuilder::pointsGeneralPolygons(RequestReader& in) {
    std::vector<int> nloops = in.intArray("nloops (loop count per face)");
    std::vector<int> nverts = in.intArray("nvertices (vertex count per loop)");
    std::vector<int> verts = in.intArray("vertices (point indices)");
    ParamList params = in.params();
    if (nloops.empty()) return warnEmptyMesh("PointsGeneralPolygons", in);
    addPolygonMesh("PointsGeneralPolygons", nloops, nverts, verts, params, in);
}

void SceneBuilder::patch(RequestReader& in) {
    std::string type = in.string("patch type");
    ParamList params = in.params();
    int const side = type == "bicubic" ? 4 : 2;
    std::vector<Vec3> points = patchPoints(params, in, side, side);
    std::optional<std::vector<Vec3>> normals;
    if (type == "bilinear") normals = bilinearNormals(params, in, 4);
    PrimvarSet vars = shapePrimvars(params);
    bool flip = state().reverseOrientation != mirrors(state().transform);
    MeshData mesh;
    // A patch is a mesh of one patch: its primvars are laid out as a patch mesh's.
    if (type == "bilinear") {
        if (points.size() != 4) in.fail(in.where(), "a bilinear patch needs \"P\" with exactly 4 points");
        mesh = buildBilinearPatchMesh(points, 2, false, 2, false, state().transform, flip, in.where(),
                                      normals ? &*normals : nullptr, &params);
    } else if (type == "bicubic") {
        if (points.size() != 16) in.fail(in.where(), "a bicubic patch needs \"P\" with exactly 16 points");
        mesh = buildBicubicPatchMesh(points, 4, false, 4, false, state().uBasis, state().vBasis, state().transform, flip,
                                     in.where(), &params);
    } else {
        in.fail(in.where(), "unknown patch type \"" + type + "\" (bilinear or bicubic)");
    }
    params.warnUnused(m_diagnostics, "Patch");
    addTessellated(std::move(mesh), "Patch", in, std::move(vars));
}

void SceneBuilder::patchMesh(RequestReader& in) {
    std::string type = in.string("patch type");
    int nu = in.integer("nu");
    std::string uwrap = in.string("uwrap");
    int nv = in.integer("nv");
    std::string vwrap = in.string("vwrap");
    ParamList params = in.params();
    std::vector<Vec3> points = patchPoints(params, in, nu, nv);
    std::optional<std::vector<Vec3>> normals;
    if (type == "bilinear") normals = bilinearNormals(params, in, points.size());
    PrimvarSet vars = shapePrimvars(params);
    bool flip = state().reverseOrientation != mirrors(state().transform);
    MeshData mesh;
    if (type == "bicubic")
        mesh = buildBicubicPatchMesh(points, nu, uwrap == "periodic", nv, vwrap == "periodic", state().uBasis,
                                     state().vBasis, state().transform, flip, in.where(), &params);
    else if (type == "bilinear")
        mesh = buildBilinearPatchMesh(points, nu, uwrap == "periodic", nv, vwrap == "periodic", state().transform, flip,
                                      in.where(), normals ? &*normals : nullptr, &params);
    else
        in.fail(in.where(), "unknown patch type \"" + type + "\" (bilinear or bicubic)");
    params.warnUnused(m_diagnostics, "PatchMesh");
    addTessellated(std::move(mesh), "PatchMesh", in, std::move(vars));
}

void SceneBuilder::geometry(RequestReader& in) {
    std::string type = in.string("geometry type");
    ParamList params = in.params();
    // RenderMan 20's light shapes, for the AreaLightSource in effect.
    if (type == "spherelight" || type == "envsphere" || type == "disklight" || type == "rectlight" ||
        type == "distantlight") {
        float diameter = 2.0f * params.getFloat("radius", 0.5f);
        // A distant light's angular size; RenderMan for Maya 20 writes -1 for the default (the sun's).
        ParamList shape;
        if (float angle = params.getFloat("anglesubtended", -1.0f); angle > 0.0f)
            shape.add(floatParam("angleExtent", angle));
        params.warnUnused(m_diagnostics, "Geometry \"" + type + "\"");
        if (!state().areaLight) {
            warnOnce("geometry " + type, in.where(), "Geometry \"" + type + "\" outside an AreaLightSource block; skipped");
            return;
        }
        // An envsphere is the environment whatever the shader (RenderMan for Maya 20 names it after its node).
        char const* light = type == "rectlight"      ? "PxrRectLight"
                            : type == "disklight"    ? "PxrDiskLight"
                            : type == "envsphere"    ? "PxrDomeLight"
                            : type == "distantlight" ? "PxrDistantLight"
                                                     : "PxrSphereLight";
        bool const sized = type == "spherelight" || type == "disklight" || type == "rectlight";
        Mat4 scaled = sized ? glm::scale(state().transform, Vec3(diameter)) : state().transform;
        if (!shapeAsLight(light, scaled, shape))
            warnOnce("geometry " + type, in.where(), "Geometry \"" + type + "\": no light made; skipped");
        return;
    }
    if (type != "teapot") {
        warnOnce("geometry " + type, in.where(), "Geometry \"" + type + "\" is not supported; skipped");
        return;
    }
    PrimvarSet vars = shapePrimvars(params);
    params.warnUnused(m_diagnostics, "Geometry \"teapot\"");
    bool flip = state().reverseOrientation != mirrors(state().transform);
    addTessellated(buildTeapot(state().transform, flip), "teapot", in, std::move(vars));
}

}  // namespace bxdflab
