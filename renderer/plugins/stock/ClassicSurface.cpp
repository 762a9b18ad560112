// ClassicSurface — what the classic RenderMan surface shaders of older RIB
// files (`Surface "plastic" "Ks" [0.5]`) become: the scene reader turns each
// such Surface request into this Bxdf, with the shader's name in "shader" and
// the Color, Opacity and ambient light in effect.
//
//   constant        Cs, unlit (an emitter with no reflection)
//   defaultsurface  Cs (Ka + Kd (I.N)^2), unlit: PRMan's default shader, which
//                   shades by the angle a surface is seen at, whatever the lights
//   matte           Kd Cs / pi
//   plastic         Kd Cs / pi  +  Ks specularcolor * glossy lobe
//   paintedplastic  as plastic, Cs times the texture map at (s, t)
//   metal           Ks Cs * glossy lobe
//   shinymetal      as metal (its environment map is not read)
//
// The scene reader reads paintedplastic's texturename with a PxrTexture node
// connected to textureColor (white where there is none).
//
// plus Ka Cs ambient emitted by all but constant (the shaders' ambient()
// term, from the scene's ambientlight shaders). Cs and Os are the shape's
// primvars when it has them ("color Cs" per vertex, say), else the Color and
// Opacity in effect (surfaceColor, surfaceOpacity).
//
// An Opacity below 1 makes the surface present with probability p, the mean
// of the Opacity's colours, and its colour where present Cs Os / p: on average
// Os of the shaded surface over 1 - p of what lies behind, which is the
// classic shaders' Ci = Os Cs ... composited (exactly so for a grey Opacity;
// a coloured one shows what is behind in grey, not tinted). Shadows pass the
// same share. A shape's own "Os" primvar darkens it as before, without showing
// through.
//
// The classic shaders' specular() is a Blinn lobe max(0, N.H)^n with no
// cosine and no normalisation. The RenderMan specification writes
// n = 1/roughness, but PRMan's highlights are far tighter: BMRT and Aqsis
// emulate them with n = 8/roughness, and that fits the highlight of a PRMan
// render of the standard metal (roughness 0.1) near its peak. Here the glossy
// lobe is the chapter 6 Phong lobe around the mirror direction, unnormalised
// and divided by pi:
//   f_s = Ks specularcolor / pi * max(0, R.L)^(2 / roughness).
// The exponent n/4 gives the same highlight width (the half vector turns half
// as fast as the mirror direction), and since the lights of those files get a
// factor pi in the scene reader (the classic diffuse() has no 1/pi), the
// highlight's peak keeps the brightness the files were made for; a lobe of
// at most 1/pi never reflects more than the surface receives.
#include <algorithm>
#include <cstring>
#include <new>

#include "Emissive.h"
#include "Plastic.h"
#include "RixShadingUtils.h"
#include "StockBxdf.h"

namespace {

enum class Shader { Constant, Default, Matte, Plastic, Metal };

/// The plastic Bxdf with the classic ambient term as emission.
class ClassicBxdf : public Plastic {
public:
    /// `glow` has one colour per point.
    ClassicBxdf(RixShadingContext const* sc, RixBxdfFactory* factory, PlasticParams const& params, RtColorRGB const* glow)
        : Plastic(sc, factory, params), m_glow(glow) {}
    bool EmitLocal(RtColorRGB* result) override {
        bool any = false;
        for (int i = 0; i < shadingCtx->numPts; ++i) {
            result[i] = m_glow[i];
            any = any || !m_glow[i].IsBlack();
        }
        return any;
    }

private:
    RtColorRGB const* m_glow;
};

class ClassicSurfaceFactory : public stockbxdfs::StockBxdfFactory {
public:
    enum Param {
        k_shader, k_surfaceColor, k_surfaceOpacity, k_ambient, k_Ka, k_Kd, k_Ks, k_roughness, k_specularcolor,
        k_textureColor
    };

    RixSCParamInfo const* GetParamTable() override {
        static RixSCParamInfo table[] = {
            RixSCParamInfo(RtUString("shader"), k_RixSCString, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("surfaceColor"), k_RixSCColor, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("surfaceOpacity"), k_RixSCColor, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("ambient"), k_RixSCColor, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("Ka"), k_RixSCFloat, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("Kd"), k_RixSCFloat, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("Ks"), k_RixSCFloat, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("roughness"), k_RixSCFloat, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("specularcolor"), k_RixSCColor, k_RixSCScatterInput),
            RixSCParamInfo(RtUString("textureColor"), k_RixSCColor, k_RixSCScatterInput),
            RixSCParamInfo()};
        return table;
    }
    void Synchronize(RixContext& ctx, RixSCSyncMsg msg, RixParameterList const*) override {
        if (msg != k_RixSCRenderBegin) return;
        g_plasticDiffuseLobe = RixBXLookupLobeByName(ctx, false, false, true, false, 0, "Diffuse");
        g_plasticSpecularLobe = RixBXLookupLobeByName(ctx, false, true, true, false, 0, "Specular");
        g_plasticTraits = RixBXLobeTraits(g_plasticDiffuseLobe) | RixBXLobeTraits(g_plasticSpecularLobe);
    }

    void CreateInstanceData(RixContext&, RtUString const, RixParameterList const* params,
                            InstanceData* instance) override {
        RixSCType type;
        RixSCConnectionInfo given = k_RixSCDefaultValue;
        if (params->GetParamInfo(k_surfaceOpacity, &type, &given) != 0 || given != k_RixSCParameterListValue) return;
        RtColorRGB opacity(1.0f);
        params->EvalParam(k_surfaceOpacity, -1, &opacity);
        // Any non-null pointer marks the instance as showing through; nothing to free.
        if (presenceOf(opacity) < 1.0f) instance->data = this;
    }
    int GetInstanceHints(RtPointer instanceData) const override {
        return instanceData ? k_ComputesPresence : k_TriviallyOpaque;
    }
    RixOpacity* BeginOpacity(RixShadingContext const* sCtx, RixSCShadingMode, void*, RtPointer) override {
        RtColorRGB const white(1.0f);
        RtColorRGB const* Os;
        sCtx->EvalParam(k_surfaceOpacity, -1, &Os, &white, false);
        RixShadingContext::Allocator pool(sCtx);
        float* presence = pool.AllocForBxdf<float>(1);
        *presence = presenceOf(*Os);
        return new (pool.AllocForBxdf<PxrSurfaceOpacity>(1)) PxrSurfaceOpacity(sCtx, this, presence, nullptr, true);
    }

    RixBxdf* BeginScatter(RixShadingContext const* sCtx, RixBXLobeTraits const&, RixSCShadingMode, void*,
                          RtPointer instanceData) override {
        // Every parameter but the texture's colour is uniform: the scene reader writes one value per material.
        RtUString const* name;
        RtColorRGB const *Cs, *Os, *ambient, *specularColor;
        float const *Ka, *Kd, *Ks, *roughness;
        RtUString const plastic("plastic");
        RtColorRGB const white(1.0f), black(0.0f);
        float const one = 1.0f, tenth = 0.1f;
        sCtx->EvalParam(k_shader, -1, &name, &plastic, false);
        sCtx->EvalParam(k_surfaceColor, -1, &Cs, &white, false);
        sCtx->EvalParam(k_surfaceOpacity, -1, &Os, &white, false);
        sCtx->EvalParam(k_ambient, -1, &ambient, &black, false);
        sCtx->EvalParam(k_specularcolor, -1, &specularColor, &white, false);
        RtColorRGB const* textureColor;
        sCtx->EvalParam(k_textureColor, -1, &textureColor, &white, true);
        Shader shader = shaderNamed(name->CStr());
        // The shaders' own defaults: matte Ka 1 Kd 1; plastic Ka 1 Kd .5 Ks .5; metal Ka 1 Ks 1; roughness .1;
        // defaultsurface Ka .2 Kd .8.
        float const kdDefault = shader == Shader::Matte ? 1.0f : shader == Shader::Default ? 0.8f : 0.5f;
        float const ksDefault = shader == Shader::Metal ? 1.0f : 0.5f;
        float const kaDefault = shader == Shader::Default ? 0.2f : one;
        sCtx->EvalParam(k_Ka, -1, &Ka, &kaDefault, false);
        sCtx->EvalParam(k_Kd, -1, &Kd, &kdDefault, false);
        sCtx->EvalParam(k_Ks, -1, &Ks, &ksDefault, false);
        sCtx->EvalParam(k_roughness, -1, &roughness, &tenth, false);

        // The shape's own Cs and Os, where it has them.
        RtColorRGB const *CsVarying = nullptr, *OsVarying = nullptr;
        if (sCtx->GetPrimVar(RtUString("Cs"), &CsVarying) == k_RixSCInvalidDetail) CsVarying = nullptr;
        if (sCtx->GetPrimVar(RtUString("Os"), &OsVarying) == k_RixSCInvalidDetail) OsVarying = nullptr;
        RixShadingContext::Allocator pool(sCtx);
        int const n = sCtx->numPts;
        // Where the surface is present only sometimes, it carries the rest of its Opacity's weight.
        float const present = instanceData ? presenceOf(*Os) : 1.0f;
        RtColorRGB const opacity = present > 0.0f ? *Os / present : *Os;
        RtColorRGB* color = pool.AllocForBxdf<RtColorRGB>(n);
        // A reflectance below 0 means nothing to light; where a file's Cs holds other data for its own
        // shader (negative values), the stand-in reflects none of that channel rather than light below black.
        for (int i = 0; i < n; ++i) {
            color[i] = (CsVarying ? CsVarying[i] : *Cs) * (OsVarying ? OsVarying[i] : opacity) * textureColor[i];
            color[i] = RtColorRGB(std::max(color[i].r, 0.0f), std::max(color[i].g, 0.0f),
                                  std::max(color[i].b, 0.0f));
        }
        if (shader == Shader::Default) {
            RtVector3 const* Vn;
            RtNormal3 const* Nn;
            sCtx->GetBuiltinVar(RixShadingContext::k_Vn, &Vn);
            sCtx->GetBuiltinVar(RixShadingContext::k_Nn, &Nn);
            for (int i = 0; i < n; ++i) {
                float const facing = Dot(Vn[i], Nn[i]);
                color[i] = color[i] * (*Ka + *Kd * facing * facing);
            }
        }
        if (shader == Shader::Constant || shader == Shader::Default)
            return new (pool.AllocForBxdf<Emissive>(1)) Emissive(sCtx, this, color);
        PlasticParams params;
        RtColorRGB* diffuseColors = pool.AllocForBxdf<RtColorRGB>(n);
        RtColorRGB* specularColors = pool.AllocForBxdf<RtColorRGB>(n);
        RtColorRGB* glow = pool.AllocForBxdf<RtColorRGB>(n);
        float* gloss = pool.AllocForBxdf<float>(n);
        for (int i = 0; i < n; ++i) {
            diffuseColors[i] = shader == Shader::Metal ? black : color[i] * *Kd;
            specularColors[i] = shader == Shader::Matte ? black
                                : (shader == Shader::Metal ? color[i] : *specularColor) * (*Ks * F_INVPI);
            glow[i] = color[i] * *ambient * *Ka;
            gloss[i] = 2.0f / RixMax(*roughness, 1e-4f);
        }
        params.diffuseColor = diffuseColors;
        params.specularColor = specularColors;
        params.gloss = gloss;
        params.normalize = 0;
        return new (pool.AllocForBxdf<ClassicBxdf>(1)) ClassicBxdf(sCtx, this, params, glow);
    }

private:
    /// How often a surface of this Opacity is there: the mean of its colours, within [0, 1].
    static float presenceOf(RtColorRGB const& opacity) {
        return RixMin(RixMax((opacity.r + opacity.g + opacity.b) / 3.0f, 0.0f), 1.0f);
    }
    static Shader shaderNamed(char const* name) {
        if (!std::strcmp(name, "constant")) return Shader::Constant;
        if (!std::strcmp(name, "defaultsurface")) return Shader::Default;
        if (!std::strcmp(name, "matte")) return Shader::Matte;
        if (!std::strcmp(name, "metal") || !std::strcmp(name, "shinymetal")) return Shader::Metal;
        return Shader::Plastic;
    }
};

}  // namespace

STOCK_BXDF_PLUGIN(ClassicSurfaceFactory)
