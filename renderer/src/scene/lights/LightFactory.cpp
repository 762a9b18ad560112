#include "scene/lights/LightFactory.h"

#include <cmath>
#include <filesystem>

#include "scene/lights/AreaLights.h"
#include "scene/lights/InfiniteLights.h"

namespace bxdflab {

std::unique_ptr<Light> makeLight(std::string const& type, ParamList const& params, Mat4 const& lightToWorld,
                                 std::string const& baseDir, SourceLocation const& where, Diagnostics& diagnostics) {
    std::unique_ptr<Light> light;
    if (type == "PxrDiskLight") {
        light = std::make_unique<PlanarLight>(PlanarLight::Shape::Disk, lightToWorld);
    } else if (type == "PxrRectLight") {
        light = std::make_unique<PlanarLight>(PlanarLight::Shape::Rect, lightToWorld);
    } else if (type == "PxrSphereLight") {
        light = std::make_unique<SphereLight>(lightToWorld);
    } else if (type == "PxrDistantLight") {
        float extent = params.getFloat("angleExtent", 0.53f);  // RenderMan's default: the sun's diameter
        if (extent < 0.0f || extent > 180.0f)
            throw RibError(where, "PxrDistantLight: angleExtent must be between 0 and 180 degrees");
        light = std::make_unique<DistantLight>(lightToWorld, extent);
    } else if (type == "PxrDomeLight") {
        std::string map = params.getString("lightColorMap", "");
        if (!map.empty() && std::filesystem::path(map).is_relative())
            map = (std::filesystem::path(baseDir) / map).string();
        std::error_code lookup;  // a name the file system rejects (too long, ...) does not exist either
        if (!map.empty() && !std::filesystem::exists(map, lookup))
            throw RibError(where, "PxrDomeLight: lightColorMap \"" + map + "\" does not exist");
        std::unique_ptr<DomeLight> dome;
        try {
            dome = std::make_unique<DomeLight>(lightToWorld, map);
        } catch (RibError const&) {
            throw;
        } catch (RenderError const& error) {
            throw RibError(where, error.what());  // an unreadable image: say which statement named it
        }
        if (dome->repairedPixels() > 0)
            diagnostics.warn(where, "PxrDomeLight: " + std::to_string(dome->repairedPixels()) + " pixels of lightColorMap \"" +
                                        map + "\" are NaN, infinite or negative; they are taken as black");
        light = std::move(dome);
    } else {
        return nullptr;
    }
    float intensity = params.getFloat("intensity", 1.0f);
    float exposure = params.getFloat("exposure", 0.0f);
    Vec3 color = params.getColor("lightColor", Vec3(1.0f));
    if (intensity < 0.0f) throw RibError(where, type + ": intensity must not be negative");
    if (color.x < 0.0f || color.y < 0.0f || color.z < 0.0f)
        throw RibError(where, type + ": lightColor must not be negative");
    float scale = intensity * std::exp2(exposure);
    light->color = RtColorRGB(scale * color.x, scale * color.y, scale * color.z);
    return light;
}

}  // namespace bxdflab
