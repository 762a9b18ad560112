// PxrVisualize: quick looks at a scene while debugging, the way RenderMan's
// integrator of that name gives them. "string style":
//   shaded   each Bxdf lit by a light at the camera (as PxrDefault): the
//            material as it responds, with no shadows or scene lights to blame
//   normals  the shading normal Nn as a colour (x, y, z to red, green, blue, 0 at mid-grey)
//   st       the texture coordinates (s, t) as (red, green)
//   flat     one colour per Bxdf statement: which material is where
// "int normalCheck" [1] paints red wherever the viewer sees the back of a
// surface (the side Ngn does not point to): flipped normals show at once.
#include <cmath>
#include <string>

#include "common/DirectLighting.h"
#include "common/Params.h"

using namespace bxdflab;

namespace {

const char* const kStyles[] = {"shaded", "normals", "st", "flat"};

class Visualize : public DirectLighting {
public:
    Visualize(std::string style, bool normalCheck)
        : DirectLighting(1, 0, true), m_style(std::move(style)), m_normalCheck(normalCheck) {}

    bool WantsHeadlight() const override { return m_style == "shaded"; }
    void DescribeEffects(int numLights, RixEffects& effects) const override {
        if (m_style == "shaded") {
            DirectLighting::DescribeEffects(numLights, effects);
        } else {
            effects.Simulate("camera rays");
            effects.Skip("lights and shadows", ("PxrVisualize style " + m_style + " shows geometry only").c_str());
        }
        if (m_normalCheck) effects.Simulate("normal check: back faces in red");
    }

    void Integrate(RixShadingContext const& ctx, RixBxdf& bxdf, RixRNG& rng, RixIntegratorContext& ictx,
                   RtColorRGB* radiance) override {
        int const n = ctx.numPts;
        if (m_style == "shaded") {
            DirectLighting::Integrate(ctx, bxdf, rng, ictx, radiance);
        } else if (m_style == "normals") {
            RtNormal3 const* Nn;
            ctx.GetBuiltinVar(RixShadingContext::k_Nn, &Nn);
            for (int i = 0; i < n; ++i)
                radiance[i] = RtColorRGB(0.5f + 0.5f * Nn[i].x, 0.5f + 0.5f * Nn[i].y, 0.5f + 0.5f * Nn[i].z);
        } else if (m_style == "st") {
            float const *s, *t;
            ctx.GetBuiltinVar(RixShadingContext::k_s, &s);
            ctx.GetBuiltinVar(RixShadingContext::k_t, &t);
            for (int i = 0; i < n; ++i) radiance[i] = RtColorRGB(s[i], t[i], 0.0f);
        } else {  // flat: a colour from the Bxdf statement's index, well spread around the hue circle
            float hue = static_cast<float>(ctx.Id()) * 0.618034f;
            hue -= static_cast<float>(static_cast<int>(hue));
            RtColorRGB color(0.5f + 0.5f * std::cos(F_TWOPI * hue), 0.5f + 0.5f * std::cos(F_TWOPI * (hue - 1.0f / 3.0f)),
                             0.5f + 0.5f * std::cos(F_TWOPI * (hue - 2.0f / 3.0f)));
            for (int i = 0; i < n; ++i) radiance[i] = color;
        }
        if (!m_normalCheck) return;
        RtVector3 const* Vn;
        RtNormal3 const* Ngn;
        ctx.GetBuiltinVar(RixShadingContext::k_Vn, &Vn);
        ctx.GetBuiltinVar(RixShadingContext::k_Ngn, &Ngn);
        for (int i = 0; i < n; ++i)
            if (Vn[i].Dot(Ngn[i]) < 0.0f) radiance[i] = RtColorRGB(1.0f, 0.0f, 0.0f);
    }

private:
    std::string m_style;
    bool m_normalCheck;
};

}  // namespace

RIX_INTEGRATORCREATE {
    std::string style = ReadString(params, "style", "shaded");
    int normalCheck = 0;
    if (!ReadInt(params, messages, "normalCheck", 0, 0, 1, normalCheck)) return nullptr;
    for (const char* known : kStyles)
        if (style == known) return new Visualize(style, normalCheck != 0);
    messages->Error("unknown style \"%s\" (choose one of shaded, normals, st, flat)", style.c_str());
    return nullptr;
}

RIX_INTEGRATORDESTROY { delete integrator; }
