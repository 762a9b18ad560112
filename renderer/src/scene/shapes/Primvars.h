// Primitive variables: values a RIB attaches to a shape ("color Cs",
// "uniform float id", "varying float[2] uv2", ...), read by plugins with
// RixShadingContext::GetPrimVar at any shading point.
//
// Storage follows how each value varies over the shape:
//   constant  one value for the whole shape
//   uniform   one value per face (per triangle of a mesh, once triangulated)
//   varying   values at the shape's vertices or corners, interpolated
// Polygon meshes store varying values per mesh vertex (their triangulation
// already made one vertex per corner, so vertex, varying and facevarying all
// end up there); quadrics take four corner values, in (u, v) order; patch
// meshes, NURBS patches, curves and subdivision surfaces keep the values as
// given and read them at the hit (PatchPrimvars, NurbsPrimvars, CurvePrimvars,
// SubdivisionSurface).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "parse/ParamList.h"

namespace bxdflab {

/// Values laid out over a surface's parameters (a patch mesh's corners or
/// control points, a subdivision surface's points or face corners): read at a
/// hit, not blended from a tessellation's vertices.
class ParametricValues {
public:
    virtual ~ParametricValues() = default;
    /// The value on face `face` (a subdivision face, a curve segment; patches
    /// ignore it) at its parameters (u, v): `out` receives the primvar's
    /// components.
    virtual void at(unsigned face, float u, float v, float* out) const = 0;
};

/// Values kept as a request lays them out, one value of `components` floats
/// per item (a control point, a corner, a patch): what the values of patch
/// meshes, NURBS patches and curves have in common.
class LaidOutValues : public ParametricValues {
public:
    bool uniform() const { return m_uniform; }

protected:
    LaidOutValues(Param const& param, int components);
    /// Throws at the parameter unless it holds `wanted` values, `each` saying
    /// what one value belongs to ("one per patch").
    void requireCount(Param const& param, size_t wanted, char const* each) const;
    /// out[k] += weight x the value of `item`, for each component.
    void add(float* out, size_t item, float weight) const;
    /// out = the values of two items blended linearly: item0 at t = 0, item1 at t = 1.
    void mix(float* out, size_t item0, size_t item1, float t) const;
    /// out = the values of four corner items blended bilinearly at (u, v):
    /// item00 at (0, 0), item10 at (1, 0), item01 at (0, 1), item11 at (1, 1).
    void blend(float* out, size_t item00, size_t item10, size_t item01, size_t item11, float u,
               float v) const;

    std::vector<float> m_values;
    size_t m_c;
    bool m_uniform;      ///< "uniform": one value per piece (patch, segment)
    bool m_vertexClass;  ///< "vertex", or no class given (the specification's default)
};

struct Primvar {
    enum class Detail { Constant, Uniform, Varying };
    std::string name;
    ParamType type = ParamType::Float;
    int components = 1;  ///< floats per value: 1, 2 (float[2]), 3 (color, point, vector, normal)
    Detail detail = Detail::Constant;
    std::vector<float> values;
    std::shared_ptr<ParametricValues const> parametric;  ///< when set, the values (`values` is then empty)
};

class PrimvarSet {
public:
    Primvar const* find(std::string const& name) const {
        for (auto const& p : m_vars)
            if (p.name == name) return &p;
        return nullptr;
    }
    void add(Primvar var) { m_vars.push_back(std::move(var)); }
    bool empty() const { return m_vars.empty(); }
    std::vector<Primvar> const& all() const { return m_vars; }
    std::vector<Primvar>& all() { return m_vars; }

private:
    std::vector<Primvar> m_vars;
};

/// The names a renderer gives meaning to (geometry, not primvars a plugin reads).
bool isGeometryParameter(std::string const& name);

/// Floats per value of a parameter used as a primvar, or 0 when it cannot be one (strings, matrices).
int primvarComponents(Param const& param);

/// The texture coordinates a shape's parametric primvars give: "st", or "s"
/// and "t" read together; nothing when it has neither.
std::shared_ptr<ParametricValues const> parametricTextureCoordinates(PrimvarSet const& primvars);

/// The primvars in a shape's parameter list that are not geometry: those with
/// one value (constant, or uniform over a shape of one face), and, when
/// `corners` is not 0, varying or vertex ones with a value per corner (a
/// quadric's four). With `elements` not 0, values given once per element
/// (a particle of Points) are kept as uniform, one per primitive. Meshes find
/// the rest themselves (MeshBuilders). Marks them used.
PrimvarSet shapePrimvars(ParamList const& params, size_t corners = 0, size_t elements = 0);

/// Adds to `primvars` each parameter of `params` that varies over the shape
/// (neither geometry, nor constant, nor taken yet), its values read at a hit
/// through a `Values(param, components, layout)`: a LaidOutValues that throws
/// where the count does not fit the layout. Marks them used.
template <class Values, class Layout>
void addParametricPrimvars(PrimvarSet& primvars, ParamList const& params, Layout const& layout) {
    for (Param const& p : params.all()) {
        int const components = primvarComponents(p);
        if (components == 0 || p.used || isGeometryParameter(p.name()) || p.decl.storageClass == "constant") continue;
        auto values = std::make_shared<Values const>(p, components, layout);
        p.used = true;
        Primvar var;
        var.name = p.name();
        var.type = p.decl.type;
        var.components = components;
        var.detail = values->uniform() ? Primvar::Detail::Uniform : Primvar::Detail::Varying;
        var.parametric = std::move(values);
        primvars.add(std::move(var));
    }
}

/// The value of `var` at parameters (u, v) of a four-corner shape, or its
/// constant value: `out` receives var.components floats.
void primvarAtCorners(Primvar const& var, float u, float v, float* out);

}  // namespace bxdflab
