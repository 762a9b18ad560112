#include "scene/shapes/NurbsSurface.h"

#include <algorithm>
#include <cmath>

namespace bxdflab {
namespace {

constexpr int kSegmentsPerSpan = 8;          // tessellation of each non-empty knot span
constexpr size_t kMaxVertices = 4'000'000;   // refuse absurd patches rather than exhaust memory

}  // namespace

void bsplineBasis(std::vector<float> const& knots, int count, int order, float t, std::vector<float>& N,
                  std::vector<float>& dN) {
    int const n = static_cast<int>(knots.size()) - 1;
    // Degree 0: the span holding t (the last non-empty span takes t = its end).
    std::vector<double> b(static_cast<size_t>(n), 0.0);
    int span = -1;
    for (int i = 0; i < n; ++i)
        if (knots[i] <= t && t < knots[i + 1]) span = i;
    if (span < 0)
        for (int i = n - 1; i >= 0; --i)
            if (knots[i] < knots[i + 1] && t >= knots[i + 1]) {
                span = i;
                break;
            }
    if (span >= 0) b[static_cast<size_t>(span)] = 1.0;
    std::vector<double> previous;
    for (int k = 2; k <= order; ++k) {
        previous = b;
        for (int i = 0; i + k <= n; ++i) {
            double left = knots[i + k - 1] - knots[i], right = knots[i + k] - knots[i + 1];
            double value = 0.0;
            if (left > 0.0) value += (t - knots[i]) / left * previous[static_cast<size_t>(i)];
            if (right > 0.0) value += (knots[i + k] - t) / right * previous[static_cast<size_t>(i + 1)];
            b[static_cast<size_t>(i)] = value;
        }
    }
    // The derivative of an order-k function from the order k-1 ones (still in `previous`).
    N.assign(static_cast<size_t>(count), 0.0f);
    dN.assign(static_cast<size_t>(count), 0.0f);
    for (int i = 0; i < count; ++i) {
        N[static_cast<size_t>(i)] = static_cast<float>(b[static_cast<size_t>(i)]);
        if (order < 2) continue;
        double left = knots[i + order - 1] - knots[i], right = knots[i + order] - knots[i + 1];
        double d = 0.0;
        if (left > 0.0) d += (order - 1) / left * previous[static_cast<size_t>(i)];
        if (right > 0.0) d -= (order - 1) / right * previous[static_cast<size_t>(i + 1)];
        dN[static_cast<size_t>(i)] = static_cast<float>(d);
    }
}

namespace {

/// Parameter values along one direction: kSegmentsPerSpan steps in each knot span within [lo, hi].
std::vector<float> samples(std::vector<float> const& knots, float lo, float hi) {
    std::vector<float> breaks = {lo};
    for (float k : knots)
        if (k > lo && k < hi) breaks.push_back(k);
    breaks.push_back(hi);
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    std::vector<float> out;
    for (size_t s = 0; s + 1 < breaks.size(); ++s)
        for (int j = 0; j < kSegmentsPerSpan; ++j)
            out.push_back(breaks[s] + (breaks[s + 1] - breaks[s]) * static_cast<float>(j) / kSegmentsPerSpan);
    out.push_back(hi);
    return out;
}

void checkKnots(std::vector<float> const& knots, int count, int order, float lo, float hi, char const* which,
                SourceLocation const& where) {
    if (order < 1 || count < order)
        throw RibError(where, std::string("NuPatch: ") + which + " order must be at least 1 and at most the number of "
                                                                 "control points");
    if (knots.size() != static_cast<size_t>(count + order))
        throw RibError(where, std::string("NuPatch: the ") + which + " knot vector needs " +
                                  std::to_string(count + order) + " values, got " + std::to_string(knots.size()));
    for (size_t i = 0; i + 1 < knots.size(); ++i)
        if (!(knots[i] <= knots[i + 1]))
            throw RibError(where, std::string("NuPatch: the ") + which + " knot vector must not decrease");
    if (!(lo < hi) || lo < knots[static_cast<size_t>(order - 1)] || hi > knots[static_cast<size_t>(count)])
        throw RibError(where, std::string("NuPatch: the ") + which + " parameter range must lie within the knots "
                                                                     "where the surface is defined");
}

}  // namespace

MeshData buildNurbsPatch(NurbsDesc const& d, Mat4 const& toWorld, bool flip, SourceLocation const& where) {
    checkKnots(d.uknot, d.nu, d.uorder, d.umin, d.umax, "u", where);
    checkKnots(d.vknot, d.nv, d.vorder, d.vmin, d.vmax, "v", where);
    if (d.Pw.size() != static_cast<size_t>(d.nu) * static_cast<size_t>(d.nv))
        throw RibError(where, "NuPatch: needs " + std::to_string(d.nu * d.nv) + " control points, got " +
                                  std::to_string(d.Pw.size()));
    std::vector<float> us = samples(d.uknot, d.umin, d.umax), vs = samples(d.vknot, d.vmin, d.vmax);
    if (us.size() * vs.size() > kMaxVertices)
        throw RibError(where, "NuPatch: too many knot spans to tessellate (" + std::to_string(us.size() * vs.size()) +
                                  " vertices)");
    MeshData mesh;
    std::vector<float> Nu, dNu, Nv, dNv;
    // The point at (u, v) and its derivatives, in the patch's own space.
    auto evaluate = [&](float u, float v, Vec3& P, Vec3& dPdu, Vec3& dPdv) {
        bsplineBasis(d.vknot, d.nv, d.vorder, v, Nv, dNv);
        bsplineBasis(d.uknot, d.nu, d.uorder, u, Nu, dNu);
        // H = sum N_i(u) N_j(v) Pw_ij, and its u and v derivatives.
        Vec4 H(0.0f), Hu(0.0f), Hv(0.0f);
        for (int j = 0; j < d.nv; ++j) {
            if (Nv[static_cast<size_t>(j)] == 0.0f && dNv[static_cast<size_t>(j)] == 0.0f) continue;
            for (int i = 0; i < d.nu; ++i) {
                Vec4 const& p = d.Pw[static_cast<size_t>(j * d.nu + i)];
                float nu = Nu[static_cast<size_t>(i)], nv = Nv[static_cast<size_t>(j)];
                H += nu * nv * p;
                Hu += dNu[static_cast<size_t>(i)] * nv * p;
                Hv += nu * dNv[static_cast<size_t>(j)] * p;
            }
        }
        float w = std::fabs(H.w) > 1e-12f ? H.w : 1e-12f;
        P = Vec3(H) / w;
        // The quotient rule: d(H.xyz / H.w) = (dH.xyz - P dH.w) / H.w.
        dPdu = (Vec3(Hu) - P * Hu.w) / w;
        dPdv = (Vec3(Hv) - P * Hv.w) / w;
    };
    for (float v : vs) {
        for (float u : us) {
            Vec3 P, dPdu, dPdv;
            evaluate(u, v, P, dPdu, dPdv);
            // As the other patches: the normal is dPdu x dPdv in world space, reversed by `flip`.
            Vec3 worldDu = transformVector(toWorld, dPdu), worldDv = transformVector(toWorld, dPdv);
            Vec3 n = safeNormalize(glm::cross(worldDu, worldDv));
            if (n == Vec3(0.0f)) {
                // Where the surface degenerates (a sphere's pole, where a whole edge meets in a point) the
                // normal is taken a small step inside, so the shading stays smooth up to it.
                float const du = 1e-3f * (d.umax - d.umin), dv = 1e-3f * (d.vmax - d.vmin);
                Vec3 insideP, insideDu, insideDv;
                evaluate(u + (u < 0.5f * (d.umin + d.umax) ? du : -du), v + (v < 0.5f * (d.vmin + d.vmax) ? dv : -dv),
                         insideP, insideDu, insideDv);
                n = safeNormalize(glm::cross(transformVector(toWorld, insideDu), transformVector(toWorld, insideDv)));
            }
            mesh.P.push_back(transformPoint(toWorld, P));
            mesh.dPdu.push_back(worldDu);
            mesh.dPdv.push_back(worldDv);
            mesh.N.push_back(flip ? -n : n);
            mesh.uv.emplace_back(u, v);
        }
    }
    unsigned const columns = static_cast<unsigned>(us.size());
    for (unsigned r = 0; r + 1 < vs.size(); ++r)
        for (unsigned c = 0; c + 1 < columns; ++c) {
            unsigned a = r * columns + c, b = a + 1, e = a + columns, f = e + 1;
            mesh.indices.insert(mesh.indices.end(), {a, b, f, a, f, e});
        }
    // A normal still zero (a patch collapsed to a line or a point): the facet normals are used.
    for (auto& n : mesh.N)
        if (n == Vec3(0.0f)) {
            mesh.N.clear();
            break;
        }
    return mesh;
}

}  // namespace bxdflab
