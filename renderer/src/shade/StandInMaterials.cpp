#include "shade/StandInMaterials.h"

#include <algorithm>

#include "core/RenderManNames.h"

namespace bxdflab {
namespace {

/// The parameter `name` as a plain (not connected) value of `type`; one written
/// without a type counts when its values can be that type, as RenderMan would
/// type it from the material's declaration.
std::optional<Param> plainValue(ParamList const& params, char const* name, ParamType type) {
    for (Param const& p : params.all()) {
        if (p.name() != name || p.decl.reference) continue;
        Param typed = p;
        if (typed.decl.untyped) giveType(typed, type);
        bool const fits = typed.decl.type == type || (type == ParamType::Float && typed.decl.type == ParamType::Int);
        if (!fits || typed.floats.size() < static_cast<size_t>(componentsOf(type))) continue;
        p.used = true;
        return typed;
    }
    return std::nullopt;
}

/// The first of `names` the material sets as a plain (not connected) colour.
std::optional<Vec3> colorOf(ParamList const& params, std::initializer_list<char const*> names) {
    for (char const* name : names)
        if (std::optional<Param> p = plainValue(params, name, ParamType::Color))
            return Vec3(p->floats[0], p->floats[1], p->floats[2]);
    return std::nullopt;
}

std::optional<float> floatOf(ParamList const& params, char const* name) {
    if (std::optional<Param> p = plainValue(params, name, ParamType::Float)) return p->floats[0];
    return std::nullopt;
}

/// Connects the stand-in's `to` where the material connects `from` to a
/// pattern (a textured diffuse colour stays textured); true if it did. Where
/// the pattern cannot be loaded, `to` takes `unconnected`: the original's value
/// without the connection, not the stand-in's own default.
bool carryConnection(MaterialDesc const& material, char const* from, MaterialDesc& standIn, std::string const& to,
                     Vec3 const& unconnected) {
    auto found = material.connections.find(from);
    if (found == material.connections.end()) return false;
    for (Param const& p : material.params.all())
        if (p.name() == from && p.decl.reference) {
            p.used = true;
            Param link = p;
            link.decl.name = to;
            link.fallback = {unconnected.x, unconnected.y, unconnected.z};
            standIn.params.add(link);
            standIn.connections[to] = found->second;
            return true;
        }
    return false;
}

float luminance(Vec3 const& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

/// Where the stand-in's `to` is connected, puts a gain between it and its pattern:
/// a PxrMix of the pattern's colour toward black, (1 - gain) * colour, added to the
/// scene's patterns. The stand-in has no gain of its own, and a textured diffuse
/// colour times diffuseGain must stay both.
void applyGain(MaterialDesc& standIn, std::string const& to, float gain, std::vector<PatternDesc>& patterns) {
    auto connected = standIn.connections.find(to);
    if (connected == standIn.connections.end() || gain == 1.0f) return;
    PatternDesc mix;
    mix.plugin = "PxrMix";
    mix.handle = standIn.handle + ":" + to + " gain";
    mix.where = standIn.where;
    for (Param const& p : standIn.params.all())
        if (p.name() == to) {
            Param input = p;  // the texture's colour, with its fallback: the untextured colour
            input.decl.name = "color1";
            mix.params.add(input);
        }
    mix.params.add(colorParam("color2", Vec3(0.0f)));
    mix.params.add(floatParam("mix", 1.0f - gain));
    Param noClamp = floatParam("clampMix", 0.0f);  // a gain above 1 brightens
    noClamp.decl.type = ParamType::Int;
    noClamp.ints = {0};
    mix.params.add(noClamp);
    mix.connections["color1"] = connected->second;
    patterns.push_back(std::move(mix));
    connected->second = Connection{static_cast<int>(patterns.size()) - 1, "resultRGB", standIn.where};
}

}  // namespace

std::optional<StandIn> standInFor(MaterialDesc const& material, std::vector<PatternDesc>& patterns) {
    std::string const& name = material.plugin;
    if (!isRenderMansOwnName(name)) return std::nullopt;
    ParamList const& in = material.params;
    StandIn s;
    s.material.handle = material.handle;
    s.material.where = material.where;
    s.material.plugin = "PxrDisney";
    ParamList& out = s.material.params;

    float const refractionGain = floatOf(in, "refractionGain").value_or(0.0f);
    bool const surface = name == "PxrSurface" || name == "PxrLayerSurface";
    bool const lama = name == "LamaDielectric";
    if (name == "PxrGlass" || name == "PxrLMGlass" || lama || (surface && refractionGain > 0.0f)) {
        // A refracting dielectric: chapter 10's glass, with the index, roughness (GGX alpha, as
        // RenderMan's roughness is here) and refraction tint of the material's glass.
        s.material.plugin = "StockGlass";
        char const* const iorName = surface ? "glassIor" : name == "PxrLMGlass" ? "eta" : lama ? "IOR" : "ior";
        float const roughness = floatOf(in, surface ? "glassRoughness" : "roughness").value_or(surface ? 0.1f : 0.0f);
        float const gain = surface ? refractionGain : floatOf(in, "refractionGain").value_or(1.0f);
        Vec3 const tint = colorOf(in, {"refractionColor", "transmissionTint"}).value_or(Vec3(1.0f));
        out.add(floatParam("ior", floatOf(in, iorName).value_or(1.5f)));
        out.add(floatParam("roughness", std::clamp(roughness, 0.0f, 1.0f)));
        out.add(colorParam("transmissionColor", tint * std::clamp(gain, 0.0f, 1.0f)));
        s.note = std::string("a refracting glass of its index, roughness and refraction colour (") +
                 (surface ? "its other lobes, " : "") + "absorption and thin glass are not rendered)";
    } else if (surface) {
        // Diffuse colour times gain; the artistic specular's face colour as a dielectric's reflectance.
        float const gain = floatOf(in, "diffuseGain").value_or(1.0f);
        Vec3 const colour = colorOf(in, {"diffuseColor"}).value_or(Vec3(0.18f));
        Vec3 face = colorOf(in, {"specularFaceColor"}).value_or(Vec3(0.0f));
        if (floatOf(in, "specularFresnelMode").value_or(0.0f) == 1.0f) {
            // Physical Fresnel: the reflectance at normal view of an index n and extinction k,
            // ((n-1)^2 + k^2) / ((n+1)^2 + k^2), in place of the artist's face colour.
            Vec3 const n = glm::max(colorOf(in, {"specularIor"}).value_or(Vec3(1.5f)), Vec3(0.0f));
            Vec3 const k = glm::max(colorOf(in, {"specularExtinctionCoeff"}).value_or(Vec3(0.0f)), Vec3(0.0f));
            face = ((n - 1.0f) * (n - 1.0f) + k * k) / ((n + 1.0f) * (n + 1.0f) + k * k);
        }
        bool const textured = carryConnection(material, "diffuseColor", s.material, "baseColor", colour);
        // No diffuse and a face colour brighter than any dielectric's (PxrDisney's specular 1 reflects
        // 0.08): what exporters write for a metal, which reflects its face colour.
        bool const metal = !textured && luminance(colour * gain) < 1e-3f && luminance(face) > 0.08f;
        if (textured)
            applyGain(s.material, "baseColor", gain, patterns);  // the gain, on the texture or its fallback
        else
            out.add(colorParam("baseColor", metal ? glm::clamp(face, Vec3(0.0f), Vec3(1.0f)) : colour * gain));
        if (metal) out.add(floatParam("metallic", 1.0f));
        out.add(floatParam("specular", std::clamp(luminance(face) / 0.08f, 0.0f, 1.0f)));
        out.add(floatParam("roughness", std::sqrt(std::clamp(floatOf(in, "specularRoughness").value_or(0.2f), 0.0f, 1.0f))));
        if (auto coat = colorOf(in, {"clearcoatFaceColor"})) out.add(floatParam("clearcoat", std::min(1.0f, luminance(*coat) / 0.04f)));
        // Glow: the surface itself emits glowGain x glowColor (off by default), PxrDisney's emitColor.
        float const glowGain = floatOf(in, "glowGain").value_or(0.0f);
        Vec3 const glow = glm::max(colorOf(in, {"glowColor"}).value_or(Vec3(1.0f)), Vec3(0.0f));  // emits, never absorbs
        if (glowGain > 0.0f) {
            if (carryConnection(material, "glowColor", s.material, "emitColor", glow))
                applyGain(s.material, "emitColor", glowGain, patterns);
            else
                out.add(colorParam("emitColor", glow * glowGain));
        }
        s.note = std::string(metal ? "a PxrDisney metal of its specular face colour, with its glow"
                                   : "PxrDisney with its diffuse colour, specular face colour and glow") +
                 " (no layering, transmission or subsurface)";
    } else if (name == "PxrLMPlastic") {
        Vec3 const diffuse = colorOf(in, {"diffuseColor"}).value_or(Vec3(0.5f));
        if (!carryConnection(material, "diffuseColor", s.material, "baseColor", diffuse))
            out.add(colorParam("baseColor", diffuse));
        out.add(floatParam("roughness", std::sqrt(std::clamp(floatOf(in, "specularRoughness").value_or(0.01f), 0.0f, 1.0f))));
        s.note = "PxrDisney with its diffuse colour";
    } else if (name == "LamaConductor") {
        // The artist's conductor: its colour at normal incidence (times tint) as a metal's base colour.
        Vec3 const tint = colorOf(in, {"tint"}).value_or(Vec3(1.0f));
        out.add(colorParam("baseColor", colorOf(in, {"reflectivity"}).value_or(Vec3(0.9f)) * tint));
        out.add(floatParam("metallic", 1.0f));
        out.add(floatParam("roughness", std::sqrt(std::clamp(floatOf(in, "roughness").value_or(0.1f), 0.0f, 1.0f))));
        s.note = "a PxrDisney metal of its reflectivity (its edge colour and complex index are not used)";
    } else if (name == "PxrLMMetal") {
        out.add(colorParam("baseColor", colorOf(in, {"specularColor"}).value_or(Vec3(0.9f))));
        out.add(floatParam("metallic", 1.0f));
        out.add(floatParam("roughness", std::sqrt(std::clamp(floatOf(in, "roughness").value_or(0.01f), 0.0f, 1.0f))));
        s.note = "a PxrDisney metal (its eta and kappa are not used)";
    } else if (name == "PxrBlack") {
        // Reflects, transmits and emits nothing, and is opaque: exactly a diffuse surface of albedo 0.
        s.material.plugin = "PxrDiffuse";
        out.add(colorParam("diffuseColor", Vec3(0.0f)));
        s.note = "PxrDiffuse in black, which is what PxrBlack is: it reflects nothing";
    } else {
        // PxrLMDiffuse, PxrDiffuse-likes and anything else: a diffuse surface in its colour.
        s.material.plugin = "PxrDiffuse";
        bool connected = false;
        for (char const* from : {"diffuseColor", "baseColor", "frontColor"})
            if (!connected) connected = carryConnection(material, from, s.material, "diffuseColor", Vec3(0.5f));
        std::optional<Vec3> color = colorOf(in, {"diffuseColor", "baseColor", "frontColor", "color", "emitColor"});
        if (color && !connected) out.add(colorParam("diffuseColor", *color));
        s.note = color || connected ? "PxrDiffuse in its colour" : "PxrDiffuse";
    }
    // Presence (PxrSurface's cut-out opacity, RenderMan 21's too): PxrDisney and PxrDiffuse carry
    // it over, value or pattern; the glass stand-in does not.
    std::optional<float> const presence = floatOf(in, "presence");
    bool const cutOut = material.connections.count("presence") > 0 || (presence && *presence < 1.0f);
    if (cutOut && s.material.plugin != "StockGlass") {
        if (!carryConnection(material, "presence", s.material, "presence", Vec3(1.0f)) && presence)
            out.add(floatParam("presence", std::clamp(*presence, 0.0f, 1.0f)));
    } else {
        s.cutOut = cutOut;
    }
    // A normal map or bump pattern stays on the surface (PxrDisney has bumpNormal; PxrDiffuse does not).
    if (s.material.plugin == "PxrDisney") carryConnection(material, "bumpNormal", s.material, "bumpNormal", Vec3(0.0f));
    return s;
}

}  // namespace bxdflab
