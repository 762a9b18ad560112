#include "scene/shapes/MeshBuilders.h"

#include <algorithm>
#include <functional>
#include <numeric>

#include "scene/shapes/PatchPrimvars.h"
#include "scene/shapes/TeapotData.h"
#include "scene/shapes/Triangulation.h"

namespace bxdflab {
namespace {

/// Reads one item of a primvar whatever its storage class.
class CornerReader {
public:
    CornerReader(Param const* param, int components) : m_param(param), m_components(components) {}
    bool present() const { return m_param != nullptr; }
    /// The value for a corner of face `face`, which is vertex `vertex` of the
    /// point list and the `corner`-th corner of the whole mesh.
    float const* at(int face, int corner, int vertex) const {
        std::string const& cls = m_param->decl.storageClass;
        size_t index = cls == "facevarying" || cls == "facevertex" ? static_cast<size_t>(corner)
                       : cls == "uniform"                          ? static_cast<size_t>(face)
                       : cls == "constant"                         ? 0
                                                                   : static_cast<size_t>(vertex);
        size_t offset = index * static_cast<size_t>(m_components);
        if (offset + static_cast<size_t>(m_components) > m_param->floats.size())
            throw RibError(m_param->location, "primvar \"" + m_param->name() + "\" (" +
                                                  (cls.empty() ? std::string("vertex") : cls) + ") has too few values");
        return &m_param->floats[offset];
    }

private:
    Param const* m_param;
    int m_components;
};

using SurfaceFunction = std::function<void(float u, float v, Vec3& P, Vec3& dPdu, Vec3& dPdv)>;

/// A parametric surface sampled on an (nu+1) x (nv+1) grid, in its own space.
/// Sampling is the costly half of tessellation; a surface used again and again
/// (the teapot's patches) keeps its grid and is only placed each time.
struct SurfaceGrid {
    int nu = 0, nv = 0;
    std::vector<Vec3> P, dPdu, dPdv;
    /// The derivatives a small step inside the patch, for the normal where an
    /// edge collapses (the teapot's lid apex, a pole).
    std::vector<Vec3> insideDu, insideDv;
};

SurfaceGrid sampleSurface(int nu, int nv, SurfaceFunction const& surface) {
    SurfaceGrid grid;
    grid.nu = nu;
    grid.nv = nv;
    size_t const count = static_cast<size_t>(nu + 1) * static_cast<size_t>(nv + 1);
    for (auto* values : {&grid.P, &grid.dPdu, &grid.dPdv, &grid.insideDu, &grid.insideDv}) values->reserve(count);
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i) {
            float u = static_cast<float>(i) / nu, v = static_cast<float>(j) / nv;
            Vec3 P, dPdu, dPdv, insideP, insideDu, insideDv;
            surface(u, v, P, dPdu, dPdv);
            surface(u + (u < 0.5f ? 1e-3f : -1e-3f), v + (v < 0.5f ? 1e-3f : -1e-3f), insideP, insideDu, insideDv);
            grid.P.push_back(P);
            grid.dPdu.push_back(dPdu);
            grid.dPdv.push_back(dPdv);
            grid.insideDu.push_back(insideDu);
            grid.insideDv.push_back(insideDv);
        }
    return grid;
}

/// Appends a sampled surface to `mesh`, transformed to world space.
void placeGrid(MeshData& mesh, SurfaceGrid const& grid, Mat4 const& toWorld, bool flip) {
    Mat3 linear(toWorld);
    float sign = flip ? -1.0f : 1.0f;
    unsigned base = static_cast<unsigned>(mesh.P.size());
    int const nu = grid.nu, nv = grid.nv;
    size_t k = 0;
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i, ++k) {
            float u = static_cast<float>(i) / nu, v = static_cast<float>(j) / nv;
            Vec3 worldDu = linear * grid.dPdu[k], worldDv = linear * grid.dPdv[k];
            Vec3 n = glm::cross(worldDu, worldDv);
            if (glm::length(n) < 1e-6f * (glm::length(worldDu) + glm::length(worldDv) + 1e-12f))
                n = glm::cross(linear * grid.insideDu[k], linear * grid.insideDv[k]);  // a collapsed edge
            mesh.P.push_back(transformPoint(toWorld, grid.P[k]));
            mesh.N.push_back(sign * safeNormalize(n));
            mesh.uv.emplace_back(u, v);
            mesh.dPdu.push_back(worldDu);
            mesh.dPdv.push_back(worldDv);
        }
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            unsigned a = base + static_cast<unsigned>(j * (nu + 1) + i);
            unsigned b = a + 1, c = a + static_cast<unsigned>(nu + 1), d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
        }
}

/// Samples a parametric surface on an (nu+1) x (nv+1) grid into `mesh`.
void tessellate(MeshData& mesh, int nu, int nv, SurfaceFunction const& surface, Mat4 const& toWorld, bool flip) {
    placeGrid(mesh, sampleSurface(nu, nv, surface), toWorld, flip);
}

/// A polygon's (u, v) where its RIB gives no texture coordinates: as in RenderMan, each face
/// has its own. A quad's run from 0 to 1 across it, corner by corner in the order written
/// ((0, 0), (1, 0), (1, 1), (0, 1)), so that a ramp or checker through (s, t) lies straight
/// on it; a triangle's are its barycentric coordinates, its corners as written at (0, 0),
/// (1, 0) and (0, 1); a larger face's, or one with holes, each of its triangles' own
/// (corner `cornerInTriangle` of the triangle there).
Vec2 faceParameters(size_t faceCorners, size_t faceLoops, int cornerInFace, size_t cornerInTriangle) {
    static Vec2 const quad[4] = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
    static Vec2 const triangle[3] = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)};
    if (faceLoops == 1 && faceCorners == 4) return quad[cornerInFace];
    if (faceLoops == 1 && faceCorners == 3) return triangle[cornerInFace];
    return triangle[cornerInTriangle];
}

}  // namespace

MeshData buildPolygonMesh(std::vector<int> const& loopsPerFace, std::vector<int> const& verticesPerLoop,
                          std::vector<int> const& vertexIndices, ParamList const& params, Mat4 const& toWorld,
                          SourceLocation const& where) {
    Param const* P = params.take("P");
    if (!P) throw RibError(where, "polygon needs a \"P\" primvar with its vertex positions");
    if (P->decl.type != ParamType::Point && P->decl.type != ParamType::Float && P->decl.type != ParamType::Vector)
        throw RibError(P->location, "\"P\" must be of type point");
    size_t numPoints = P->floats.size() / 3;
    if (P->floats.size() % 3 != 0) throw RibError(P->location, "\"P\" needs three numbers per point");

    Param const* normals = params.take("N");
    if (normals && normals->decl.type != ParamType::Normal && normals->decl.type != ParamType::Vector)
        throw RibError(normals->location, "\"N\" must be of type normal");
    Param const* st = params.take("st");
    Param const* s = params.take("s");
    Param const* t = params.take("t");
    CornerReader normalVar(normals, 3), stVar(st, 2), sVar(s, 1), tVar(t, 1);
    // Primvars that vary over the mesh (one value per shape is the shape's constant primvar).
    struct Varying {
        Param const* param;
        CornerReader reader;
        Primvar out;
    };
    std::vector<Varying> varying;
    for (Param const& p : params.all()) {
        int components = primvarComponents(p);
        if (components == 0 || isGeometryParameter(p.name()) || p.floats.size() <= static_cast<size_t>(components)) continue;
        Primvar out;
        out.name = p.name();
        out.type = p.decl.type;
        out.components = components;
        out.detail = p.decl.storageClass == "uniform" ? Primvar::Detail::Uniform : Primvar::Detail::Varying;
        p.used = true;
        varying.push_back({&p, CornerReader(&p, components), std::move(out)});
    }
    bool hasSt = st || (s && t);

    Mat4 normalMatrix = glm::inverse(toWorld);
    bool mirrored = glm::determinant(Mat3(toWorld)) < 0.0f;
    MeshData mesh;
    size_t loopCursor = 0, cornerCursor = 0;
    for (size_t face = 0; face < loopsPerFace.size(); ++face) {
        int loops = loopsPerFace[face];
        if (loops < 1) throw RibError(where, "face " + std::to_string(face) + " has no loops");
        if (loopCursor + static_cast<size_t>(loops) > verticesPerLoop.size())
            throw RibError(where, "more loops than vertex counts (nloops and nverts disagree)");
        // The face's corners (every loop's), and each loop as indices into them.
        std::vector<Vec3> corners;
        std::vector<int> pointIndex;
        std::vector<std::vector<int>> faceLoops;
        size_t const firstCorner = cornerCursor;
        for (int loop = 0; loop < loops; ++loop) {
            int count = verticesPerLoop[loopCursor + static_cast<size_t>(loop)];
            if (count < 0 || cornerCursor + static_cast<size_t>(count) > vertexIndices.size())
                throw RibError(where, "vertex counts add up to more indices than were given");
            if (corners.size() + static_cast<size_t>(count) > kMaxFaceVertices)
                throw RibError(where, "face " + std::to_string(face) + " has more than " + std::to_string(kMaxFaceVertices) +
                                          " vertices");
            faceLoops.emplace_back();
            for (int k = 0; k < count; ++k) {
                int vi = vertexIndices[cornerCursor + static_cast<size_t>(k)];
                if (vi < 0 || static_cast<size_t>(vi) >= numPoints)
                    throw RibError(where, "vertex index " + std::to_string(vi) + " is out of range (there are " +
                                              std::to_string(numPoints) + " points)");
                faceLoops.back().push_back(static_cast<int>(corners.size()));
                pointIndex.push_back(vi);
                corners.emplace_back(P->floats[3 * static_cast<size_t>(vi)], P->floats[3 * static_cast<size_t>(vi) + 1],
                                     P->floats[3 * static_cast<size_t>(vi) + 2]);
            }
            cornerCursor += static_cast<size_t>(count);
        }
        std::vector<int> triangles = triangulatePolygon(corners, faceLoops);
        // If the mirror flips winding, swap two corners to keep "outside" outside.
        for (size_t k = 0; k + 2 < triangles.size(); k += 3) {
            if (mirrored) std::swap(triangles[k + 1], triangles[k + 2]);
            for (Varying& v : varying)
                if (v.out.detail == Primvar::Detail::Uniform) {
                    float const* value = v.reader.at(static_cast<int>(face), 0, 0);
                    v.out.values.insert(v.out.values.end(), value, value + v.out.components);
                }
            for (size_t c = 0; c < 3; ++c) {
                int local = triangles[k + c];
                int corner = static_cast<int>(firstCorner) + local;
                int vertex = pointIndex[static_cast<size_t>(local)];
                for (Varying& v : varying)
                    if (v.out.detail == Primvar::Detail::Varying) {
                        float const* value = v.reader.at(static_cast<int>(face), corner, vertex);
                        v.out.values.insert(v.out.values.end(), value, value + v.out.components);
                    }
                unsigned id = mesh.addVertex(transformPoint(toWorld, corners[static_cast<size_t>(local)]));
                if (normalVar.present()) {
                    float const* n = normalVar.at(static_cast<int>(face), corner, vertex);
                    mesh.N.push_back(safeNormalize(transformNormal(normalMatrix, Vec3(n[0], n[1], n[2]))));
                }
                if (hasSt) {
                    Vec2 value = st ? Vec2(stVar.at(static_cast<int>(face), corner, vertex)[0],
                                           stVar.at(static_cast<int>(face), corner, vertex)[1])
                                    : Vec2(*sVar.at(static_cast<int>(face), corner, vertex),
                                           *tVar.at(static_cast<int>(face), corner, vertex));
                    mesh.st.push_back(value);
                    mesh.uv.push_back(value);
                } else {
                    mesh.uv.push_back(faceParameters(corners.size(), faceLoops.size(), local, c));
                }
                mesh.indices.push_back(id);
            }
        }
        loopCursor += static_cast<size_t>(loops);
    }
    if (mesh.indices.empty()) throw RibError(where, "polygon mesh has no triangles (all faces are degenerate)");
    for (Varying& v : varying) mesh.primvars.add(std::move(v.out));
    return mesh;
}

namespace {
/// Squared quads per side per unit of relative bend: a patch bent by its own size gets the
/// finest sampling (16 x 16), one bent by 10% of it 5 x 5.
constexpr float kPatchBendToResolution = 250.0f;
}  // namespace

MeshData buildBilinearPatch(std::array<Vec3, 4> const& c, Mat4 const& toWorld, bool flip,
                            std::array<Vec3, 4> const* normals) {
    MeshData mesh;
    // Planar patches need one quad; twisted ones are sampled finely enough to look smooth:
    // the more the fourth corner leaves the plane of the other three (relative to the
    // patch's size), the finer, so a height field of many gently bent patches (a
    // PatchMesh "Pz" terrain) stays light.
    Vec3 const normal = glm::cross(c[1] - c[0], c[2] - c[0]);
    float const size = std::max(glm::length(c[3] - c[0]), glm::length(c[2] - c[1]));
    float const area = glm::length(normal);
    float const bend = area > 1e-12f * size * size ? std::fabs(glm::dot(normal, c[3] - c[0])) / area / size : 1.0f;
    int const resolution =
        bend > 1e-6f ? std::clamp(static_cast<int>(std::ceil(std::sqrt(kPatchBendToResolution * bend))), 2, 16) : 1;
    tessellate(
        mesh, resolution, resolution,
        [&](float u, float v, Vec3& P, Vec3& dPdu, Vec3& dPdv) {
            P = (1 - u) * (1 - v) * c[0] + u * (1 - v) * c[1] + (1 - u) * v * c[2] + u * v * c[3];
            dPdu = (1 - v) * (c[1] - c[0]) + v * (c[3] - c[2]);
            dPdv = (1 - u) * (c[2] - c[0]) + u * (c[3] - c[1]);
        },
        toWorld, flip);
    mesh.st = mesh.uv;
    if (normals) {
        // The given normals are used as written, as a polygon mesh's are: orientation does not turn them.
        std::array<Vec3, 4> const& n = *normals;
        Mat4 const normalMatrix = glm::inverse(toWorld);
        for (size_t k = 0; k < mesh.P.size(); ++k) {
            float const u = mesh.uv[k].x, v = mesh.uv[k].y;
            Vec3 const blend = (1 - u) * (1 - v) * n[0] + u * (1 - v) * n[1] + (1 - u) * v * n[2] + u * v * n[3];
            Vec3 const world = transformNormal(normalMatrix, blend);
            if (glm::length(world) > 1e-12f) mesh.N[k] = glm::normalize(world);  // else the surface's own
        }
    }
    return mesh;
}

bool SplineBasis::named(std::string const& name, SplineBasis& out) {
    struct Named {
        const char* name;
        float scale;
        float m[4][4];
        int step;
    };
    static const Named table[] = {
        {"bezier", 1.0f, {{-1, 3, -3, 1}, {3, -6, 3, 0}, {-3, 3, 0, 0}, {1, 0, 0, 0}}, 3},
        {"b-spline", 1.0f / 6.0f, {{-1, 3, -3, 1}, {3, -6, 3, 0}, {-3, 0, 3, 0}, {1, 4, 1, 0}}, 1},
        {"catmull-rom", 0.5f, {{-1, 3, -3, 1}, {2, -5, 4, -1}, {-1, 0, 1, 0}, {0, 2, 0, 0}}, 1},
        {"hermite", 1.0f, {{2, 1, -2, 1}, {-3, -2, 3, -1}, {0, 1, 0, 0}, {1, 0, 0, 0}}, 2},
        {"power", 1.0f, {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}, 4},
    };
    for (Named const& n : table)
        if (name == n.name) {
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) out.matrix[i][j] = n.scale * n.m[i][j];
            out.step = n.step;
            return true;
        }
    return false;
}

SplineBasis SplineBasis::bezier() {
    SplineBasis b{};
    named("bezier", b);
    return b;
}

void SplineBasis::weights(float t, float w[4], float dw[4]) const {
    float powers[4] = {t * t * t, t * t, t, 1.0f}, slopes[4] = {3 * t * t, 2 * t, 1.0f, 0.0f};
    for (int j = 0; j < 4; ++j) {
        w[j] = dw[j] = 0.0f;
        for (int i = 0; i < 4; ++i) {
            w[j] += powers[i] * matrix[i][j];
            dw[j] += slopes[i] * matrix[i][j];
        }
    }
}

namespace {

/// One bicubic patch, control[row in v][column in u], sampled on a 13 x 13 grid.
SurfaceGrid sampleBicubicPatch(Vec3 const (&control)[4][4], SplineBasis const& uBasis, SplineBasis const& vBasis) {
    return sampleSurface(12, 12, [&](float u, float v, Vec3& P, Vec3& dPdu, Vec3& dPdv) {
        float wu[4], dwu[4], wv[4], dwv[4];
        uBasis.weights(u, wu, dwu);
        vBasis.weights(v, wv, dwv);
        P = dPdu = dPdv = Vec3(0.0f);
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i) {
                P += wu[i] * wv[j] * control[j][i];
                dPdu += dwu[i] * wv[j] * control[j][i];
                dPdv += wu[i] * dwv[j] * control[j][i];
            }
    });
}

/// Makes the vertices from `first` on, one patch's with (u, v) over [0, 1]^2,
/// part of a mesh of patchesU x patchesV patches whose (u, v) run over [0, 1]^2
/// together (the RI specification's parameterisation of a patch mesh).
void spreadOverMesh(MeshData& mesh, size_t first, int pu, int pv, int patchesU, int patchesV) {
    if (patchesU == 1 && patchesV == 1) return;
    float const nu = static_cast<float>(patchesU), nv = static_cast<float>(patchesV);
    for (size_t k = first; k < mesh.P.size(); ++k) {
        Vec2 const local = mesh.uv[k];
        mesh.uv[k] = Vec2((static_cast<float>(pu) + local.x) / nu, (static_cast<float>(pv) + local.y) / nv);
        if (k < mesh.st.size()) mesh.st[k] = mesh.uv[k];
        // Derivatives in the mesh's parameters: a patch spans 1 / patches of them.
        if (k < mesh.dPdu.size()) mesh.dPdu[k] *= nu;
        if (k < mesh.dPdv.size()) mesh.dPdv[k] *= nv;
    }
}

int patchCount(int points, bool periodic, int step, int order, SourceLocation const& where, const char* axis) {
    int count = periodic ? points / step : (points - order) / step + 1;
    bool fits = periodic ? points % step == 0 : points >= order && (points - order) % step == 0;
    if (!fits || count < 1)
        throw RibError(where, std::string("PatchMesh: ") + std::to_string(points) + " points in " + axis +
                                  " do not make whole patches for this basis (step " + std::to_string(step) + ")");
    return count;
}

}  // namespace

MeshData buildBicubicPatchMesh(std::vector<Vec3> const& points, int nu, bool uPeriodic, int nv, bool vPeriodic,
                               SplineBasis const& uBasis, SplineBasis const& vBasis, Mat4 const& toWorld, bool flip,
                               SourceLocation const& where, ParamList const* primvars) {
    if (nu < 1 || nv < 1 || points.size() != static_cast<size_t>(nu) * static_cast<size_t>(nv))
        throw RibError(where, "PatchMesh: \"P\" has " + std::to_string(points.size()) + " points, expected nu x nv = " +
                                  std::to_string(nu) + " x " + std::to_string(nv));
    int patchesU = patchCount(nu, uPeriodic, uBasis.step, 4, where, "u");
    int patchesV = patchCount(nv, vPeriodic, vBasis.step, 4, where, "v");
    MeshData mesh;
    for (int pv = 0; pv < patchesV; ++pv)
        for (int pu = 0; pu < patchesU; ++pu) {
            Vec3 control[4][4];  // [row in v][column in u]
            for (int j = 0; j < 4; ++j)
                for (int i = 0; i < 4; ++i) {
                    int col = (pu * uBasis.step + i) % nu, row = (pv * vBasis.step + j) % nv;
                    control[j][i] = points[static_cast<size_t>(row) * static_cast<size_t>(nu) + static_cast<size_t>(col)];
                }
            size_t const first = mesh.P.size();
            placeGrid(mesh, sampleBicubicPatch(control, uBasis, vBasis), toWorld, flip);
            spreadOverMesh(mesh, first, pu, pv, patchesU, patchesV);
        }
    mesh.st = mesh.uv;
    if (primvars)
        addPatchPrimvars(mesh, *primvars, {nu, nv, uPeriodic, vPeriodic, patchesU, patchesV, true, uBasis, vBasis});
    return mesh;
}

MeshData buildBilinearPatchMesh(std::vector<Vec3> const& points, int nu, bool uPeriodic, int nv, bool vPeriodic,
                                Mat4 const& toWorld, bool flip, SourceLocation const& where,
                                std::vector<Vec3> const* normals, ParamList const* primvars) {
    if (nu < 2 || nv < 2 || points.size() != static_cast<size_t>(nu) * static_cast<size_t>(nv))
        throw RibError(where, "PatchMesh \"bilinear\": \"P\" must have nu x nv points with nu, nv >= 2");
    if (normals && normals->size() != points.size())
        throw RibError(where, "PatchMesh \"bilinear\": \"N\" must have one normal per point (" +
                                  std::to_string(points.size()) + "), got " + std::to_string(normals->size()));
    MeshData mesh;
    int patchesU = uPeriodic ? nu : nu - 1, patchesV = vPeriodic ? nv : nv - 1;
    auto index = [&](int i, int j) { return static_cast<size_t>(j % nv) * static_cast<size_t>(nu) + static_cast<size_t>(i % nu); };
    for (int j = 0; j < patchesV; ++j)
        for (int i = 0; i < patchesU; ++i) {
            std::array<size_t, 4> const c = {index(i, j), index(i + 1, j), index(i, j + 1), index(i + 1, j + 1)};
            std::array<Vec3, 4> cornerNormals;
            if (normals)
                for (size_t k = 0; k < 4; ++k) cornerNormals[k] = (*normals)[c[k]];
            size_t const first = mesh.P.size();
            mesh.append(buildBilinearPatch({points[c[0]], points[c[1]], points[c[2]], points[c[3]]}, toWorld, flip,
                                           normals ? &cornerNormals : nullptr));
            spreadOverMesh(mesh, first, i, j, patchesU, patchesV);
        }
    if (primvars)
        addPatchPrimvars(mesh, *primvars,
                         {nu, nv, uPeriodic, vPeriodic, patchesU, patchesV, false, SplineBasis::bezier(), SplineBasis::bezier()});
    return mesh;
}

MeshData buildTorus(float majorRadius, float minorRadius, float phiMinDegrees, float phiMaxDegrees,
                    float thetaMaxDegrees, Mat4 const& toWorld, bool flip) {
    float thetaMax = glm::radians(std::clamp(thetaMaxDegrees, 0.0f, 360.0f));
    // A sweep past a full turn covers nothing more (and would ask for a huge tessellation).
    float phiMin = glm::radians(phiMinDegrees),
          deltaPhi = glm::radians(std::clamp(phiMaxDegrees - phiMinDegrees, -360.0f, 360.0f));
    int nu = std::max(4, static_cast<int>(96.0f * thetaMax / (2.0f * kPi)));
    int nv = std::max(4, static_cast<int>(48.0f * std::fabs(deltaPhi) / (2.0f * kPi)));
    MeshData mesh;
    tessellate(
        mesh, nu, nv,
        [&](float u, float v, Vec3& P, Vec3& dPdu, Vec3& dPdv) {
            float theta = u * thetaMax, phi = phiMin + v * deltaPhi;
            float ring = majorRadius + minorRadius * std::cos(phi);
            P = Vec3(ring * std::cos(theta), ring * std::sin(theta), minorRadius * std::sin(phi));
            dPdu = thetaMax * Vec3(-P.y, P.x, 0.0f);
            dPdv = deltaPhi * Vec3(-minorRadius * std::sin(phi) * std::cos(theta),
                                   -minorRadius * std::sin(phi) * std::sin(theta), minorRadius * std::cos(phi));
        },
        toWorld, flip);
    mesh.st = mesh.uv;
    return mesh;
}

MeshData buildTeapot(Mat4 const& toWorld, bool flip) {
    // The 32 Bezier patches are the same for every teapot: sampled once.
    static std::vector<SurfaceGrid> const patches = [] {
        std::vector<SurfaceGrid> grids;
        for (auto const& patch : teapot::kPatches) {
            Vec3 control[4][4];
            for (int k = 0; k < 16; ++k) {
                float const* p = teapot::kPoints[patch[k] - 1];
                control[k / 4][k % 4] = Vec3(p[0], p[1], p[2]);
            }
            grids.push_back(sampleBicubicPatch(control, SplineBasis::bezier(), SplineBasis::bezier()));
        }
        return grids;
    }();
    MeshData mesh;
    for (SurfaceGrid const& grid : patches) placeGrid(mesh, grid, toWorld, flip);
    mesh.st = mesh.uv;
    return mesh;
}

}  // namespace bxdflab
