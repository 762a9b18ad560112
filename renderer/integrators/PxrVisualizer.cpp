// PxrVisualizer: quick looks at a scene while debugging, with no lights or
// materials to set up, as RenderMan's integrator of that name gives them.
// "string style":
//   shaded   (the default) grey by how squarely the surface faces the camera,
//            |Nn . Vn|: a normal that points into its surface shades the same
//   bxdf     each Bxdf lit by a light at the camera (as PxrDefault): the
//            material as it responds, with no shadows or scene lights to blame
//   normals  the shading normal in object space as a colour (x, y, z to red,
//            green, blue, 0 at mid-grey)
//   st       the texture coordinates (s, t) as (red, green)
//   flat     one colour per Bxdf statement: which material is where
//   matcap   RenderMan looks the normal up in the "matCap" image; here it is
//            shown as shaded, with a warning
// "int normalCheck" [1] paints orange wherever the viewer sees the back of a
// surface (the side Ngn does not point to): flipped normals show at once.
// "int wireframe" (on in RenderMan unless set to 0) would draw the tessellation
// over the image; it is not drawn here, and a warning says so.
#include <cmath>
#include <string>

#include "RixPredefinedStrings.hpp"
#include "common/DirectLighting.h"
#include "common/Params.h"

using namespace bxdflab;

namespace {

const char* const kStyles[] = {"shaded", "bxdf", "normals", "st", "flat", "matcap"};

class Visualizer : public DirectLighting {
public:
    Visualizer(std::string style, bool normalCheck, bool wireframe)
        : DirectLighting(1, 0, true),
          m_style(style == "matcap" ? "shaded" : std::move(style)),
          m_normalCheck(normalCheck),
          m_wireframe(wireframe) {}

    bool WantsHeadlight() const override { return m_style == "bxdf"; }
    void DescribeEffects(int numLights, RixEffects& effects) const override {
        if (m_style == "bxdf") {
            DirectLighting::DescribeEffects(numLights, effects);
        } else {
            effects.Simulate("camera rays");
            effects.Skip("lights and shadows",
                         ("PxrVisualizer style " + m_style + " shows geometry only").c_str());
        }
        if (m_normalCheck) effects.Simulate("normal check: back faces in orange");
        if (m_wireframe) effects.Skip("wireframe", "the tessellation is not drawn over the image");
    }

    void Integrate(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                   RtColorRGB* radiance) override {
        int const n = ctx.numPts;
        if (m_style == "bxdf") {
            DirectLighting::Integrate(ctx, bxdf, rng, ictx, radiance);
        } else if (m_style == "shaded") {
            RtNormal3 const* Nn;
            RtVector3 const* Vn;
            ctx.GetBuiltinVar(RixShadingContext::k_Nn, &Nn);
            ctx.GetBuiltinVar(RixShadingContext::k_Vn, &Vn);
            for (int i = 0; i < n; ++i) radiance[i] = RtColorRGB(std::fabs(Nn[i].Dot(Vn[i])));
        } else if (m_style == "normals") {
            RtNormal3 const* Nn;
            ctx.GetBuiltinVar(RixShadingContext::k_Nn, &Nn);
            RtNormal3* N = static_cast<RtNormal3*>(RixAlloca(sizeof(RtNormal3) * static_cast<size_t>(n)));
            for (int i = 0; i < n; ++i) N[i] = Nn[i];
            ctx.Transform(RixShadingContext::k_AsNormals, Rix::k_current, Rix::k_object, N);
            for (int i = 0; i < n; ++i) {
                RtNormal3 o = Normalize(N[i]);
                radiance[i] = RtColorRGB(0.5f + 0.5f * o.x, 0.5f + 0.5f * o.y, 0.5f + 0.5f * o.z);
            }
        } else if (m_style == "st") {
            float const *s, *t;
            ctx.GetBuiltinVar(RixShadingContext::k_s, &s);
            ctx.GetBuiltinVar(RixShadingContext::k_t, &t);
            for (int i = 0; i < n; ++i) radiance[i] = RtColorRGB(s[i], t[i], 0.0f);
        } else {  // flat: a colour from the Bxdf statement's index, well spread around the hue circle
            float hue = static_cast<float>(ctx.Id()) * 0.618034f;
            hue -= static_cast<float>(static_cast<int>(hue));
            RtColorRGB color(0.5f + 0.5f * std::cos(F_TWOPI * hue),
                             0.5f + 0.5f * std::cos(F_TWOPI * (hue - 1.0f / 3.0f)),
                             0.5f + 0.5f * std::cos(F_TWOPI * (hue - 2.0f / 3.0f)));
            for (int i = 0; i < n; ++i) radiance[i] = color;
        }
        if (!m_normalCheck) return;
        RtVector3 const* Vn;
        RtNormal3 const* Ngn;
        ctx.GetBuiltinVar(RixShadingContext::k_Vn, &Vn);
        ctx.GetBuiltinVar(RixShadingContext::k_Ngn, &Ngn);
        for (int i = 0; i < n; ++i)
            if (Vn[i].Dot(Ngn[i]) < 0.0f) radiance[i] = RtColorRGB(1.0f, 0.5f, 0.0f);
    }

private:
    std::string m_style;
    bool m_normalCheck, m_wireframe;
};

}  // namespace

RIX_INTEGRATORCREATE {
    std::string style = ReadString(params, "style", "shaded");
    int normalCheck = 0, wireframe = 1;
    if (!ReadInt(params, messages, "normalCheck", 0, 0, 1, normalCheck) ||
        !ReadInt(params, messages, "wireframe", 1, 0, 1, wireframe))
        return nullptr;
    bool known = false;
    for (const char* name : kStyles) known = known || style == name;
    if (!known) {
        messages->Error("unknown style \"%s\" (choose one of shaded, bxdf, normals, st, flat, matcap)",
                        style.c_str());
        return nullptr;
    }
    if (style == "matcap")
        messages->Warning(
            "style matcap: the \"matCap\" image is not looked up; the surface is shown as style shaded");
    if (wireframe != 0)
        messages->Warning(
            "wireframe 1 (RenderMan's default): the tessellation is not drawn over the image "
            "(\"int wireframe\" [0] says it is not wanted)");
    return new Visualizer(style, normalCheck != 0, wireframe != 0);
}

RIX_INTEGRATORDESTROY { delete integrator; }
