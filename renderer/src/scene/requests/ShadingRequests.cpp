// Shading and lights: RIS Bxdfs and lights (Bxdf, Light), the classic
// shaders of older RIB files (Surface, LightSource, Illuminate), and the
// material a surface gets when it names none.
#include <algorithm>
#include <cmath>

#include <filesystem>
#include <fstream>
#include <utility>

#include "core/ImageFiles.h"
#include "core/RenderManNames.h"
#include "core/Spelling.h"
#include "scene/SceneBuilder.h"
#include "scene/lights/InfiniteLights.h"
#include "scene/lights/LightFactory.h"
#include "scene/lights/MeshLight.h"

namespace bxdflab {
namespace {

namespace fs = std::filesystem;

/// The classic surface shaders this renderer gives their meaning (stock
/// plugin ClassicSurface), each with its parameters as the RenderMan
/// Interface Specification lists them; null for any other shader.
std::vector<std::string> const* classicSurfaceParameters(std::string const& shader) {
    static const std::map<std::string, std::vector<std::string>> parameters = {
        {"constant", {}},
        {"defaultsurface", {"Ka", "Kd"}},
        {"matte", {"Ka", "Kd"}},
        {"metal", {"Ka", "Ks", "roughness"}},
        {"shinymetal", {"Ka", "Ks", "Kr", "roughness", "texturename"}},
        {"plastic", {"Ka", "Kd", "Ks", "roughness", "specularcolor"}},
        {"paintedplastic", {"Ka", "Kd", "Ks", "roughness", "specularcolor", "texturename"}},
    };
    auto found = parameters.find(shader);
    return found == parameters.end() ? nullptr : &found->second;
}

/// The standard shader an unknown one most likely is, and why: the one its
/// name holds ("RCPlastic", "TLFresnelPlastic", "rsmetal", "RCMatte"), else
/// plastic when it has a specular weight Ks (given, or declared in its source), else matte, which most shaders
/// of a scene's own grew from: its Ka * ambient() is lit by the scene's
/// ambientlight as theirs would be.
std::pair<std::string, std::string> lookalikeSurface(std::string const& name, ParamList const& params,
                                                     bool sourceHasKs) {
    std::string const lower = lowered(name);
    for (char const* standard : {"plastic", "matte", "metal", "constant"})
        if (lower.find(standard) != std::string::npos) return {standard, "the standard one its name suggests"};
    if (params.has("Ks") || sourceHasKs) return {"plastic", "the standard one its specular weight Ks suggests"};
    return {"matte", "the standard shader most shaders of a scene's own grew from"};
}

}  // namespace

void SceneBuilder::bxdf(RequestReader& in) {
    MaterialDesc material;
    material.plugin = in.string("Bxdf plugin name");
    material.handle = in.string("Bxdf handle");
    material.params = in.params();
    material.where = in.where();
    if (material.plugin.empty()) in.fail(in.where(), "the plugin name is empty");
    // RenderMan's volume Bxdf fills the inside of its shapes with a medium; there are no volumes here.
    state().volume = material.plugin == "PxrVolume";
    if (state().volume) {
        warnOnce("volume", in.where(), "Bxdf \"PxrVolume\": volumes are not rendered; its shapes are left out");
        return;
    }
    if (!building()) return;
    material.connections = connectionsOf(material.params, "Bxdf \"" + material.handle + "\"");
    state().material = static_cast<int>(m_scene.materials.size());
    m_scene.materials.push_back(std::move(material));
}

void SceneBuilder::pattern(RequestReader& in) {
    PatternDesc node;
    node.plugin = in.string("pattern plugin name");
    node.handle = in.string("pattern handle");
    node.params = in.params();
    node.where = in.where();
    if (node.plugin.empty()) in.fail(in.where(), "the plugin name is empty");
    if (node.handle.find(':') != std::string::npos)
        in.fail(in.where(), "a pattern handle may not contain ':' (it separates handle and output in references)");
    if (!building()) return;
    // Resolved before this node is known by its handle: a node cannot reach itself.
    node.connections = connectionsOf(node.params, "Pattern \"" + node.handle + "\"");
    m_patternHandles[node.handle] = static_cast<int>(m_scene.patterns.size());
    m_scene.patterns.push_back(std::move(node));
}

std::string SceneBuilder::oslShaderNamed(std::string const& name) const {
    if (name.find('/') != std::string::npos) return {};
    return shaderFileNamed(name, {".oso", ".osl"});
}

std::string SceneBuilder::shaderFileNamed(std::string const& name, std::vector<char const*> const& extensions) const {
    std::vector<fs::path> folders(m_shaderSearchPath.begin(), m_shaderSearchPath.end());
    folders.push_back(fs::path(m_scene.file).parent_path());
    folders.push_back(".");  // where RenderMan's users compile their shaders
    for (fs::path const& folder : folders)
        for (char const* extension : extensions) {
            fs::path const file = folder / (name + extension);
            std::error_code error;
            if (fs::is_regular_file(file, error)) return file.lexically_normal().string();
        }
    return {};
}

DeclaredDefaults const& SceneBuilder::declaredDefaults(std::string const& name) {
    std::string key = name;
    for (std::string const& folder : m_shaderSearchPath) key += '\n' + folder;
    auto [entry, added] = m_declaredDefaults.try_emplace(key);
    if (!added) return entry->second;
    std::string const shader = fs::path(name).filename().string();
    entry->second.file = shader.empty() ? std::string() : shaderFileNamed(name, {".sl"});
    if (entry->second.file.empty()) return entry->second;
    // A parameter list is at the top of its file: a file larger than any shader is read no further.
    constexpr size_t kLongestRead = 1 << 20;
    std::ifstream in(entry->second.file, std::ios::binary);
    std::string text(kLongestRead, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<size_t>(in.gcount()));
    entry->second.values = surfaceShaderDefaults(text, shader);
    entry->second.ownColours = ownSurfaceColours(text, shader);
    entry->second.unlit = readsNoLight(text);
    return entry->second;
}

std::map<std::string, Connection> SceneBuilder::connectionsOf(ParamList const& params, std::string const& owner) {
    std::map<std::string, Connection> connections;
    for (Param const& p : params.all()) {
        if (!p.decl.reference) continue;
        p.used = true;
        std::string const target = p.strings.empty() ? "" : p.strings[0];
        size_t colon = target.find(':');
        if (colon == std::string::npos || colon == 0 || colon + 1 == target.size())
            throw RibError(p.location, owner + " parameter \"" + p.name() + "\": a reference is \"handle:output\", not \"" +
                                           target + "\"");
        std::string handle = target.substr(0, colon);
        auto found = m_patternHandles.find(handle);
        if (found == m_patternHandles.end()) {
            // RenderMan renders on without the connection; so does this renderer, saying where.
            m_diagnostics.warn(p.location, owner + " parameter \"" + p.name() + "\" refers to pattern \"" + handle +
                                               "\", which is not declared before it (patterns come before what uses "
                                               "them); the parameter is left unconnected, at the plugin's default");
            continue;
        }
        connections[p.name()] = {found->second, target.substr(colon + 1), p.location};
    }
    return connections;
}

void SceneBuilder::surface(RequestReader& in) {
    std::string name = in.string("surface shader name");
    std::string const given = name;  // what messages call it, whatever it is rendered as
    ParamList params = in.params();
    std::vector<std::string> const* known = classicSurfaceParameters(name);
    std::string const base = std::filesystem::path(name).filename().string();
    // A shader the scene brings (its source beside it or on the shader search path) declares
    // its own defaults: the scene was lit for them (a diffuse weight of 0.04, a metal's Ks of 3).
    static DeclaredDefaults const none;
    DeclaredDefaults const& source = known ? none : declaredDefaults(name);
    ShaderDefaults const& declared = source.values;
    auto const useDeclared = [&](std::string const& standardShader) {
        std::string list;
        for (std::string const& standard : *classicSurfaceParameters(standardShader)) {
            auto const value = declared.find(standard);
            bool const colour = standard == "specularcolor";
            if (params.has(standard) || value == declared.end() || value->second.size() != (colour ? 3u : 1u))
                continue;
            std::vector<float> const& v = value->second;
            params.add(colour ? colorParam(standard, Vec3(v[0], v[1], v[2])) : floatParam(standard, v[0]));
            list += (list.empty() ? "" : ", ") + standard;
        }
        return list.empty() ? std::string()
                            : "the defaults its source " + fs::path(source.file).filename().string() +
                                  " declares for " + list;
    };
    // "shaders/plastic": a compiled shader the scene brings along, most often a copy
    // of the standard one; the standard one is the closest this renderer can come.
    if (!known && base != name && (known = classicSurfaceParameters(base))) {
        std::string const sourceDefaults = useDeclared(base);
        warnOnce("surface " + name, in.where(),
                 "Surface \"" + name + "\" is a shader file of the scene's own, which this renderer cannot run; it is "
                 "rendered as the standard \"" + base + "\"" +
                     (sourceDefaults.empty() ? "" : " with " + sourceDefaults));
        name = base;
    }
    // A shader of the scene's own is rendered as the standard one it most likely resembles, with the
    // standard parameters it shares (most were written from the standard shaders).
    bool lookalike = false;
    std::optional<Vec3> ownColour;
    if (!known) {
        auto [like, why] = lookalikeSurface(base, params, declared.count("Ks") > 0);
        // A sky or a backdrop of its own colour: what it shows does not depend on the lights. (A glow or a
        // flame of Cs shows mostly darker than its Cs: it keeps its look-alike, which is closer on average.)
        if (source.unlit && !source.ownColours.empty()) {
            like = "constant";
            why = "as its source " + fs::path(source.file).filename().string() + " reads no light";
        }
        std::string const sourceDefaults = useDeclared(like);
        // A shader that never reads Cs has a colour of its own: the RIB's value of it, else its source's default
        // (the average of a set: a checker's two colours).
        std::string colouring;
        Vec3 sum(0.0f);
        int found = 0;
        for (std::string const& colourName : source.ownColours) {
            auto const declaredValue = declared.find(colourName);
            Param const* written = params.find(colourName);
            bool const inRib = written && written->decl.type == ParamType::Color && written->floats.size() == 3u;
            std::vector<float> const* rgb = inRib ? &written->floats
                                            : declaredValue != declared.end() && declaredValue->second.size() == 3u
                                                ? &declaredValue->second
                                                : nullptr;
            if (!rgb) continue;  // a default written as an expression: the others stand for it
            sum = sum + Vec3((*rgb)[0], (*rgb)[1], (*rgb)[2]);
            colouring +=
                std::string(found++ ? " and " : "") + colourName + (inRib ? " (as given)" : " (its default)");
        }
        if (found) {
            ownColour = sum / static_cast<float>(found);
            colouring = "; coloured by " + std::string(found > 1 ? "the average of " : "") + "its " + colouring +
                        ", since its source never reads Cs";
        }
        bool const mapped =
            like != "metal" && params.has("texturename") && params.getString("texturename", "") != kRayTraced;
        // RenderMan's own materials (PxrDisney, PxrSurface, ...) are Bxdfs, which Surface does not give.
        bool const renderMansBxdf = isRenderMansOwnName(base);
        // A glass shader traces its own refraction, which no standard shader does: say why it looks solid.
        bool const refracts = lowered(base).find("glass") != std::string::npos || params.has("ior") ||
                              params.has("eta") || params.has("Kt");
        warnOnce("surface " + name, in.where(),
                 "Surface \"" + name + "\" is a shader this renderer does not have: rendered as \"" + like + "\", " +
                     why + ", with the parameters of it that it gives (its others are ignored" +
                     (mapped ? "; its texturename maps its colour, as paintedplastic's does" : "") + ")" +
                     (sourceDefaults.empty() ? "" : " and " + sourceDefaults) +
                     (refracts ? "; the light it refracts is not rendered, so it is opaque (Opacity still shows "
                                 "what lies behind it)"
                               : "") +
                     colouring +
                     (renderMansBxdf ? "; \"" + base + "\" is a Bxdf, given with Bxdf \"" + base + "\" \"handle\""
                                     : ""));
        name = like;
        known = classicSurfaceParameters(like);
        lookalike = true;
    }
    auto shader = std::make_shared<MaterialDesc>();
    shader->plugin = "ClassicSurface";
    shader->handle = name;
    shader->where = in.where();
    shader->params.add(stringParam("shader", name));
    std::string const owner = "Surface \"" + name + "\"";
    for (Param const& p : params.all()) {
        if (isRendererMetadata(p.name())) continue;
        bool const standard = std::find(known->begin(), known->end(), p.name()) != known->end();
        // A texture map: paintedplastic's colour, and most often a shader of the scene's own too,
        // written from it; a metal's texturename is its environment map, which is not read.
        bool const colourMap = p.name() == "texturename" && (name == "paintedplastic" || (lookalike && name != "metal"));
        if (colourMap) {
            std::string const file = p.strings.empty() ? "" : p.strings[0];
            if (file == kRayTraced)
                warnOnce("raytrace texturename", p.location,
                         "Surface \"" + given + "\": texturename \"raytrace\" is RenderMan's name for a lookup that "
                         "traces rays (environment or shadow), not a texture file: the colour is not mapped, and what "
                         "the shader traces with it is not rendered");
            else if (!file.empty() && building())
                classicTexture(file, p.location, *shader, "Surface \"" + given + "\"");
        } else if (lookalike && (!standard || p.name() == "texturename")) {
            p.used = true;  // said once above
        } else if (!standard) {
            std::string list;
            for (std::string const& k : *known) list += (list.empty() ? "" : ", ") + k;
            std::string const meant = closestSpelling(p.name(), *known);
            m_diagnostics.warn(p.location, owner + " has no parameter \"" + p.name() + "\"; ignored (" +
                                               (meant.empty() ? "" : "did you mean \"" + meant + "\"? ") +
                                               "its parameters: " + (list.empty() ? "none" : list) + ")");
        } else if (name == "shinymetal" && (p.name() == "Kr" || p.name() == "texturename")) {
            bool const traced = params.getString("texturename", "") == kRayTraced;
            warnOnce("shinymetal reflection", p.location,
                     std::string("Surface \"shinymetal\": its ") +
                         (traced ? "ray-traced reflection (Kr, texturename \"raytrace\")"
                                 : "reflection of an environment map (Kr, texturename)") +
                         " is not rendered; it shades as metal");
        } else {
            shader->params.add(p);
        }
    }
    state().surface = shader;
    state().surfaceOwnColour = ownColour;
}

void SceneBuilder::classicTexture(std::string const& file, SourceLocation const& where, MaterialDesc& shader,
                                  std::string const& owner) {
    // The classic texture(texturename) at the surface's s and t, as a PxrTexture
    // node: its t runs down the image (t = 0 is the top row, invertT 0), and a
    // file that cannot be read leaves the colour as it is (missingColor white).
    PatternDesc node;
    node.plugin = "PxrTexture";
    node.handle = "texture \"" + file + "\"";
    node.where = where;
    node.params.add(stringParam("filename", file));
    node.params.add(intParam("invertT", 0));
    node.params.add(colorParam("missingColor", Vec3(1.0f)));
    checkTexture(file, where, owner, "the surface keeps its colour");
    Param link;
    link.decl.name = "textureColor";
    link.decl.type = ParamType::Color;
    link.decl.reference = true;
    link.strings = {node.handle + ":resultRGB"};
    link.fallback = {1.0f, 1.0f, 1.0f};  // where PxrTexture cannot be loaded: the untextured colour
    link.location = where;
    shader.params.add(link);
    shader.connections["textureColor"] = {static_cast<int>(m_scene.patterns.size()), "resultRGB", where};
    m_scene.patterns.push_back(std::move(node));
}

void SceneBuilder::checkTexture(std::string const& file, SourceLocation const& where, std::string const& owner,
                                std::string const& consequence) {
    // Said here, where the RIB line is known; the texture service then does not say it again.
    TextureLocator const textures = m_scene.textureLocator();
    if (file.empty() || m_scene.missingTextures.count(file)) return;
    std::optional<std::string> const found = textures.find(file);
    // A file that is there but holds no image (empty, a Git LFS pointer) is said here too.
    std::string const notAnImage = found ? notAnImageBecause(*found) : std::string();
    if (found && notAnImage.empty()) return;
    m_scene.missingTextures.insert(file);
    if (found)
        missingFile(where, owner + ": texture \"" + file + "\" cannot be read (" + notAnImage + "); " + consequence);
    else
        missingFile(where, owner + ": texture \"" + file + "\" does not exist (looked for from " +
                               textures.searchedPlaces() + "); " + consequence);
}

void SceneBuilder::makeTexture(RequestReader& in) { madeTexture(in, true); }

void SceneBuilder::makeLatLongEnvironment(RequestReader& in) { madeTexture(in, false); }

void SceneBuilder::madeTexture(RequestReader& in, bool wrapModes) {
    // RenderMan makes the texture file from the picture before it renders. Here
    // the picture itself is read wherever the scene names the texture: OpenImageIO
    // tiles, mip-maps and filters it as it would the texture file. Only a file
    // that makes textures and renders nothing has its textures written (rixrender).
    MadeTexture made;
    made.where = in.where();
    made.environment = !wrapModes;
    std::string const picture = in.string("picture file name");
    std::string const texture = in.string("texture file name");
    if (wrapModes) {  // MakeTexture's; an environment wraps around by itself
        made.wrapS = in.string("s wrap mode");
        made.wrapT = in.string("t wrap mode");
        for (std::string* mode : {&made.wrapS, &made.wrapT})
            if (*mode != "periodic" && *mode != "clamp" && *mode != "black") {
                m_diagnostics.warn(made.where, "MakeTexture: wrap mode \"" + *mode +
                                                   "\" is not periodic, clamp or black; periodic is used");
                *mode = "periodic";
            }
    }
    in.string("filter name");
    in.number("filter width in s");
    in.number("filter width in t");
    in.params();  // txmake's options ("resize", ...): the picture is read as it is
    if (picture.empty() || texture.empty()) in.fail(in.where(), "a file name is empty");
    // The picture as found from the file being read, when it is there (RenderMan
    // looks from the folder it runs in, which is most often that one).
    std::error_code lookup;
    fs::path const beside = fs::path(currentDirectory()) / picture;
    bool const found = fs::path(picture).is_relative() && fs::exists(beside, lookup);
    made.picture = found ? beside.string() : picture;
    m_scene.madeTextures[fs::path(texture).lexically_normal().string()] = std::move(made);
}

int SceneBuilder::classicMaterial() {
    // One material per shader, colour and opacity: the classic shaders read Cs and Os.
    MaterialDesc material = *state().surface;
    Vec3 const c = state().surfaceOwnColour.value_or(state().color), o = state().opacity;
    material.params.add(colorParam("surfaceColor", c));
    material.params.add(colorParam("surfaceOpacity", o));
    material.params.add(colorParam("ambient", m_ambient));
    material.handle += " (Color " + std::to_string(c.x) + " " + std::to_string(c.y) + " " + std::to_string(c.z) +
                       (o == Vec3(1.0f) ? std::string()
                                        : ", Opacity " + std::to_string(o.x) + " " + std::to_string(o.y) + " " +
                                              std::to_string(o.z)) +
                       ")";
    std::string key = "classic " + material.handle + " at " + material.where.str();
    auto found = m_defaultMaterials.find(key);
    if (found != m_defaultMaterials.end()) return found->second;
    int index = static_cast<int>(m_scene.materials.size());
    m_scene.materials.push_back(std::move(material));
    m_defaultMaterials[key] = index;
    return index;
}

int SceneBuilder::primvarColorMaterial() {
    std::shared_ptr<MaterialDesc> saved = state().surface;
    auto matte = std::make_shared<MaterialDesc>();
    matte->plugin = "ClassicSurface";
    matte->handle = "default material (the shape's Cs)";
    matte->params.add(stringParam("shader", "matte"));
    std::optional<Vec3> const savedColour = state().surfaceOwnColour;
    state().surface = matte;
    state().surfaceOwnColour.reset();
    int index = classicMaterial();
    state().surface = saved;
    state().surfaceOwnColour = savedColour;
    if (m_unshaded.empty() || m_unshaded.back().material != index)
        m_unshaded.push_back({index, state().color, state().opacity});
    return index;
}

int SceneBuilder::defaultMaterial() {
    // RenderMan shades surfaces without a Bxdf with the stock PxrDiffuse; the
    // legacy `Color` attribute, when set, is its colour, and an `Opacity` below 1
    // (a classic shader this renderer does not have) its presence, as the
    // classic shaders it stands in for would show through.
    Vec3 c = state().color;
    bool colored = state().colorSet;
    Vec3 const o = state().opacity;
    float const presence = std::clamp((o.x + o.y + o.z) / 3.0f, 0.0f, 1.0f);
    std::string const colour =
        colored ? " (Color " + std::to_string(c.x) + " " + std::to_string(c.y) + " " + std::to_string(c.z) + ")" : "";
    std::string const cutOut = presence < 1.0f ? " (presence " + std::to_string(presence) + ")" : "";
    std::string const key = colour + cutOut;
    auto found = m_defaultMaterials.find(key);
    if (found != m_defaultMaterials.end()) return found->second;
    MaterialDesc material;
    material.plugin = "PxrDiffuse";
    material.handle = "default material" + key;
    if (colored) material.params.add(colorParam("diffuseColor", c));
    if (presence < 1.0f) material.params.add(floatParam("presence", presence));
    int index = static_cast<int>(m_scene.materials.size());
    m_scene.materials.push_back(std::move(material));
    m_defaultMaterials[key] = index;
    m_unshaded.push_back({index, c, o});
    return index;
}

void SceneBuilder::shadeUnshadedAsClassic() {
    // PRMan shaded a surface given no shader with its defaultsurface: lit by no light, brighter
    // where it faces the camera. RIS's PxrDiffuse in its place would leave a shape the file's lights
    // do not reach (its own light list, or none of them) black.
    for (Unshaded const& unshaded : m_unshaded) {
        MaterialDesc& material = m_scene.materials[static_cast<size_t>(unshaded.material)];
        SourceLocation const where = material.where;
        material = MaterialDesc();
        material.plugin = "ClassicSurface";
        material.handle = "default material (defaultsurface, RenderMan's before RIS)";
        material.where = where;
        material.params.add(stringParam("shader", "defaultsurface"));
        material.params.add(colorParam("surfaceColor", unshaded.color));
        material.params.add(colorParam("surfaceOpacity", unshaded.opacity));
    }
}

void SceneBuilder::makeLightFrom(std::string const& request, std::string const& type, std::string const& handle,
                                 ParamList const& params, Mat4 const& lightToWorld, SourceLocation const& where) {
    std::unique_ptr<Light> light;
    if (request == "Light" && type == "PxrPortalLight") {
        m_portals.push_back({handle, params, lightToWorld, where, state().visibility});
        return;
    }
    if (request == "Light") {
        light = makeLight(type, params, lightToWorld, textures(), where, m_diagnostics,
                          [this](SourceLocation const& at, std::string const& message) { missingFile(at, message); });
        if (!light) {
            warnOnce("light " + type, where, unsupportedLightMessage(type));
            ++m_scene.unrenderableLights;
            return;
        }
        // Exporters write every parameter of every light: each unused name is said once.
        params.warnUnused(m_diagnostics, type + " \"" + handle + "\"", [&](std::string const& name) {
            return firstOfKind("light " + type + " parameter " + name);
        });
    } else {
        std::string guess, leftOut;
        light = makeClassicLight(type, params, lightToWorld, where, m_ambient, guess, leftOut);
        if (!leftOut.empty()) warnOnce("light without direction", where, leftOut);
        if (!guess.empty())
            warnOnce("light shader " + type, where,
                     "LightSource \"" + type + "\" is a shader this renderer does not have; " +
                         (light ? "it is rendered as " + guess : std::string("skipped")));
        if (!light) {
            if (type != "ambientlight") ++m_scene.unrenderableLights;  // the ambient term is kept apart
            return;
        }
        if (state().classicLightShadows) light->castsShadows = true;
    }
    light->handle = handle;
    light->groups = state().membership;
    light->visibility = state().visibility;
    if (state().lightMute) {
        m_scene.dropped.push_back("light \"" + handle + "\" (" + type + ") is muted (Attribute \"lighting\" \"mute\")");
        return;
    }
    // A classic light shader was never geometry: the camera did not see even an area light's shape.
    if (request == "LightSource") light->visibility.camera = false;
    if (light->color.IsBlack()) {
        m_scene.dropped.push_back("light \"" + handle + "\" (" + type + ") has zero intensity");
        return;
    }
    warnIfLightMoves(where);
    m_lightHandles[handle] = m_scene.lights.size();
    m_scene.lights.push_back(std::move(light));
    if (request == "LightSource" && !isRenderMansOwnName(type)) {
        if (!m_firstClassicLight) m_firstClassicLight = where;
        // RenderMan's classic light list: the light is on for the shapes that follow, in this block.
        state().lightList.insert(handle);
        LightUse& use = m_lightUse[handle];
        use.listed = true;
        use.shapesBefore = m_worldShapes;
        use.listedOrder = m_listedLights++;
        use.where = where;
    }
}

void SceneBuilder::resolvePortals() {
    // With a sky, a portal only guides the sampling of the sky through an opening, and the sky lights
    // the scene through it all the same (with more noise). Without one, the portal is the only way
    // light comes in: an opening onto a uniform sky of its own intensity, exposure and colour, which is
    // a rect light of those.
    bool const sky = std::any_of(m_scene.lights.begin(), m_scene.lights.end(), [](auto const& light) {
        return std::string(light->kind()) == "PxrDomeLight" || std::string(light->kind()) == "PxrEnvDayLight";
    });
    for (PortalLight const& portal : m_portals) {
        if (sky) {
            warnOnce("light PxrPortalLight", portal.where,
                     "PxrPortalLight skipped: it only guides the sampling of the dome light through an opening, and "
                     "the dome light lights the scene through it all the same (with more noise)");
            continue;
        }
        warnOnce("light PxrPortalLight", portal.where,
                 "PxrPortalLight with no dome light in the world: rendered as a rect light of its intensity, exposure "
                 "and colour (the opening onto a uniform sky)");
        size_t const before = m_scene.lights.size();
        makeLightFrom("Light", "PxrRectLight", portal.handle, portal.params, portal.toWorld, portal.where);
        if (m_scene.lights.size() > before) m_scene.lights.back()->visibility = portal.visibility;
    }
    m_portals.clear();
}

std::string SceneBuilder::unsupportedLightMessage(std::string const& type) {
    // One of RenderMan's lights changes nothing a render here would show: say so, rather than
    // leave the reader to wonder what is missing from the image.
    if (type == "PxrAovLight") return "PxrAovLight skipped: it lights nothing (RenderMan uses it to draw masks into AOVs)";
    return "unsupported light type \"" + type + "\" skipped";
}

void SceneBuilder::light(RequestReader& in) {
    std::string type = in.string("light type");
    std::string handle = in.string("light handle");
    ParamList params = in.params();
    params.typeUntyped(lightParameterTypes(), type + " \"" + handle + "\"");
    if (type == "PxrMeshLight") {  // RenderMan 21+: the geometry in this attribute block is the light
        startAreaLight(type, handle, params, in.where());
        return;
    }
    if (!m_inWorld) {
        m_cameraLights.push_back({"Light", type, handle, params, state().transform, in.where()});
        return;
    }
    if (building()) makeLightFrom("Light", type, handle, params, state().transform, in.where());
}

std::string SceneBuilder::lightHandle(RequestReader& in, std::string const& request) {
    // A sequence number in older files, a string in newer ones. Some hand-written
    // files leave it out (LightSource "ambientlight" "intensity" [1]), which Aqsis
    // and Pixie read: the string that follows is then a parameter's name.
    if (in.atEnd() || in.nextIsParameter()) {
        std::string handle = "(no handle, " + in.where().str() + ")";
        warnOnce(request + " without handle", in.where(),
                 request + " has no handle (a number or a name after the shader's name); read without one");
        return handle;
    }
    return in.nextIsString() ? in.string("light handle") : std::to_string(in.integer("light handle"));
}

void SceneBuilder::lightSource(RequestReader& in) {
    std::string type = in.string("light shader name");
    std::string handle = lightHandle(in, "LightSource");
    ParamList params = in.params();
    if (!m_inWorld) {
        m_cameraLights.push_back({"LightSource", type, handle, params, state().transform, in.where()});
        return;
    }
    if (building()) makeLightFrom("LightSource", type, handle, params, state().transform, in.where());
}

void SceneBuilder::areaLightSource(RequestReader& in) {
    std::string type = in.string("area light shader name");
    std::string handle = lightHandle(in, "AreaLightSource");
    ParamList params = in.params();
    params.typeUntyped(lightParameterTypes(), "AreaLightSource \"" + type + "\"");
    startAreaLight(type, handle, params, in.where());
}

void SceneBuilder::startAreaLight(std::string const& shader, std::string const& handle, ParamList const& params,
                                  SourceLocation const& where) {
    auto area = std::make_shared<AreaLightDesc>();
    area->shader = shader;
    area->handle = handle;
    area->params = params;
    area->where = where;
    // RenderMan for Maya 20 writes each light as its own shader, named by its node:
    // "<project>/shaders/PxrStdEnvMapLightShape1_rfm"; the node's name tells the kind.
    std::string const base = std::filesystem::path(shader).filename().string();
    area->classic = !isRenderMansOwnName(base);
    if (!area->classic) {
        area->radiance = risLightRadiance(shader, params, where);
        area->daylight = base.rfind("PxrStdEnvDayLight", 0) == 0;
        area->environment = area->daylight || base.rfind("PxrStdEnvMapLight", 0) == 0;
    } else {
        // The classic area light shaders: intensity * lightcolor.
        area->radiance = params.getFloat("intensity", 1.0f) * params.getColor("lightcolor", Vec3(1.0f));
    }
    // The shape is given by the geometry that follows; maps and shadow controls are not modelled.
    for (auto const& p : area->params.all())
        if (p.name() != "rman__EnvMap" && p.name() != "rman__EmissionMap") p.used = true;
    state().areaLight = area;
}

bool SceneBuilder::shapeAsLight(char const* lightType, Mat4 const& lightToWorld, ParamList params) {
    if (!state().areaLight) return false;
    state().areaLight->shaped = true;
    if (!building()) return true;
    AreaLightDesc const& area = *state().areaLight;
    std::string type = area.environment ? "PxrDomeLight" : lightType;
    if (type == "PxrDomeLight" && area.daylight) {
        // PxrStdEnvDayLight's parameters are PxrEnvDayLight's, its sun's "direction" aside.
        type = "PxrEnvDayLight";
        for (Param p : area.params.all()) {
            if (p.name() == "direction") p.decl.name = "sunDirection";
            p.used = false;
            params.add(std::move(p));
        }
    } else if (type == "PxrDomeLight") {
        // An environment light's image; RenderMan 20 named it by the light shader's parameter.
        for (char const* name : {"rman__EnvMap", "rman__EmissionMap"})
            if (Param const* map = area.params.take(name))
                if (!map->strings.empty() && !map->strings[0].empty()) params.add(stringParam("lightColorMap", map->strings[0]));
    }
    std::unique_ptr<Light> light =
        makeLight(type, params, lightToWorld, textures(), area.where, m_diagnostics,
                  [this](SourceLocation const& at, std::string const& message) { missingFile(at, message); });
    if (!light) return false;
    Vec3 radiance = area.radiance;
    // A distant light's intensity is spread over the disc it subtends, as PxrDistantLight's is.
    if (type == "PxrDistantLight")
        radiance *= distantLightIrradianceScale(params.getFloat("angleExtent", kSunAngleExtent), false);
    addAreaLight(std::move(light), area, radiance);
    return true;
}

void SceneBuilder::warnIfLightMoves(SourceLocation const& where) {
    if (state().motion && m_scene.shutterClose > m_scene.shutterOpen)
        warnOnce("moving light", where,
                 "a light under a moving transform does not move: it stands where the transform is as the shutter "
                 "opens (only shapes are blurred)");
}

bool SceneBuilder::meshAsLight(Shape const& shape) {
    auto const* mesh = dynamic_cast<TriangleMesh const*>(&shape);
    if (!state().areaLight || state().areaLight->environment || !mesh ||
        mesh->data().triangleCount() > MeshLight::kMaxTriangles)
        return false;
    state().areaLight->shaped = true;
    if (!building()) return true;
    AreaLightDesc const& area = *state().areaLight;
    addAreaLight(std::make_unique<MeshLight>(mesh->data(), mesh->orientation(), state().twoSided), area, area.radiance);
    return true;
}

void SceneBuilder::addAreaLight(std::unique_ptr<Light> light, AreaLightDesc const& area, Vec3 radiance) {
    // A classic shader's intensity is not the radiance of its shape (see classicAreaLightRadiance).
    if (area.classic && light->surfaceArea() > 0.0f)
        radiance = classicAreaLightRadiance(area.shader, area.params, light->surfaceArea());
    light->color = RtColorRGB(radiance.x, radiance.y, radiance.z);
    if (area.classic)
        readClassicLobeSwitches(area.params, *light);
    else
        readCommonLightControls(area.params, *light, area.where);
    light->handle = area.handle;
    light->visibility = state().visibility;
    if (light->color.IsBlack()) {
        m_scene.dropped.push_back("area light \"" + area.handle + "\" (" + area.shader + ") has zero intensity");
        return;
    }
    warnIfLightMoves(area.where);
    m_lightHandles[area.handle] = m_scene.lights.size();
    m_scene.lights.push_back(std::move(light));
    if (area.classic && !m_firstClassicLight) m_firstClassicLight = area.where;
}

int SceneBuilder::emissiveMaterial(SourceLocation const& where) {
    std::shared_ptr<AreaLightDesc> const& area = state().areaLight;
    area->shaped = true;
    auto found = m_emissiveMaterials.find(area);
    if (found != m_emissiveMaterials.end()) return found->second;
    warnOnce("glowing area light", where,
             area->shader + " \"" + area->handle + "\" on this shape: it glows, but only a sphere, a disk, a "
             "Geometry \"rectlight\" or polygons of at most " + std::to_string(MeshLight::kMaxTriangles) +
             " triangles become a light the integrators sample, so it lights the scene through indirect paths only");
    MaterialDesc material;
    material.plugin = "PxrConstant";
    material.handle = "area light \"" + area->handle + "\"";
    material.where = area->where;
    material.params.add(colorParam("emitColor", area->radiance));
    int index = static_cast<int>(m_scene.materials.size());
    m_scene.materials.push_back(std::move(material));
    m_emissiveMaterials[area] = index;
    return index;
}

void SceneBuilder::illuminate(RequestReader& in) {
    std::string handle = in.nextIsString() ? in.string("light handle") : std::to_string(in.integer("light handle"));
    int on = in.integer("on or off");
    in.finish();
    // An attribute: it holds for the shapes in the rest of the block.
    if (on) {
        state().lightsOff.erase(handle);
        state().lightList.insert(handle);
    } else {
        state().lightsOff.insert(handle);
        state().lightList.erase(handle);
    }
    m_lightUse[handle].illuminated = true;  // this light's use by shapes is counted from now on
}

}  // namespace bxdflab
