#include "scene/shapes/SubdivisionSurface.h"

#include <cstring>
#include <map>
#include <optional>

namespace bxdflab {

namespace {

/// The rate a storage class asks for, or nothing for constant and uniform.
std::optional<SubdivisionPrimvar::Rate> rateOf(std::string const& storageClass) {
    if (storageClass.empty() || storageClass == "vertex") return SubdivisionPrimvar::Rate::Vertex;
    if (storageClass == "varying") return SubdivisionPrimvar::Rate::Varying;
    if (storageClass == "facevarying" || storageClass == "facevertex") return SubdivisionPrimvar::Rate::FaceVarying;
    return std::nullopt;
}

/// Facevarying values, one per face corner, shared by the corners of one point
/// that carry the same value: the subdivision then runs smoothly across faces
/// and stops at seams.
void weldCorners(Param const& param, SubdivisionData const& data, SubdivisionPrimvar& out) {
    size_t const c = static_cast<size_t>(out.var.components);
    std::map<std::pair<unsigned, std::vector<float>>, unsigned> seen;
    out.cornerValues.reserve(data.indices.size());
    for (size_t corner = 0; corner < data.indices.size(); ++corner) {
        std::vector<float> value(param.floats.begin() + static_cast<std::ptrdiff_t>(corner * c),
                                 param.floats.begin() + static_cast<std::ptrdiff_t>((corner + 1) * c));
        auto [it, added] = seen.try_emplace({data.indices[corner], value}, static_cast<unsigned>(seen.size()));
        if (added) out.var.values.insert(out.var.values.end(), value.begin(), value.end());
        out.cornerValues.push_back(it->second);
    }
}

/// A primvar of a subdivision surface, read on its limit surface.
class LimitValues final : public ParametricValues {
public:
    LimitValues(SubdivisionSurface const& surface, unsigned slot, unsigned components)
        : m_surface(surface), m_slot(slot), m_components(components) {}
    void at(unsigned face, float u, float v, float* out) const override {
        m_surface.limitValue(m_slot, face, u, v, out, m_components);
    }

private:
    SubdivisionSurface const& m_surface;  ///< which holds this
    unsigned m_slot, m_components;
};

}  // namespace

PrimvarSet readSubdivisionPrimvars(ParamList const& params, SubdivisionData& data) {
    PrimvarSet uniform;
    for (Param const& p : params.all()) {
        int const components = primvarComponents(p);
        if (components == 0 || isGeometryParameter(p.name()) || p.used) continue;
        std::string const& cls = p.decl.storageClass;
        size_t const given = p.floats.size() / static_cast<size_t>(components);
        Primvar var;
        var.name = p.name();
        var.type = p.decl.type;
        var.components = components;
        std::optional<SubdivisionPrimvar::Rate> rate = rateOf(cls);
        // How many values the storage class asks for, and what of the mesh they follow.
        std::pair<size_t, char const*> wanted = {1, "one"};
        if (cls == "uniform")
            wanted = {data.faceSizes.size(), "one per face"};
        else if (rate == SubdivisionPrimvar::Rate::FaceVarying)
            wanted = {data.indices.size(), "one per face corner"};
        else if (rate)
            wanted = {data.P.size(), "one per point"};
        if (given != wanted.first || p.floats.size() % static_cast<size_t>(components) != 0)
            throw RibError(p.location, "primvar \"" + p.name() + "\" (" + (cls.empty() ? std::string("vertex") : cls) +
                                           ") needs " + std::to_string(wanted.first) + " values here (" + wanted.second +
                                           "), got " + std::to_string(given));
        p.used = true;
        if (!rate) {  // uniform (constant ones are the shape's own)
            var.detail = Primvar::Detail::Uniform;
            var.values = p.floats;
            uniform.add(std::move(var));
            continue;
        }
        SubdivisionPrimvar sub;
        sub.var = std::move(var);
        sub.var.detail = Primvar::Detail::Varying;
        sub.rate = *rate;
        if (sub.rate == SubdivisionPrimvar::Rate::FaceVarying)
            weldCorners(p, data, sub);
        else
            sub.var.values = p.floats;
        data.primvars.push_back(std::move(sub));
    }
    return uniform;
}

SubdivisionSurface::SubdivisionSurface(SubdivisionData data, bool flipNormals)
    : m_data(std::move(data)), m_orientation(flipNormals ? -1.0f : 1.0f) {
    for (size_t slot = 0; slot < m_data.primvars.size(); ++slot) {
        Primvar listed = m_data.primvars[slot].var;
        listed.values.clear();  // the ray tracer holds them
        listed.parametric = std::make_shared<LimitValues const>(*this, static_cast<unsigned>(slot),
                                                                static_cast<unsigned>(listed.components));
        primvars.add(std::move(listed));
    }
    takeSTFromPrimvars();
}

bool SubdivisionSurface::samePointsAs(Shape const& other) const {
    auto const* mesh = dynamic_cast<SubdivisionSurface const*>(&other);
    return mesh && mesh->m_data.P.size() == m_data.P.size() && mesh->m_data.indices == m_data.indices &&
           mesh->m_data.faceSizes == m_data.faceSizes;
}

void SubdivisionSurface::deform(std::shared_ptr<PointSteps const> steps) {
    m_data.P = steps->steps.front();
    Shape::deform(std::move(steps));
}

SurfaceBasics SubdivisionSurface::basicsUnmoved(HitRecord const& hit) const {
    SurfaceTangents t = tangentsUnmoved(hit);
    SurfaceBasics out;
    // The hit is on Embree's tessellation: P where the ray met it keeps
    // secondary rays off that same surface.
    out.P = hit.org + hit.t * hit.dir;
    out.pError = 3e-5f * (glm::abs(hit.org) + glm::abs(hit.t * hit.dir)) + Vec3(1e-7f);
    Vec3 limitNormal = safeNormalize(glm::cross(t.dPdu, t.dPdv));
    Vec3 facet = safeNormalize(hit.Ng);
    if (facet == Vec3(0.0f)) facet = limitNormal;
    out.Ng = m_orientation * facet;
    out.N = limitNormal == Vec3(0.0f) ? out.Ng : m_orientation * limitNormal;
    if (glm::dot(out.Ng, out.N) < 0.0f) out.Ng = -out.Ng;
    return out;
}

SurfaceTangents SubdivisionSurface::tangentsUnmoved(HitRecord const& hit) const {
    float P[3], dPdu[3], dPdv[3];
    // A deforming mesh's limit surface is blended between the shapes around the hit's time.
    m_evaluator->evaluate(hit.primID, hit.u, hit.v, m_deformation ? hit.time : 0.0f, P, dPdu, dPdv, 3);
    return {Vec3(dPdu[0], dPdu[1], dPdu[2]), Vec3(dPdv[0], dPdv[1], dPdv[2])};
}

void SubdivisionSurface::primvarUnmoved(Primvar const& var, HitRecord const& hit, float* out) const {
    size_t const c = static_cast<size_t>(var.components);
    if (var.detail == Primvar::Detail::Uniform && (hit.primID + 1) * c <= var.values.size()) {
        std::memcpy(out, var.values.data() + hit.primID * c, c * sizeof(float));
        return;
    }
    if (var.parametric) {
        var.parametric->at(hit.primID, hit.u, hit.v, out);
        return;
    }
    Shape::primvarUnmoved(var, hit, out);  // a constant
}

}  // namespace bxdflab
