#include "scene/lights/LightFactory.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "core/Spelling.h"
#include "scene/lights/AreaLights.h"
#include "scene/lights/Blackbody.h"
#include "scene/lights/DayLight.h"
#include "scene/lights/InfiniteLights.h"
#include "scene/lights/MeshLight.h"
#include "scene/lights/PointLights.h"

namespace bxdflab {

namespace {

/// A flat light's coneAngle, coneSoftness, emissionFocus and emissionFocusTint.
EmissionShaping emissionShapingOf(ParamList const& params) {
    EmissionShaping shaping;
    // Out-of-range values are clamped, as UsdLux says of its cone; a negative focus is ignored.
    shaping.coneAngle = std::clamp(params.getFloat("coneAngle", 90.0f), 0.0f, 90.0f) * kPi / 180.0f;
    shaping.coneSoftness = std::clamp(params.getFloat("coneSoftness", 0.0f), 0.0f, 1.0f);
    shaping.focus = std::max(params.getFloat("emissionFocus", 0.0f), 0.0f);
    shaping.focusTint = glm::max(params.getColor("emissionFocusTint", Vec3(0.0f)), Vec3(0.0f));
    return shaping;
}

/// The unit square, or the disk of unit diameter (as a fan of triangles), in the xy plane of a
/// light's space, placed in the world.
MeshData flatLightOutline(bool disk, Mat4 const& lightToWorld) {
    MeshData outline;
    outline.P.push_back(transformPoint(lightToWorld, Vec3(0.0f)));
    int const corners = disk ? 64 : 4;
    for (int k = 0; k < corners; ++k) {
        float const angle = 2.0f * kPi * (k + (disk ? 0.0f : 0.5f)) / corners;
        // A square's corners lie at 45 degrees, sqrt(2)/2 from its centre.
        float const reach = disk ? 0.5f : 0.5f * std::sqrt(2.0f);
        outline.P.push_back(transformPoint(lightToWorld, Vec3(reach * std::cos(angle), reach * std::sin(angle), 0.0f)));
        outline.indices.insert(outline.indices.end(), {0u, 1u + k, 1u + (k + 1) % corners});
    }
    return outline;
}

/// RenderMan 16's physically plausible light shaders ("plausibleArealight") give their
/// intensity as a radiance; the older classic ones do not.
bool isPlausible(std::string const& shader) {
    return lowered(std::filesystem::path(shader).filename().string()).rfind("plausible", 0) == 0;
}

/// A classic light shader that is an area light without geometry, as RenderMan 16's
/// plausibleArealight is: its "shape" ("rect", the default, "disk" or "sphere", the size
/// of RenderMan's rect, disk and sphere lights) in the light's space, emitting what
/// classicAreaLightRadiance says from its +z face under "sides" 1 and from both faces
/// otherwise. Such shaders trace their shadows.
std::unique_ptr<Light> classicAreaLight(std::string const& shader, ParamList const& params, Mat4 const& lightToWorld,
                                        std::string& guess) {
    std::string shape = lowered(params.getString("shape", "rect"));
    if (shape != "disk" && shape != "sphere") shape = "rect";
    bool const twoSided = params.getFloat("sides", 1.0f) != 1.0f && shape != "sphere";
    std::unique_ptr<Light> light;
    if (shape == "sphere")
        light = std::make_unique<SphereLight>(lightToWorld);
    else if (twoSided)
        light = std::make_unique<MeshLight>(flatLightOutline(shape == "disk", lightToWorld), 1.0f, true);
    else
        light = std::make_unique<PlanarLight>(shape == "disk" ? PlanarLight::Shape::Disk : PlanarLight::Shape::Rect,
                                              lightToWorld);
    Vec3 const radiance = classicAreaLightRadiance(shader, params, light->surfaceArea());
    light->color = RtColorRGB(radiance.x, radiance.y, radiance.z);
    light->castsShadows = true;
    readClassicLobeSwitches(params, *light);
    guess = std::string("a ") + (twoSided ? "two-sided " : "") + shape + " light " +
            (isPlausible(shader) ? "of radiance intensity x lightcolor" : "giving what a point light of its intensity would");
    return light;
}

}  // namespace

void readClassicLobeSwitches(ParamList const& params, Light& light) {
    auto on = [&params](char const* name) {  // old files give them untyped too
        Param const* p = params.find(name);
        return p && !p->floats.empty() && p->floats.front() != 0.0f;
    };
    if (on("__nondiffuse")) light.diffuseMultiplier = 0.0f;
    if (on("__nonspecular")) light.specularMultiplier = 0.0f;
}

void readCommonLightControls(ParamList const& params, Light& light, SourceLocation const& where) {
    light.castsShadows = params.getFloat("enableShadows", 1.0f) != 0.0f;
    light.diffuseMultiplier = params.getFloat("diffuse", 1.0f);
    light.specularMultiplier = params.getFloat("specular", 1.0f);
    if (!(light.diffuseMultiplier >= 0.0f) || !(light.specularMultiplier >= 0.0f) ||
        !std::isfinite(light.diffuseMultiplier) || !std::isfinite(light.specularMultiplier))
        throw RibError(where, "the light's diffuse and specular multipliers must be finite and not negative (diffuse " +
                                  std::to_string(light.diffuseMultiplier) + ", specular " +
                                  std::to_string(light.specularMultiplier) + ")");
    params.ignore("lightGroup");
    auto atDefault = [&params](char const* name, std::vector<float> const& noEffect) {
        Param const* p = params.find(name);
        if (p && p->floats == noEffect) params.ignore(name);
    };
    atDefault("shadowColor", {0.0f, 0.0f, 0.0f});
    atDefault("shadowDistance", {-1.0f});
    atDefault("shadowFalloff", {-1.0f});
    atDefault("shadowFalloffGamma", {1.0f});
    atDefault("thinShadow", {1.0f});
    atDefault("traceLightPaths", {0.0f});
    atDefault("fixedSampleCount", {0.0f});
    atDefault("importanceMultiplier", {1.0f});
    atDefault("colorMapGamma", {1.0f, 1.0f, 1.0f});
    atDefault("colorMapSaturation", {1.0f});
    atDefault("intensityNearDist", {0.0f});  // RenderMan's default: no change to the falloff near the light
    atDefault("iesProfileScale", {0.0f});
    // Exporters write every light's full list: an empty file name asks for nothing.
    for (char const* subset : {"shadowSubset", "shadowExcludeSubset", "iesProfile", "lightColorMap"})
        if (Param const* p = params.find(subset); p && (p->strings.empty() || p->strings[0].empty())) params.ignore(subset);
}

std::unique_ptr<Light> makeLight(std::string const& type, ParamList const& params, Mat4 const& lightToWorld,
                                 TextureLocator const& textures, SourceLocation const& where, Diagnostics& diagnostics,
                                 MissingFileReport const& missing) {
    std::unique_ptr<Light> light;
    if (type == "PxrDiskLight" || type == "PxrRectLight") {
        auto planar = std::make_unique<PlanarLight>(
            type == "PxrDiskLight" ? PlanarLight::Shape::Disk : PlanarLight::Shape::Rect, lightToWorld);
        planar->setShaping(emissionShapingOf(params));
        light = std::move(planar);
    } else if (type == "PxrSphereLight") {
        light = std::make_unique<SphereLight>(lightToWorld);
    } else if (type == "PxrCylinderLight") {
        light = std::make_unique<CylinderLight>(lightToWorld);
    } else if (type == "PxrDistantLight") {
        float extent = params.getFloat("angleExtent", kSunAngleExtent);
        if (extent < 0.0f || extent > 180.0f)
            throw RibError(where, "PxrDistantLight: angleExtent must be between 0 and 180 degrees");
        light = std::make_unique<DistantLight>(lightToWorld, extent);
    } else if (type == "PxrDomeLight") {
        std::string const written = params.getString("lightColorMap", "");
        std::string map = textures.find(written).value_or("");
        if (!written.empty() && map.empty())  // RenderMan lights the scene with the plain colour then
            missing(where, "PxrDomeLight: lightColorMap \"" + written + "\" does not exist (looked for from " +
                               textures.searchedPlaces() + ")");
        std::error_code lookup;  // a name the file system rejects (too long, ...) is not a file either
        if (!map.empty() && !std::filesystem::is_regular_file(map, lookup))
            throw RibError(where, "PxrDomeLight: lightColorMap \"" + map + "\" is not a regular file");
        std::unique_ptr<DomeLight> dome;
        try {
            dome = std::make_unique<DomeLight>(lightToWorld, map);
        } catch (RibError const&) {
            throw;
        } catch (RenderError const& error) {
            // An image that cannot be decoded is treated as a missing one: RenderMan renders on
            // without it, and a repository cloned without its LFS images should render as well.
            missing(where, error.what());
            map.clear();
            dome = std::make_unique<DomeLight>(lightToWorld, map);
        }
        if (dome->repairedPixels() > 0)
            diagnostics.warn(where, "PxrDomeLight: " + std::to_string(dome->repairedPixels()) + " pixels of lightColorMap \"" +
                                        map + "\" are NaN, infinite or negative; they are taken as black");
        light = std::move(dome);
    } else if (type == "PxrEnvDayLight") {
        light = std::make_unique<DayLight>(lightToWorld, DaylightParams::from(params));
    } else {
        return nullptr;
    }
    Vec3 radiance = risLightRadiance(type, params, where);
    // areaNormalize: the light's power stays the same whatever its size (radiance / area).
    bool const areaNormalize = params.getFloat("areaNormalize", 0.0f) != 0.0f;
    if (areaNormalize && light->surfaceArea() > 0.0f) radiance /= std::max(light->surfaceArea(), 1e-12f);
    if (type == "PxrDistantLight")
        radiance *= distantLightIrradianceScale(params.getFloat("angleExtent", kSunAngleExtent), areaNormalize);
    light->color = RtColorRGB(radiance.x, radiance.y, radiance.z);
    readCommonLightControls(params, *light, where);
    return light;
}

std::map<std::string, ParamType> const& lightParameterTypes() {
    static const std::map<std::string, ParamType> types = {
        // Every RIS light.
        {"intensity", ParamType::Float}, {"exposure", ParamType::Float}, {"lightColor", ParamType::Color},
        {"enableTemperature", ParamType::Int}, {"temperature", ParamType::Float}, {"areaNormalize", ParamType::Int},
        {"enableShadows", ParamType::Int}, {"shadowColor", ParamType::Color}, {"diffuse", ParamType::Float},
        {"specular", ParamType::Float}, {"shadowDistance", ParamType::Float}, {"shadowFalloff", ParamType::Float},
        {"shadowFalloffGamma", ParamType::Float}, {"thinShadow", ParamType::Int}, {"traceLightPaths", ParamType::Int},
        {"fixedSampleCount", ParamType::Int}, {"importanceMultiplier", ParamType::Float},
        {"shadowSubset", ParamType::String}, {"shadowExcludeSubset", ParamType::String},
        {"lightGroup", ParamType::String}, {"colorMapGamma", ParamType::Vector},
        {"colorMapSaturation", ParamType::Float},
        // PxrRectLight and PxrDiskLight's shaping.
        {"coneAngle", ParamType::Float}, {"coneSoftness", ParamType::Float}, {"emissionFocus", ParamType::Float},
        {"emissionFocusTint", ParamType::Color},
        // PxrDistantLight and PxrDomeLight.
        {"angleExtent", ParamType::Float}, {"lightColorMap", ParamType::String},
        // PxrEnvDayLight.
        {"sunDirection", ParamType::Vector}, {"haziness", ParamType::Float}, {"skyTint", ParamType::Color},
        {"sunTint", ParamType::Color}, {"sunSize", ParamType::Float}, {"month", ParamType::Int},
        {"day", ParamType::Int}, {"year", ParamType::Int}, {"hour", ParamType::Float}, {"zone", ParamType::Float},
        {"latitude", ParamType::Float}, {"longitude", ParamType::Float},
    };
    return types;
}

Vec3 risLightRadiance(std::string const& type, ParamList const& params, SourceLocation const& where) {
    float intensity = params.getFloat("intensity", 1.0f);
    float exposure = params.getFloat("exposure", 0.0f);
    Vec3 color = params.getColor("lightColor", Vec3(1.0f));
    if (intensity < 0.0f) throw RibError(where, type + ": intensity must not be negative");
    if (color.x < 0.0f || color.y < 0.0f || color.z < 0.0f)
        throw RibError(where, type + ": lightColor must not be negative");
    // RenderMan's plausible colour temperature tints the light (at the same luminance).
    if (params.getFloat("enableTemperature", 0.0f) != 0.0f)
        color *= blackbodyColor(params.getFloat("temperature", 6500.0f));
    else
        params.ignore("temperature");  // written with the switch off: it changes nothing
    return intensity * std::exp2(exposure) * color;
}

Vec3 classicAreaLightRadiance(std::string const& shader, ParamList const& params, float area) {
    Vec3 radiance = params.getFloat("intensity", 1.0f) * params.getColor("lightcolor", Vec3(1.0f));
    if (!(area > 0.0f)) return radiance;
    if (!isPlausible(shader)) return radiance * (kPi / area);
    return params.getFloat("areanormalize", 0.0f) != 0.0f ? radiance / area : radiance;
}

std::unique_ptr<Light> makeClassicLight(std::string const& shader, ParamList const& params, Mat4 const& lightToWorld,
                                        SourceLocation const& where, Vec3& ambient, std::string& guess,
                                        std::string& leftOut) {
    guess.clear();
    leftOut.clear();
    std::string const lowerName = lowered(shader);  // names say what a shader is, in any case
    float intensity = params.getFloat("intensity", 1.0f);
    Vec3 lightColor = params.getColor("lightcolor", Vec3(1.0f));
    if (intensity < 0.0f) throw RibError(where, "LightSource \"" + shader + "\": intensity must not be negative");
    if (shader == "ambientlight") {
        ambient += intensity * lightColor;
        return nullptr;
    }
    if (lowerName.find("arealight") != std::string::npos) {
        for (auto const& p : params.all()) p.used = true;  // samples, shadow bias, maps: not modelled
        return classicAreaLight(shader, params, lightToWorld, guess);
    }
    Vec3 from = params.getVector("from", Vec3(0.0f)), to = params.getVector("to", Vec3(0.0f, 0.0f, 1.0f));
    // The shadowed versions in the RenderMan Companion and BMRT take the same
    // parameters (plus a shadow map, not modelled).
    static std::map<std::string, std::string> const shadowed = {
        {"shadowpoint", "pointlight"}, {"shadowspot", "spotlight"}, {"shadowdistant", "distantlight"}};
    std::string kind = shadowed.count(shader) ? shadowed.at(shader) : shader;
    // A spotlight's cone, soft edge and falloff (radians, radians, cosine exponent).
    float cone = 0.0f, coneDelta = 0.0f, beam = 0.0f;
    bool coneGiven = false;
    bool ownFalloff = false;  // the shader's own distance falloff, not the inverse square
    float falloffPower = 0.0f, falloffReference = 1.0f;
    if (kind == "uberlight" || kind == "l_uber") {
        // Barzel's uberlight (and MTOR's l_uber, made from it) shines from its space's
        // origin along +z (the defaults of "from" and "to"), or along +z everywhere with
        // "parallelrays". A spot's superellipse "width" (a tangent) and "wedge" become a
        // spotlight's cone and soft edge; l_uber's Maya "coneAngle" and "penumbraAngle"
        // (full angles in degrees) take their place when given. Its distance falloff is
        // (falloffdist / d)^falloff, none by default. Blockers, cuton/cutoff, shear and
        // the superellipse's roundness are not modelled.
        guess = "skipped";  // until it is placed
        ownFalloff = true;
        // Old files often give these without a type: whatever number or string is there is read.
        auto number = [&params](char const* name, float fallback) {
            Param const* p = params.find(name);
            return p && !p->floats.empty() ? p->floats.front() : fallback;
        };
        // "lighttype": "spot", "omni" or "arealight" in Barzel's shader; 0 spot, 1 omni, 2 area
        // and 3 directional in MTOR's l_uber.
        Param const* type = params.find("lighttype");
        std::string const named = type && !type->strings.empty() ? type->strings.front() : "";
        float const numbered = named.empty() ? number("lighttype", 0.0f) : -1.0f;
        bool const omni = named == "omni" || numbered == 1.0f;
        bool const parallel = numbered == 3.0f || number("parallelrays", 0.0f) != 0.0f;
        kind = parallel ? "distantlight" : omni ? "pointlight" : "spotlight";
        float const mayaCone = number("coneAngle", 0.0f), penumbra = number("penumbraAngle", 0.0f);
        if (kind == "spotlight" && mayaCone > 0.006f) {  // 0.006 degrees: Maya's least, "no cone"
            float const inner = glm::radians(0.5f * std::min(mayaCone, mayaCone + penumbra));
            float const outer = glm::radians(0.5f * std::max(mayaCone, mayaCone + penumbra));
            cone = std::min(outer, 0.5f * kPi);
            coneDelta = cone - std::max(inner, 0.0f);
        } else {
            float const width = std::max(number("width", 1.0f), number("height", 1.0f));
            cone = std::atan(std::max(width + number("wedge", 0.1f), 1e-3f));
            coneDelta = cone - std::atan(std::max(width, 0.0f));
        }
        beam = std::max(number("beamdistribution", 0.0f), 0.0f);
        coneGiven = true;
        falloffPower = std::max(number("falloff", 0.0f), 0.0f);
        // MTOR's l_uber writes "falloffdist" 0 with a Maya decay rate in "falloff": 1 / d^falloff.
        float const reference = number("falloffdist", 1.0f);
        falloffReference = reference > 0.0f ? reference : 1.0f;
    }
    if (kind != "pointlight" && kind != "spotlight" && kind != "distantlight") {
        guess = "skipped";  // until it is placed
        if (params.all().empty()) return nullptr;
        bool hasFrom = false, hasTo = false, hasCone = false;
        for (auto const& p : params.all()) {
            hasFrom = hasFrom || p.name() == "from";
            hasTo = hasTo || p.name() == "to";
            hasCone = hasCone || p.name() == "coneangle";
        }
        // The shader's name says what it is more often than its parameters do
        // (MayaMan's "RMsoftDistant" has "from" and "to", as a spotlight would).
        auto named = [&lowerName](char const* word) { return lowerName.find(word) != std::string::npos; };
        if (hasCone || named("spot"))
            kind = "spotlight";
        else if (named("distant") || named("direction") || named("sun"))
            kind = "distantlight";
        else if (named("point") || named("omni"))
            kind = "pointlight";
        else  // a "to" without a cone points a distant light; "from" alone places a point
            kind = hasTo ? "distantlight" : hasFrom ? "pointlight" : "";
        if (kind.empty()) return nullptr;
    }
    Vec3 worldFrom = transformPoint(lightToWorld, from), worldTo = transformPoint(lightToWorld, to);
    std::unique_ptr<Light> light;
    if (kind == "pointlight") {
        light = std::make_unique<PointLight>(worldFrom);
    } else if (kind == "spotlight") {
        if (!coneGiven) {
            cone = params.getFloat("coneangle", glm::radians(30.0f));
            coneDelta = params.getFloat("conedeltaangle", glm::radians(5.0f));
            beam = params.getFloat("beamdistribution", 2.0f);
        }
        light = std::make_unique<PointLight>(worldFrom, worldTo - worldFrom, cone, coneDelta, beam);
    } else {
        Vec3 travel = safeNormalize(worldTo - worldFrom);
        if (glm::length(travel) == 0.0f) {
            leftOut = "LightSource \"" + shader + "\": \"from\" and \"to\" are the same point, so the light has no " +
                      "direction; it is left out";
            return nullptr;
        }
        Vec3 x, y;
        orthonormalBasis(travel, x, y);
        Mat4 frame(Vec4(x, 0.0f), Vec4(y, 0.0f), Vec4(travel, 0.0f), Vec4(0.0f, 0.0f, 0.0f, 1.0f));
        light = std::make_unique<DistantLight>(frame, 0.0f);
    }
    // "pointnofalloff" and its kin say so in their name: the light does not weaken with distance.
    if (lowerName.find("nofall") != std::string::npos) {
        ownFalloff = true;
        falloffPower = 0.0f;
    }
    if (auto* point = dynamic_cast<PointLight*>(light.get()); point && ownFalloff)
        point->setDistanceFalloff(falloffPower, falloffReference);
    Vec3 c = kPi * intensity * lightColor;
    light->color = RtColorRGB(c.x, c.y, c.z);
    // A classic light casts shadows only when its shader is given a shadow map or told to trace them
    // ("shadowname" "raytrace", uberlight's "raytraceshadow" 1; MTOR's l_uber names a point light's six
    // cube-face maps "spx" ... "snz"); BMRT's Attribute "light" "shadows" "on" is the caller's to add.
    light->castsShadows = false;
    static std::set<std::string> const cubeFaceMaps = {"spx", "spy", "spz", "snx", "sny", "snz"};
    for (auto const& p : params.all()) {
        std::string const option = lowered(p.name());
        bool const map = (option.find("shadow") != std::string::npos || cubeFaceMaps.count(option)) &&
                         !p.strings.empty() && !p.strings[0].empty();
        bool const traced = option.find("raytrace") != std::string::npos && !p.floats.empty() && p.floats[0] != 0.0f;
        if (map || traced) light->castsShadows = true;
    }
    // A shader of the scene's own that says so in its name ("pointlight_shadows", "shadowlight") and
    // is given no map can only trace its shadows, as its transmission() or shadow(..., "raytrace") does.
    bool const namedShadowed = !guess.empty() && lowerName.find("shadow") != std::string::npos;
    if (namedShadowed) light->castsShadows = true;
    readClassicLobeSwitches(params, *light);
    for (auto const& p : params.all()) p.used = true;  // shadow maps, samples and other shader options: not modelled
    if (!guess.empty())
        guess = std::string("the ") + light->kind() + " its parameters describe" +
                (namedShadowed ? ", tracing the shadows its name speaks of" : "");
    return light;
}

}  // namespace bxdflab
