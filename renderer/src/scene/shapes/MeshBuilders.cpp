#include "scene/shapes/MeshBuilders.h"

#include <functional>
#include <numeric>

#include "scene/shapes/TeapotData.h"

namespace bxdflab {
namespace {

/// Reads one item of a primvar whatever its storage class.
class Primvar {
public:
    Primvar(Param const* param, int components) : m_param(param), m_components(components) {}
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

/// Signed area test in 2-D, used by ear clipping.
float cross2(Vec2 const& a, Vec2 const& b, Vec2 const& c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

bool insideTriangle(Vec2 const& p, Vec2 const& a, Vec2 const& b, Vec2 const& c) {
    return cross2(a, b, p) >= 0.0f && cross2(b, c, p) >= 0.0f && cross2(c, a, p) >= 0.0f;
}

/// Triangulates one simple polygon (corner positions in order); returns
/// triples of corner indices. Ear clipping in the polygon's dominant plane.
std::vector<int> triangulateLoop(std::vector<Vec3> const& corners) {
    int n = static_cast<int>(corners.size());
    std::vector<int> triangles;
    if (n < 3) return triangles;
    // Newell's method gives a robust normal for non-planar and concave loops.
    Vec3 normal(0.0f);
    for (int i = 0; i < n; ++i) {
        Vec3 const& a = corners[i];
        Vec3 const& b = corners[(i + 1) % n];
        normal += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    int axis = std::fabs(normal.x) > std::fabs(normal.y) ? (std::fabs(normal.x) > std::fabs(normal.z) ? 0 : 2)
                                                         : (std::fabs(normal.y) > std::fabs(normal.z) ? 1 : 2);
    int ax = (axis + 1) % 3, ay = (axis + 2) % 3;
    float orientation = normal[axis] >= 0.0f ? 1.0f : -1.0f;
    std::vector<Vec2> flat(n);
    for (int i = 0; i < n; ++i) flat[i] = Vec2(corners[i][ax], orientation * corners[i][ay]);

    std::vector<int> remaining(n);
    std::iota(remaining.begin(), remaining.end(), 0);
    int guard = 2 * n * n;
    while (remaining.size() > 3 && guard-- > 0) {
        int m = static_cast<int>(remaining.size());
        bool clipped = false;
        for (int k = 0; k < m && !clipped; ++k) {
            int ia = remaining[(k + m - 1) % m], ib = remaining[k], ic = remaining[(k + 1) % m];
            if (cross2(flat[ia], flat[ib], flat[ic]) <= 0.0f) continue;  // reflex corner
            bool blocked = false;
            for (int other : remaining)
                if (other != ia && other != ib && other != ic && insideTriangle(flat[other], flat[ia], flat[ib], flat[ic])) {
                    blocked = true;
                    break;
                }
            if (blocked) continue;
            triangles.insert(triangles.end(), {ia, ib, ic});
            remaining.erase(remaining.begin() + k);
            clipped = true;
        }
        if (!clipped) break;  // degenerate loop: fall back to a fan below
    }
    if (remaining.size() > 3 || guard <= 0) {
        for (size_t k = 1; k + 1 < remaining.size(); ++k)
            triangles.insert(triangles.end(), {remaining[0], remaining[k], remaining[k + 1]});
    } else if (remaining.size() == 3) {
        triangles.insert(triangles.end(), {remaining[0], remaining[1], remaining[2]});
    }
    return triangles;
}

/// Samples a parametric surface on an (nu+1) x (nv+1) grid into `mesh`.
using SurfaceFunction = std::function<void(float u, float v, Vec3& P, Vec3& dPdu, Vec3& dPdv)>;

void tessellate(MeshData& mesh, int nu, int nv, SurfaceFunction const& surface, Mat4 const& toWorld, bool flip) {
    Mat3 linear(toWorld);
    float sign = flip ? -1.0f : 1.0f;
    unsigned base = static_cast<unsigned>(mesh.P.size());
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i) {
            float u = static_cast<float>(i) / nu, v = static_cast<float>(j) / nv;
            Vec3 P, dPdu, dPdv;
            surface(u, v, P, dPdu, dPdv);
            Vec3 worldDu = linear * dPdu, worldDv = linear * dPdv;
            Vec3 n = glm::cross(worldDu, worldDv);
            if (glm::length(n) < 1e-6f * (glm::length(worldDu) + glm::length(worldDv) + 1e-12f)) {
                // A collapsed edge (the teapot's lid apex, a pole): take the
                // normal a small step inside the patch instead.
                Vec3 P2, du2, dv2;
                surface(u + (u < 0.5f ? 1e-3f : -1e-3f), v + (v < 0.5f ? 1e-3f : -1e-3f), P2, du2, dv2);
                n = glm::cross(linear * du2, linear * dv2);
            }
            mesh.P.push_back(transformPoint(toWorld, P));
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

/// Cubic Bernstein basis and its derivative at t.
void bernstein(float t, float b[4], float db[4]) {
    float s = 1.0f - t;
    b[0] = s * s * s;
    b[1] = 3.0f * t * s * s;
    b[2] = 3.0f * t * t * s;
    b[3] = t * t * t;
    db[0] = -3.0f * s * s;
    db[1] = 3.0f * s * s - 6.0f * t * s;
    db[2] = 6.0f * t * s - 3.0f * t * t;
    db[3] = 3.0f * t * t;
}

}  // namespace

MeshData buildPolygonMesh(std::vector<int> const& loopsPerFace, std::vector<int> const& verticesPerLoop,
                          std::vector<int> const& vertexIndices, ParamList const& params, Mat4 const& toWorld,
                          SourceLocation const& where, Diagnostics& diagnostics) {
    Param const* P = params.find("P");
    if (!P) throw RibError(where, "polygon needs a \"P\" primvar with its vertex positions");
    if (P->decl.type != ParamType::Point && P->decl.type != ParamType::Float && P->decl.type != ParamType::Vector)
        throw RibError(P->location, "\"P\" must be of type point");
    size_t numPoints = P->floats.size() / 3;
    if (P->floats.size() % 3 != 0) throw RibError(P->location, "\"P\" needs three numbers per point");

    Param const* normals = params.find("N");
    if (normals && normals->decl.type != ParamType::Normal && normals->decl.type != ParamType::Vector)
        throw RibError(normals->location, "\"N\" must be of type normal");
    Param const* st = params.find("st");
    Param const* s = params.find("s");
    Param const* t = params.find("t");
    Primvar normalVar(normals, 3), stVar(st, 2), sVar(s, 1), tVar(t, 1);
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
        if (loops > 1)
            diagnostics.warn(where, "polygons with holes are not supported: the holes are filled");
        for (int loop = 0; loop < loops; ++loop) {
            int count = verticesPerLoop[loopCursor + static_cast<size_t>(loop)];
            if (count < 0 || cornerCursor + static_cast<size_t>(count) > vertexIndices.size())
                throw RibError(where, "vertex counts add up to more indices than were given");
            if (loop == 0) {
                std::vector<Vec3> corners;
                std::vector<int> pointIndex;
                for (int k = 0; k < count; ++k) {
                    int vi = vertexIndices[cornerCursor + static_cast<size_t>(k)];
                    if (vi < 0 || static_cast<size_t>(vi) >= numPoints)
                        throw RibError(where, "vertex index " + std::to_string(vi) + " is out of range (there are " +
                                                  std::to_string(numPoints) + " points)");
                    pointIndex.push_back(vi);
                    corners.emplace_back(P->floats[3 * vi], P->floats[3 * vi + 1], P->floats[3 * vi + 2]);
                }
                std::vector<int> triangles = triangulateLoop(corners);
                // If the mirror flips winding, swap two corners to keep "outside" outside.
                for (size_t k = 0; k < triangles.size(); k += 3) {
                    if (mirrored) std::swap(triangles[k + 1], triangles[k + 2]);
                    for (size_t c = 0; c < 3; ++c) {
                        int local = triangles[k + c];
                        int corner = static_cast<int>(cornerCursor) + local;
                        int vertex = pointIndex[static_cast<size_t>(local)];
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
                        }
                        mesh.indices.push_back(id);
                    }
                }
            }
            cornerCursor += static_cast<size_t>(count);
        }
        loopCursor += static_cast<size_t>(loops);
    }
    if (mesh.indices.empty()) throw RibError(where, "polygon mesh has no triangles (all faces are degenerate)");
    return mesh;
}

MeshData buildBilinearPatch(std::array<Vec3, 4> const& c, Mat4 const& toWorld, bool flip) {
    MeshData mesh;
    // Planar patches need one quad; twisted ones are sampled finely enough to look smooth.
    float twist = std::fabs(glm::dot(glm::cross(c[1] - c[0], c[2] - c[0]), c[3] - c[0]));
    int resolution = twist > 1e-6f * glm::length(c[3] - c[0]) ? 16 : 1;
    tessellate(
        mesh, resolution, resolution,
        [&](float u, float v, Vec3& P, Vec3& dPdu, Vec3& dPdv) {
            P = (1 - u) * (1 - v) * c[0] + u * (1 - v) * c[1] + (1 - u) * v * c[2] + u * v * c[3];
            dPdu = (1 - v) * (c[1] - c[0]) + v * (c[3] - c[2]);
            dPdv = (1 - u) * (c[2] - c[0]) + u * (c[3] - c[1]);
        },
        toWorld, flip);
    mesh.st = mesh.uv;
    return mesh;
}

MeshData buildTeapot(Mat4 const& toWorld, bool flip) {
    MeshData mesh;
    for (auto const& patch : teapot::kPatches) {
        Vec3 control[16];
        for (int k = 0; k < 16; ++k) {
            float const* p = teapot::kPoints[patch[k] - 1];
            control[k] = Vec3(p[0], p[1], p[2]);
        }
        tessellate(
            mesh, 12, 12,
            [&](float u, float v, Vec3& P, Vec3& dPdu, Vec3& dPdv) {
                float bu[4], dbu[4], bv[4], dbv[4];
                bernstein(u, bu, dbu);
                bernstein(v, bv, dbv);
                P = dPdu = dPdv = Vec3(0.0f);
                for (int j = 0; j < 4; ++j)
                    for (int i = 0; i < 4; ++i) {
                        Vec3 const& cp = control[4 * j + i];
                        P += bu[i] * bv[j] * cp;
                        dPdu += dbu[i] * bv[j] * cp;
                        dPdv += bu[i] * dbv[j] * cp;
                    }
            },
            toWorld, flip);
    }
    mesh.st = mesh.uv;
    return mesh;
}

}  // namespace bxdflab
