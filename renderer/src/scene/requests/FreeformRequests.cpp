// Free-form shapes: subdivision meshes, NURBS patches, blobby implicit
// surfaces, curves and points.
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>
#include <stdexcept>

#include "scene/SceneBuilder.h"
#include "scene/shapes/BlobbySurface.h"
#include "scene/shapes/CurvePrimvars.h"
#include "scene/shapes/Curves.h"
#include "scene/shapes/NurbsPrimvars.h"
#include "scene/shapes/NurbsSurface.h"
#include "scene/shapes/SubdivisionSurface.h"

namespace bxdflab {
namespace {

bool mirrors(Mat4 const& m) { return glm::determinant(Mat3(m)) < 0.0f; }

/// How much a transform scales lengths (on average): widths of curves and points follow it.
float lengthScale(Mat4 const& m) { return std::cbrt(std::fabs(glm::determinant(Mat3(m)))); }

std::vector<Vec3> worldPoints(ParamList const& params, Mat4 const& toWorld, RequestReader& in) {
    std::vector<float> const* P = params.getFloats("P", ParamType::Point);
    if (!P) in.fail(in.where(), "needs a \"P\" parameter with the vertex positions");
    std::vector<Vec3> points;
    points.reserve(P->size() / 3);
    for (size_t i = 0; i + 2 < P->size(); i += 3) points.push_back(transformPoint(toWorld, Vec3((*P)[i], (*P)[i + 1], (*P)[i + 2])));
    return points;
}

/// A normal given in object space as the unit normal in world space (`toObject` is the inverse of
/// the object-to-world transform); zero when it has no direction: zero itself, or too small or
/// too large for floats once transformed.
Vec3 worldNormal(Mat4 const& toObject, float const* n) {
    return safeNormalize(transformNormal(toObject, Vec3(n[0], n[1], n[2])));
}

/// Points' "N", in world space: one unit normal per point, or one for all of them (constant or
/// uniform). Empty when the points have none (or "N" is connected to a pattern); a normal with no
/// direction (see worldNormal) is left zero for the caller to report.
std::vector<Vec3> pointNormals(ParamList const& params, Mat4 const& toWorld, size_t points,
                               RequestReader& in) {
    std::vector<float> const* n = params.getNormals("N");
    if (!n) return {};
    size_t const given = n->size() / 3;
    if (n->size() % 3 != 0 || (given != 1 && given != points))
        in.fail(params.find("N")->location, "\"N\" needs one normal per point (" + std::to_string(points) +
                                                ") or one for all, got " + std::to_string(n->size()) +
                                                " numbers");
    Mat4 const toObject = glm::inverse(toWorld);
    std::vector<Vec3> normals;
    normals.reserve(points);
    for (size_t i = 0; i < points; ++i) {
        size_t const k = given == 1 ? 0 : 3 * i;
        normals.push_back(worldNormal(toObject, n->data() + k));
    }
    return normals;
}

/// A 4x4 matrix written row by row, as the RI specification writes bases.
using Rows = std::array<std::array<float, 4>, 4>;

Rows rowsOf(SplineBasis const& basis) {
    Rows r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[static_cast<size_t>(i)][static_cast<size_t>(j)] = basis.matrix[i][j];
    return r;
}

/// The matrix that turns a segment's control points in `basis` into Bezier
/// control points: inverse(Bezier) * basis (both act on the control points).
Rows toBezier(SplineBasis const& basis) {
    Rows bezier = rowsOf(SplineBasis::bezier()), given = rowsOf(basis);
    glm::mat4 b;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) b[j][i] = bezier[static_cast<size_t>(i)][static_cast<size_t>(j)];
    glm::mat4 inverse = glm::inverse(b);
    Rows out{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            float sum = 0.0f;
            for (int k = 0; k < 4; ++k) sum += inverse[k][i] * given[static_cast<size_t>(k)][static_cast<size_t>(j)];
            out[static_cast<size_t>(i)][static_cast<size_t>(j)] = sum;
        }
    return out;
}

}  // namespace

void SceneBuilder::subdivisionMesh(RequestReader& in) { readSubdivisionMesh(in, false); }
void SceneBuilder::hierarchicalSubdivisionMesh(RequestReader& in) { readSubdivisionMesh(in, true); }

void SceneBuilder::readSubdivisionMesh(RequestReader& in, bool hierarchical) {
    char const* request = hierarchical ? "HierarchicalSubdivisionMesh" : "SubdivisionMesh";
    std::string scheme = in.string("subdivision scheme");
    std::vector<int> nverts = in.intArray("nvertices (vertex count per face)");
    std::vector<int> verts = in.intArray("vertices (point indices)");
    // The tags and their arguments are optional: they are arrays, parameter names are not.
    std::vector<std::string> tags;
    std::vector<int> nargs, intargs;
    std::vector<float> floatargs;
    if (in.nextIsArray()) {
        tags = in.stringArray("tags");
        nargs = in.intArray("nargs (counts per tag)");
        intargs = in.intArray("intargs");
        floatargs = in.numberArray("floatargs");
        if (hierarchical) in.stringArray("stringargs");
    }
    ParamList params = in.params();
    if (nverts.empty()) {
        warnOnce("empty mesh", in.where(), std::string(request) + " with no faces; skipped");
        return;
    }
    std::vector<Vec3> P = worldPoints(params, state().transform, in);
    params.ignore("N");  // the limit surface has its own normals
    PrimvarSet vars = shapePrimvars(params);
    if (scheme == "bilinear") {
        // Flat faces: the polygons themselves, which keep the primvars that vary.
        std::vector<int> loops(nverts.size(), 1);
        MeshData mesh = buildPolygonMesh(loops, nverts, verts, params, state().transform, in.where());
        params.warnUnused(m_diagnostics, request);
        addShape(std::make_unique<TriangleMesh>(std::move(mesh), request, state().reverseOrientation), in.where(),
                 std::move(vars));
        return;
    }
    if (scheme != "catmull-clark")
        warnOnce("subdivision " + scheme, in.where(),
                 std::string(request) + " \"" + scheme + "\" is rendered with Catmull-Clark rules (the only scheme here)");

    SubdivisionData data;
    data.P = std::move(P);
    size_t total = 0;
    for (int n : nverts) {
        if (n < 3) in.fail(in.where(), "every face needs at least 3 vertices, got " + std::to_string(n));
        data.faceSizes.push_back(static_cast<unsigned>(n));
        total += static_cast<size_t>(n);
    }
    if (verts.size() != total)
        in.fail(in.where(), "the faces' vertex counts add up to " + std::to_string(total) + " but " +
                                std::to_string(verts.size()) + " vertex indices are given");
    for (int v : verts) {
        if (v < 0 || static_cast<size_t>(v) >= data.P.size())
            in.fail(in.where(), "vertex index " + std::to_string(v) + " is outside \"P\" (" + std::to_string(data.P.size()) +
                                    " points)");
        data.indices.push_back(static_cast<unsigned>(v));
    }
    PrimvarSet perFace = readSubdivisionPrimvars(params, data);
    for (Primvar& var : perFace.all()) vars.add(std::move(var));
    params.warnUnused(m_diagnostics, request);
    // Tags: each has two counts in nargs (integers, floats), or three in a
    // hierarchical mesh (integers, floats, strings), and takes them in turn.
    size_t const countsPerTag = hierarchical ? 3 : 2;
    if (nargs.size() < countsPerTag * tags.size())
        in.fail(in.where(), "nargs needs " + std::string(hierarchical ? "three" : "two") + " counts per tag (" +
                                std::to_string(countsPerTag * tags.size()) + " for " + std::to_string(tags.size()) +
                                " tags), got " + std::to_string(nargs.size()));
    size_t ints = 0, floats = 0;
    for (size_t t = 0; t < tags.size(); ++t) {
        size_t ni = static_cast<size_t>(std::max(0, nargs[countsPerTag * t]));
        size_t nf = static_cast<size_t>(std::max(0, nargs[countsPerTag * t + 1]));
        if (ints + ni > intargs.size() || floats + nf > floatargs.size())
            in.fail(in.where(), "tag \"" + tags[t] + "\" asks for more arguments than intargs/floatargs hold");
        auto vertex = [&](size_t k) {
            int v = intargs[ints + k];
            if (v < 0 || static_cast<size_t>(v) >= data.P.size()) in.fail(in.where(), "tag \"" + tags[t] + "\": vertex index out of range");
            return static_cast<unsigned>(v);
        };
        std::string const& tag = tags[t];
        if (tag == "crease" && ni >= 2 && nf >= 1) {
            for (size_t k = 0; k + 1 < ni; ++k) {
                data.creaseEdges.insert(data.creaseEdges.end(), {vertex(k), vertex(k + 1)});
                data.creaseWeights.push_back(floatargs[floats]);
            }
        } else if (tag == "corner") {
            for (size_t k = 0; k < ni; ++k) {
                data.corners.push_back(vertex(k));
                data.cornerWeights.push_back(floatargs[floats + std::min(k, nf > 0 ? nf - 1 : 0)]);
            }
        } else if (tag == "hole") {
            for (size_t k = 0; k < ni; ++k)
                if (intargs[ints + k] >= 0 && static_cast<size_t>(intargs[ints + k]) < nverts.size())
                    data.holes.push_back(static_cast<unsigned>(intargs[ints + k]));
        } else if (tag == "interpolateboundary") {
            int mode = ni > 0 ? intargs[ints] : 1;
            data.boundary = mode == 2 ? SubdivisionData::Boundary::Edges
                            : mode == 0 ? SubdivisionData::Boundary::None
                                        : SubdivisionData::Boundary::EdgesAndCorners;
        } else if (tag == "facevaryinginterpolateboundary") {
            // 0 subdivides facevarying values smoothly up to their seams; 1 (the default)
            // and 2 pin their corners; 3 pins the whole seam; more makes them linear.
            int mode = ni > 0 ? intargs[ints] : 1;
            using Seams = SubdivisionData::FaceVaryingBoundary;
            data.faceVaryingBoundary = mode <= 0 ? Seams::Smooth
                                       : mode <= 2 ? Seams::PinCorners
                                       : mode == 3 ? Seams::PinBoundary
                                                   : Seams::Linear;
        } else {
            warnOnce("subdivision tag " + tag, in.where(), std::string(request) + " tag \"" + tag + "\" is not used; skipped");
        }
        ints += ni;
        floats += nf;
    }
    std::sort(data.holes.begin(), data.holes.end());
    data.holes.erase(std::unique(data.holes.begin(), data.holes.end()), data.holes.end());
    bool flip = state().reverseOrientation != mirrors(state().transform);
    addShape(std::make_unique<SubdivisionSurface>(std::move(data), flip), in.where(), std::move(vars));
}

void SceneBuilder::nuPatch(RequestReader& in) {
    NurbsDesc d;
    d.nu = in.integer("nu");
    d.uorder = in.integer("uorder");
    d.uknot = in.numberArray("uknot");
    d.umin = in.number("umin");
    d.umax = in.number("umax");
    d.nv = in.integer("nv");
    d.vorder = in.integer("vorder");
    d.vknot = in.numberArray("vknot");
    d.vmin = in.number("vmin");
    d.vmax = in.number("vmax");
    ParamList params = in.params();
    if (d.nu < 1 || d.nv < 1 || static_cast<long>(d.nu) * d.nv > 16'000'000L)
        in.fail(in.where(), "nu and nv must be positive (and their product reasonable)");
    if (std::vector<float> const* Pw = params.getFloats("Pw", ParamType::HPoint)) {
        for (size_t i = 0; i + 3 < Pw->size(); i += 4) d.Pw.emplace_back((*Pw)[i], (*Pw)[i + 1], (*Pw)[i + 2], (*Pw)[i + 3]);
    } else if (std::vector<float> const* P = params.getFloats("P", ParamType::Point)) {
        for (size_t i = 0; i + 2 < P->size(); i += 3) d.Pw.emplace_back((*P)[i], (*P)[i + 1], (*P)[i + 2], 1.0f);
    } else {
        in.fail(in.where(), "needs \"P\" or \"Pw\" control points");
    }
    bool flip = state().reverseOrientation != mirrors(state().transform);
    MeshData mesh = buildNurbsPatch(d, state().transform, flip, in.where());
    if (state().trimLoops) mesh.trim = {state().trimLoops, state().trimKeepsOutside};
    addNurbsPrimvars(mesh, params, d);
    PrimvarSet vars = shapePrimvars(params);
    params.warnUnused(m_diagnostics, "NuPatch");
    addTessellated(std::move(mesh), "NuPatch", in, std::move(vars));
}

void SceneBuilder::trimCurve(RequestReader& in) {
    // RIB leaves out nloops: it is the length of ncurves.
    std::vector<int> const ncurves = in.intArray("ncurves");
    std::vector<int> const order = in.intArray("order");
    std::vector<float> const knot = in.numberArray("knot");
    std::vector<float> const min = in.numberArray("min"), max = in.numberArray("max");
    std::vector<int> const n = in.intArray("n");
    std::vector<float> const u = in.numberArray("u"), v = in.numberArray("v"), w = in.numberArray("w");
    in.finish();
    auto fail = [&](std::string const& why) { in.fail(in.where(), why); };
    size_t curves = 0;
    for (int c : ncurves) {
        if (c < 0 || c > 1'000'000) fail("a loop's number of curves must be between 0 and 1000000");
        curves += static_cast<size_t>(c);
    }
    if (order.size() != curves || min.size() != curves || max.size() != curves || n.size() != curves)
        fail("order, min, max and n need one value per curve (" + std::to_string(curves) + ")");
    size_t knots = 0, points = 0;
    for (size_t c = 0; c < curves; ++c) {
        if (n[c] < 1 || order[c] < 1 || n[c] > 4096 || order[c] > 64)
            fail("curve " + std::to_string(c) + " needs 1 to 4096 points and an order from 1 to 64");
        knots += static_cast<size_t>(n[c] + order[c]);
        points += static_cast<size_t>(n[c]);
    }
    if (points > 100'000) fail("at most 100000 control points in all, got " + std::to_string(points));
    if (knot.size() != knots) fail("knot needs " + std::to_string(knots) + " values, got " + std::to_string(knot.size()));
    if (u.size() != points || v.size() != points || w.size() != points)
        fail("u, v and w need one value per control point (" + std::to_string(points) + ")");
    std::vector<std::vector<TrimCurveDesc>> loops;
    size_t curve = 0, knotAt = 0, pointAt = 0;
    for (int count : ncurves) {
        std::vector<TrimCurveDesc>& loop = loops.emplace_back();
        for (int k = 0; k < count; ++k, ++curve) {
            TrimCurveDesc& c = loop.emplace_back();
            c.order = order[curve];
            c.min = min[curve];
            c.max = max[curve];
            size_t const pointCount = static_cast<size_t>(n[curve]);
            c.knots.assign(knot.begin() + static_cast<long>(knotAt),
                           knot.begin() + static_cast<long>(knotAt + pointCount + static_cast<size_t>(c.order)));
            for (size_t i = pointAt; i < pointAt + pointCount; ++i) c.uvw.emplace_back(u[i], v[i], w[i]);
            knotAt += pointCount + static_cast<size_t>(c.order);
            pointAt += pointCount;
        }
    }
    try {
        auto trim = std::make_shared<TrimLoops const>(loops);
        state().trimLoops = trim->loopCount() > 0 ? trim : nullptr;
    } catch (std::invalid_argument const& e) {
        fail(e.what());
    }
}

void SceneBuilder::blobby(RequestReader& in) {
    int leaves = in.integer("nleaf");
    std::vector<int> code = in.intArray("code");
    std::vector<float> floats = in.numberArray("floats");
    std::vector<std::string> strings = in.stringArray("strings");
    ParamList params = in.params();
    PrimvarSet vars = shapePrimvars(params);
    params.warnUnused(m_diagnostics, "Blobby");
    bool flip = state().reverseOrientation != mirrors(state().transform);
    std::string skipped;
    MeshData mesh = buildBlobby(leaves, code, floats, state().transform, flip, in.where(), skipped);
    if (!skipped.empty()) warnOnce("blobby " + skipped, in.where(), "Blobby: " + skipped + " count as a field of 0");
    if (mesh.indices.empty()) {
        warnOnce("empty blobby", in.where(), "Blobby: the field never reaches the surface threshold; nothing to draw");
        return;
    }
    addTessellated(std::move(mesh), "Blobby", in, std::move(vars));
}

void SceneBuilder::points(RequestReader& in) {
    ParamList params = in.params();
    std::vector<Vec3> P = worldPoints(params, state().transform, in);
    std::vector<float> const* widths = params.getFloats("width", ParamType::Float);
    float constantWidth = params.getFloat("constantwidth", 1.0f);
    if (widths && widths->size() != P.size())
        in.fail(in.where(), "\"width\" needs one value per point (" + std::to_string(P.size()) + "), got " +
                                std::to_string(widths->size()));
    // As in RenderMan: points with normals are disks facing them, points without are spheres.
    std::vector<Vec3> normals = pointNormals(params, state().transform, P.size(), in);
    auto const aimless = std::find(normals.begin(), normals.end(), Vec3(0.0f));
    if (aimless != normals.end()) {
        // As a Scale by 0 gives them: drawn as they would be without "N" (the warning says why).
        warnOnce("aimless point normal", params.find("N")->location,
                 "Points: \"N\" of point " + std::to_string(aimless - normals.begin()) +
                     " has no direction for a disk to face (zero, or beyond float range); these points are "
                     "drawn as spheres");
        normals.clear();
    }
    PrimvarSet vars = shapePrimvars(params, 0, P.size());  // "varying color Cs": a colour per particle
    params.warnUnused(m_diagnostics, "Points");
    if (P.empty()) return;
    float scale = lengthScale(state().transform);
    std::vector<Vec4> particles;
    particles.reserve(P.size());
    for (size_t i = 0; i < P.size(); ++i)
        particles.emplace_back(P[i], 0.5f * scale * std::fabs(widths ? (*widths)[i] : constantWidth));
    addShape(std::make_unique<Points>(std::move(particles), std::move(normals)), in.where(), std::move(vars));
}

void SceneBuilder::curves(RequestReader& in) {
    std::string type = in.string("curve type (linear or cubic)");
    std::vector<int> nverts = in.intArray("nvertices (vertex count per curve)");
    std::string wrap = in.string("wrap (periodic or nonperiodic)");
    ParamList params = in.params();
    if (type != "linear" && type != "cubic") in.fail(in.where(), "curve type must be \"linear\" or \"cubic\", not \"" + type + "\"");
    if (wrap != "periodic" && wrap != "nonperiodic") in.fail(in.where(), "wrap must be \"periodic\" or \"nonperiodic\"");
    bool const cubic = type == "cubic", periodic = wrap == "periodic";
    std::vector<Vec3> P = worldPoints(params, state().transform, in);
    // "width" is varying unless declared otherwise: one value in all (constant), one per curve
    // (uniform), one per control vertex (vertex, interpolated like P) or one per segment end.
    Param const* widthParam = params.find("width");
    std::string const widthClass = widthParam ? widthParam->decl.storageClass : "varying";
    std::vector<float> const* widths = params.getFloats("width", ParamType::Float);
    float constantWidth = params.getFloat("constantwidth", 1.0f);
    // "N" makes the curves flat ribbons facing it, as RenderMan draws them; without it they are round
    // tubes. Its storage classes read as width's do (it is varying unless declared otherwise).
    std::vector<float> const* normals = params.getNormals("N");
    Param const* normalParam = params.find("N");
    std::string const normalClass = normals ? normalParam->decl.storageClass : "varying";
    Mat4 const toObject = glm::inverse(state().transform);
    std::optional<size_t> aimless;  // the first normal with no direction, if any
    auto normalValue = [&](size_t at) {
        if (3 * at + 2 >= normals->size())
            in.fail(normalParam->location, "\"N\" has too few values for the curves (" + normalClass + ": " +
                                               std::to_string(normals->size()) + " numbers given)");
        Vec3 const n = worldNormal(toObject, normals->data() + 3 * at);
        if (n == Vec3(0.0f) && !aimless) aimless = at;
        return n;
    };
    float const scale = lengthScale(state().transform);
    int const step = cubic ? state().vBasis.step : 1;
    Rows const convert = toBezier(state().vBasis);

    CurveData data;
    data.cubic = cubic || normals;  // Embree's ribbons are Bezier curves: a linear segment is one too
    CurveLayout layout;
    layout.cubic = cubic;
    layout.periodic = periodic;
    layout.basis = state().vBasis;
    layout.curves = nverts.size();
    bool const perVertex = widthClass == "vertex";
    size_t first = 0, widthIndex = 0;
    for (size_t curve = 0; curve < nverts.size(); ++curve) {
        int const n = nverts[curve];
        int const minimum = cubic ? 4 : 2;
        if (n < minimum) in.fail(in.where(), "a " + type + " curve needs at least " + std::to_string(minimum) + " vertices");
        if (first + static_cast<size_t>(n) > P.size()) in.fail(in.where(), "the curves' vertex counts exceed \"P\"");
        int segments = cubic ? (periodic ? n / step : (n - 4) / step + 1) : (periodic ? n : n - 1);
        int varying = periodic ? segments : segments + 1;  // varying widths per curve
        auto widthValue = [&](size_t at) {
            if (at >= widths->size())
                in.fail(in.where(), "\"width\" has too few values for the curves (" + widthClass + ": " +
                                        std::to_string(widths->size()) + " given)");
            return 0.5f * scale * std::fabs((*widths)[at]);
        };
        // Control vertex k of this curve, as an index into a vertex value ("P", vertex width or N).
        auto vertexAt = [&](int k) { return first + static_cast<size_t>(periodic ? k % n : k); };
        // Where a value of storage class `storage` for the start of segment k sits (k = segments:
        // the end of the last one).
        auto segmentStart = [&](std::string const& storage, int k) -> size_t {
            if (storage == "constant") return 0;
            if (storage == "uniform") return curve;
            if (storage == "vertex") return vertexAt(k * step);
            return widthIndex + static_cast<size_t>(periodic ? k % varying : k);
        };
        auto radius = [&](int k) {
            return widths ? widthValue(segmentStart(widthClass, k)) : 0.5f * scale * std::fabs(constantWidth);
        };
        auto vertexRadius = [&](int k) { return widthValue(vertexAt(k)); };
        auto point = [&](int k) { return P[vertexAt(k)]; };
        bool const normalPerVertex = normalClass == "vertex";
        auto normalAt = [&](int k) { return normalValue(segmentStart(normalClass, k)); };
        auto vertexNormal = [&](int k) { return normalValue(vertexAt(k)); };
        for (int s = 0; s < segments; ++s) {
            data.segments.push_back(static_cast<unsigned>(data.points.size()));
            layout.segments.push_back({static_cast<unsigned>(curve), static_cast<unsigned>(s),
                                       static_cast<unsigned>(first), static_cast<unsigned>(n),
                                       static_cast<unsigned>(widthIndex), static_cast<unsigned>(varying)});
            if (!cubic && !normals) {
                data.points.emplace_back(point(s), radius(s));
                data.points.emplace_back(point(s + 1), radius(s + 1));
                continue;
            }
            if (!cubic) {  // a ribbon's straight segment, as the Bezier segment with its points a third apart
                Vec3 const n0 = normalAt(s), n1 = normalAt(s + 1);
                for (int i = 0; i < 4; ++i) {
                    float const f = static_cast<float>(i) / 3.0f;
                    data.points.emplace_back(point(s) + f * (point(s + 1) - point(s)),
                                             radius(s) + f * (radius(s + 1) - radius(s)));
                    data.normals.push_back(n0 + f * (n1 - n0));
                }
                continue;
            }
            // Per-vertex widths go through the basis as P does; the others run linearly along the segment.
            float const r0 = perVertex ? 0.0f : radius(s), r1 = perVertex ? 0.0f : radius(s + 1);
            Vec3 G[4];
            float Gr[4] = {0.0f, 0.0f, 0.0f, 0.0f};
            for (int m = 0; m < 4; ++m) {
                G[m] = point(s * step + m);
                if (perVertex) Gr[m] = vertexRadius(s * step + m);
            }
            for (int i = 0; i < 4; ++i) {
                Vec3 c(0.0f);
                float r = 0.0f;
                for (int m = 0; m < 4; ++m) {
                    float const weight = convert[static_cast<size_t>(i)][static_cast<size_t>(m)];
                    c += weight * G[m];
                    r += weight * Gr[m];
                }
                if (!perVertex) r = r0 + (r1 - r0) * static_cast<float>(i) / 3.0f;
                data.points.emplace_back(c, std::fabs(r));
            }
            if (!normals) continue;
            // Per-vertex normals go through the basis as P does; the others run linearly along the segment.
            Vec3 const n0 = normalPerVertex ? Vec3(0.0f) : normalAt(s),
                       n1 = normalPerVertex ? Vec3(0.0f) : normalAt(s + 1);
            for (int i = 0; i < 4; ++i) {
                Vec3 normal = n0 + (n1 - n0) * (static_cast<float>(i) / 3.0f);
                if (normalPerVertex) {
                    normal = Vec3(0.0f);
                    for (int m = 0; m < 4; ++m)
                        normal += convert[static_cast<size_t>(i)][static_cast<size_t>(m)] *
                                  vertexNormal(s * step + m);
                }
                data.normals.push_back(normal);
            }
        }
        first += static_cast<size_t>(n);
        widthIndex += static_cast<size_t>(varying);
    }
    if (aimless) {  // as a Scale by 0 gives them: round tubes, as without "N" (the warning says why)
        warnOnce("aimless curve normal", normalParam->location,
                 "Curves: \"N\" value " + std::to_string(*aimless) +
                     " has no direction for a ribbon to face (zero, or beyond float range); these curves are "
                     "drawn as round tubes");
        data.normals.clear();
    }
    layout.vertices = first;
    layout.varyings = widthIndex;
    PrimvarSet alongCurves;
    addCurvePrimvars(alongCurves, params, std::move(layout));
    PrimvarSet constants = shapePrimvars(params);
    params.warnUnused(m_diagnostics, "Curves");
    if (data.segments.empty()) return;
    addShape(std::make_unique<Curves>(std::move(data), std::move(alongCurves)), in.where(),
             std::move(constants));
}

}  // namespace bxdflab
