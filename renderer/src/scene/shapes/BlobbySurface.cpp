#include "scene/shapes/BlobbySurface.h"

#include <array>
#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/gtc/type_ptr.hpp>
#include <map>

namespace bxdflab {
namespace {

constexpr float kThreshold = 0.5f;
constexpr int kGridCells = 72;  // along the longest side of the bounding box

float supportRadius() { return 1.0f / std::sqrt(1.0f - std::cbrt(0.5f)); }

float falloff(float r2) {
    float const R2 = supportRadius() * supportRadius();
    if (r2 >= R2) return 0.0f;
    float x = 1.0f - r2 / R2;
    return x * x * x;
}

/// One instruction of the code array: an opcode and its operands.
struct Instruction {
    int op;
    std::vector<int> operands;
};

struct Primitive {
    enum class Kind { Constant, Ellipsoid, Segment, Zero } kind;
    float value = 0.0f;        ///< Constant
    Mat4 toUnit{1.0f};         ///< object space -> the unit space of the primitive
    Vec3 a{0.0f}, b{0.0f};     ///< Segment ends (in the matrix's space)
    float radius = 1.0f;       ///< Segment radius
    Mat4 toObject{1.0f};       ///< for the bounding box
};

/// The field of the whole code array at object-space point p.
class Field {
public:
    Field(std::vector<Instruction> program, std::vector<Primitive> primitives)
        : m_program(std::move(program)), m_primitives(std::move(primitives)) {}

    float operator()(Vec3 const& p) const {
        std::vector<float> results(m_program.size(), 0.0f);
        size_t leaf = 0;
        for (size_t k = 0; k < m_program.size(); ++k) {
            Instruction const& in = m_program[k];
            auto arg = [&](size_t i) { return results[static_cast<size_t>(in.operands[i])]; };
            float r = 0.0f;
            if (in.op >= 1000) {
                r = primitiveField(m_primitives[leaf++], p);
            } else if (in.op <= 3) {  // add, multiply, maximum, minimum over a list
                r = in.op == 1 ? 1.0f : in.op == 2 ? -1e30f : in.op == 3 ? 1e30f : 0.0f;
                for (size_t i = 1; i < in.operands.size(); ++i) {
                    float x = arg(i);
                    r = in.op == 0 ? r + x : in.op == 1 ? r * x : in.op == 2 ? std::max(r, x) : std::min(r, x);
                }
            } else if (in.op == 4) {
                r = arg(1) - arg(0);  // minuend - subtrahend
            } else if (in.op == 5) {
                float divisor = arg(1);
                r = divisor != 0.0f ? arg(0) / divisor : 0.0f;
            } else if (in.op == 6) {
                r = -arg(0);
            } else if (in.op == 7) {
                r = arg(0);
            }
            results[k] = r;
        }
        return results.empty() ? 0.0f : results.back();
    }

    /// Object-space bounds of every primitive's support.
    void bounds(Vec3& lo, Vec3& hi) const {
        lo = Vec3(1e30f);
        hi = Vec3(-1e30f);
        float const R = supportRadius();
        for (Primitive const& prim : m_primitives) {
            if (prim.kind != Primitive::Kind::Ellipsoid && prim.kind != Primitive::Kind::Segment) continue;
            Vec3 ends[2] = {prim.a, prim.b};
            float reach = prim.kind == Primitive::Kind::Segment ? R * prim.radius : R;
            for (Vec3 const& end : ends)
                for (int corner = 0; corner < 8; ++corner) {
                    Vec3 c = end + reach * Vec3(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
                    Vec3 q = transformPoint(prim.toObject, c);
                    lo = glm::min(lo, q);
                    hi = glm::max(hi, q);
                }
        }
    }

private:
    static float primitiveField(Primitive const& prim, Vec3 const& p) {
        switch (prim.kind) {
            case Primitive::Kind::Constant: return prim.value;
            case Primitive::Kind::Zero: return 0.0f;
            case Primitive::Kind::Ellipsoid: {
                Vec3 q = transformPoint(prim.toUnit, p);
                return falloff(glm::dot(q, q));
            }
            case Primitive::Kind::Segment: {
                Vec3 q = transformPoint(prim.toUnit, p);
                Vec3 ab = prim.b - prim.a;
                float len2 = glm::dot(ab, ab);
                float t = len2 > 0.0f ? std::clamp(glm::dot(q - prim.a, ab) / len2, 0.0f, 1.0f) : 0.0f;
                Vec3 d = (q - (prim.a + t * ab)) / prim.radius;
                return falloff(glm::dot(d, d));
            }
        }
        return 0.0f;
    }

    std::vector<Instruction> m_program;
    std::vector<Primitive> m_primitives;
};

Mat4 matrixAt(std::vector<float> const& floats, int index, SourceLocation const& where) {
    if (index < 0 || static_cast<size_t>(index) + 16 > floats.size())
        throw RibError(where, "Blobby: a primitive's matrix runs past the end of the floats array");
    return glm::make_mat4(floats.data() + index);
}

/// Marching tetrahedra over a grid of field values: the six tetrahedra of each
/// cube share the cube's main diagonal, so neighbouring cubes agree on their faces.
void polygonise(Field const& field, Vec3 const& lo, Vec3 const& hi, MeshData& mesh) {
    Vec3 extent = hi - lo;
    float cell = std::max({extent.x, extent.y, extent.z}) / kGridCells;
    glm::ivec3 n = glm::max(glm::ivec3(1), glm::ivec3(glm::ceil(extent / cell)));
    auto position = [&](int i, int j, int k) { return lo + cell * Vec3(i, j, k); };
    std::vector<float> values(static_cast<size_t>((n.x + 1) * (n.y + 1) * (n.z + 1)));
    auto at = [&](int i, int j, int k) -> float& {
        return values[static_cast<size_t>((k * (n.y + 1) + j) * (n.x + 1) + i)];
    };
    for (int k = 0; k <= n.z; ++k)
        for (int j = 0; j <= n.y; ++j)
            for (int i = 0; i <= n.x; ++i) at(i, j, k) = field(position(i, j, k)) - kThreshold;

    // One vertex per grid edge crossed, shared by the triangles around it.
    std::map<std::pair<long, long>, unsigned> edgeVertex;
    auto gridIndex = [&](glm::ivec3 c) { return static_cast<long>((c.z * (n.y + 1) + c.y) * (n.x + 1) + c.x); };
    auto vertexOn = [&](glm::ivec3 c0, glm::ivec3 c1) {
        long k0 = gridIndex(c0), k1 = gridIndex(c1);
        auto key = std::make_pair(std::min(k0, k1), std::max(k0, k1));
        auto found = edgeVertex.find(key);
        if (found != edgeVertex.end()) return found->second;
        float f0 = at(c0.x, c0.y, c0.z), f1 = at(c1.x, c1.y, c1.z);
        float t = f0 != f1 ? f0 / (f0 - f1) : 0.5f;
        Vec3 p = glm::mix(position(c0.x, c0.y, c0.z), position(c1.x, c1.y, c1.z), std::clamp(t, 0.0f, 1.0f));
        unsigned index = mesh.addVertex(p);
        edgeVertex.emplace(key, index);
        return index;
    };
    static const glm::ivec3 corner[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    static const int tetrahedra[6][4] = {{0, 5, 1, 6}, {0, 1, 2, 6}, {0, 2, 3, 6},
                                         {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}};
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i)
                for (auto const& tet : tetrahedra) {
                    glm::ivec3 c[4];
                    std::array<bool, 4> inside{};
                    int count = 0;
                    for (int v = 0; v < 4; ++v) {
                        c[v] = glm::ivec3(i, j, k) + corner[tet[v]];
                        inside[static_cast<size_t>(v)] = at(c[v].x, c[v].y, c[v].z) > 0.0f;
                        count += inside[static_cast<size_t>(v)];
                    }
                    if (count == 0 || count == 4) continue;
                    std::vector<int> in, out;
                    for (int v = 0; v < 4; ++v) (inside[static_cast<size_t>(v)] ? in : out).push_back(v);
                    // Triangles are wound consistently afterwards (from the field's gradient).
                    if (in.size() == 1 || out.size() == 1) {
                        int apex = in.size() == 1 ? in[0] : out[0];
                        std::vector<int> const& others = in.size() == 1 ? out : in;
                        unsigned a = vertexOn(c[apex], c[others[0]]), b = vertexOn(c[apex], c[others[1]]),
                                 d = vertexOn(c[apex], c[others[2]]);
                        mesh.indices.insert(mesh.indices.end(), {a, b, d});
                    } else {
                        unsigned a = vertexOn(c[in[0]], c[out[0]]), b = vertexOn(c[in[0]], c[out[1]]),
                                 d = vertexOn(c[in[1]], c[out[1]]), e = vertexOn(c[in[1]], c[out[0]]);
                        mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, e});
                    }
                }
}

}  // namespace

MeshData buildBlobby(int leaves, std::vector<int> const& code, std::vector<float> const& floats, Mat4 const& toWorld,
                     bool flip, SourceLocation const& where, std::string& skipped) {
    // Decode the code array into instructions and primitives.
    std::vector<Instruction> program;
    std::vector<Primitive> primitives;
    size_t pc = 0;
    auto take = [&](size_t count) {
        if (pc + count > code.size()) throw RibError(where, "Blobby: the code array ends inside an instruction");
        std::vector<int> operands(code.begin() + static_cast<long>(pc), code.begin() + static_cast<long>(pc + count));
        pc += count;
        return operands;
    };
    while (pc < code.size()) {
        Instruction in;
        in.op = code[pc++];
        Primitive prim;
        prim.kind = Primitive::Kind::Zero;
        if (in.op == 1000) {
            in.operands = take(1);
            if (in.operands[0] < 0 || static_cast<size_t>(in.operands[0]) >= floats.size())
                throw RibError(where, "Blobby: a constant's index is outside the floats array");
            prim.kind = Primitive::Kind::Constant;
            prim.value = floats[static_cast<size_t>(in.operands[0])];
        } else if (in.op == 1001) {
            in.operands = take(1);
            prim.kind = Primitive::Kind::Ellipsoid;
            prim.toObject = matrixAt(floats, in.operands[0], where);
        } else if (in.op == 1002) {
            in.operands = take(1);
            int base = in.operands[0];
            if (base < 0 || static_cast<size_t>(base) + 23 > floats.size())
                throw RibError(where, "Blobby: a segment's 23 floats run past the end of the floats array");
            prim.kind = Primitive::Kind::Segment;
            prim.a = Vec3(floats[static_cast<size_t>(base)], floats[static_cast<size_t>(base + 1)], floats[static_cast<size_t>(base + 2)]);
            prim.b = Vec3(floats[static_cast<size_t>(base + 3)], floats[static_cast<size_t>(base + 4)], floats[static_cast<size_t>(base + 5)]);
            prim.radius = std::max(std::fabs(floats[static_cast<size_t>(base + 6)]), 1e-6f);
            prim.toObject = matrixAt(floats, base + 7, where);
        } else if (in.op == 1003) {
            in.operands = take(2);
            skipped = "repelling planes (they need a depth file)";
        } else if (in.op == 1004 || in.op == 9000) {
            in.operands = take(5);
            skipped = "plugin fields (shared objects are not loaded)";
        } else if (in.op >= 0 && in.op <= 3) {
            std::vector<int> count = take(1);
            if (count[0] < 0) throw RibError(where, "Blobby: a negative operand count");
            std::vector<int> rest = take(static_cast<size_t>(count[0]));
            in.operands = count;
            in.operands.insert(in.operands.end(), rest.begin(), rest.end());
        } else if (in.op == 4 || in.op == 5) {
            in.operands = take(2);
        } else if (in.op == 6 || in.op == 7) {
            in.operands = take(1);
        } else if (in.op == 8) {
            // The volumetric flag (RenderMan 16+): the surface is drawn either way.
        } else {
            throw RibError(where, "Blobby: unknown opcode " + std::to_string(in.op) + " in the code array");
        }
        if (in.op >= 1000) {
            if (prim.kind == Primitive::Kind::Ellipsoid || prim.kind == Primitive::Kind::Segment) {
                if (std::fabs(glm::determinant(prim.toObject)) < 1e-20f)
                    throw RibError(where, "Blobby: a primitive's matrix is singular");
                prim.toUnit = glm::inverse(prim.toObject);
            }
            primitives.push_back(prim);
        } else if (in.op <= 7) {
            // Operands refer to the results of earlier instructions.
            size_t first = in.op <= 3 ? 1 : 0;
            for (size_t i = first; i < in.operands.size(); ++i)
                if (in.operands[i] < 0 || static_cast<size_t>(in.operands[i]) >= program.size())
                    throw RibError(where, "Blobby: an operation refers to instruction " + std::to_string(in.operands[i]) +
                                              ", which does not come before it");
        }
        if (in.op != 8) program.push_back(in);
    }
    // Plugin fields and repelling planes are not always counted as leaves (Aqsis's
    // examples leave them out of nleaf); either count is accepted.
    long const notDrawn = std::count_if(primitives.begin(), primitives.end(),
                                        [](Primitive const& p) { return p.kind == Primitive::Kind::Zero; });
    if (static_cast<int>(primitives.size()) != leaves && static_cast<int>(primitives.size() - static_cast<size_t>(notDrawn)) != leaves)
        throw RibError(where, "Blobby: nleaf is " + std::to_string(leaves) + " but the code array has " +
                                  std::to_string(primitives.size()) + " primitives");
    // Operand indices count instructions; the flag (op 8) is not one.
    Field field(std::move(program), std::move(primitives));
    Vec3 lo, hi;
    field.bounds(lo, hi);
    MeshData mesh;
    if (!(lo.x <= hi.x)) return mesh;  // nothing but constants: no surface
    polygonise(field, lo, hi, mesh);

    // Normals from the field's gradient (it grows inward), and windings to match.
    float h = 1e-3f * glm::length(hi - lo);
    std::vector<Vec3> objectP = mesh.P;
    mesh.N.resize(mesh.P.size());
    Mat3 const normalMatrix = glm::transpose(glm::inverse(Mat3(toWorld)));
    for (size_t v = 0; v < mesh.P.size(); ++v) {
        Vec3 p = objectP[v];
        Vec3 gradient(field(p + Vec3(h, 0, 0)) - field(p - Vec3(h, 0, 0)), field(p + Vec3(0, h, 0)) - field(p - Vec3(0, h, 0)),
                      field(p + Vec3(0, 0, h)) - field(p - Vec3(0, 0, h)));
        Vec3 outward = -gradient;
        Vec3 n = safeNormalize(normalMatrix * outward);
        mesh.N[v] = flip ? -n : n;
        mesh.P[v] = transformPoint(toWorld, p);
    }
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        Vec3 const& a = mesh.P[mesh.indices[t]];
        Vec3 facet = glm::cross(mesh.P[mesh.indices[t + 1]] - a, mesh.P[mesh.indices[t + 2]] - a);
        Vec3 average = mesh.N[mesh.indices[t]] + mesh.N[mesh.indices[t + 1]] + mesh.N[mesh.indices[t + 2]];
        if (glm::dot(facet, average) < 0.0f) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    }
    return mesh;
}

}  // namespace bxdflab
