// Everything a RIB file describes, ready to render: options, camera,
// materials (Bxdf statements), lights and shapes.
#pragma once

#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/Error.h"
#include "core/ImageFinish.h"
#include "core/Math.h"
#include "core/TextureLocator.h"
#include "parse/ParamList.h"
#include "scene/DisplayChannels.h"
#include "scene/Motion.h"
#include "scene/lights/Light.h"
#include "scene/shapes/Shape.h"

namespace bxdflab {

struct CameraDesc {
    /// The transform in effect at WorldBegin (or at the Camera request that named it), as the shutter opens.
    Mat4 worldToCamera{1.0f};
    /// The same over time, when a motion block before WorldBegin moves the camera (null when it holds still).
    std::shared_ptr<TransformPath const> motion;
    std::string projection = "orthographic";  ///< the RenderMan Interface's default
    float fov = 90.0f;  ///< degrees, across the shorter image axis
    bool hasScreenWindow = false;
    float screenWindow[4] = {-1.0f, 1.0f, -1.0f, 1.0f};  ///< left right bottom top
    /// FrameAspectRatio: width over height of the default screen window (0 or less: the Format's, pixel aspect
    /// included).
    float frameAspectRatio = 0.0f;
    /// DepthOfField fstop focallength focaldistance: a thin lens of diameter
    /// focallength / fstop, sharp on the plane z = focaldistance. fstop 0 (or
    /// infinite, RenderMan's default, or the 1e38 exporters write for it) is a pinhole.
    float fStop = 0.0f, focalLength = 0.0f, focalDistance = 0.0f;
    /// Clipping near far: camera rays see only what lies between the planes z = near and z = far of
    /// camera space. The defaults clip nothing in front of the camera.
    float clipNear = 0.0f, clipFar = kInfinity;
    /// The lens's radius in camera space (0: a pinhole).
    float lensRadius() const {
        return projection == "perspective" && fStop > 0.0f && fStop < 1e30f ? 0.5f * focalLength / fStop : 0.0f;
    }
};

struct DisplayDesc {
    std::string name = "rixrender.exr";
    std::string type = "file";
    std::string mode = "rgba";
    SourceLocation where;
    DisplayLayout layout = displayLayout("rgba");  ///< the channels `mode` names, read once
    std::string camera;  ///< "string camera": the name a Camera request gave the camera it is seen from
    SourceLocation cameraWhere;
};

struct IntegratorDesc {
    std::string name = "PxrDefault";
    std::string handle;
    ParamList params;
    SourceLocation where;
    bool given = false;
};

/// A parameter connected to a pattern's output: "reference color x" ["handle:output"].
struct Connection {
    int pattern = -1;    ///< index into Scene::patterns
    std::string output;  ///< the output's name in that pattern's table
    SourceLocation where;
};

/// One `Bxdf "plugin" "handle" ...` statement.
struct MaterialDesc {
    std::string plugin;
    std::string handle;
    ParamList params;
    SourceLocation where;
    std::map<std::string, Connection> connections;  ///< by parameter name
};

/// One `Pattern "plugin" "handle" ...` statement: a node of a shading network.
/// Its connections only reach patterns declared before it, so networks have no cycles.
struct PatternDesc {
    std::string plugin;
    std::string handle;
    ParamList params;
    SourceLocation where;
    std::map<std::string, Connection> connections;
    /// An OSL shader of the plugin's name ("dimples.oso") on the shader search path or beside
    /// the RIB, which RenderMan would run here; empty when there is none.
    std::string oslShader;
};

/// An area light given by geometry: AreaLightSource (RenderMan 20 and the
/// classic arealight shaders) or Light "PxrMeshLight" (RenderMan 21+); the
/// shapes in its attribute block emit its light.
struct AreaLightDesc {
    std::string shader;  ///< e.g. "PxrStdAreaLight", "PxrMeshLight", "arealight"
    std::string handle;
    ParamList params;
    SourceLocation where;
    Vec3 radiance{1.0f};  ///< what the shapes emit
    bool environment = false;  ///< PxrStdEnvMapLight or PxrStdEnvDayLight: the light at infinity
    bool daylight = false;     ///< PxrStdEnvDayLight: a sky and sun rather than an image
    bool shaped = false;       ///< a shape in its block has become the light or glows with it
    bool classic = false;      ///< a classic shader (BMRT's arealight), not one of RenderMan's own
};

/// What a frame's options say: image, camera, display, integrator.
/// PixelFilter: a name of pixelFilterNames() and its widths in pixels. RenderMan's
/// own default is "gaussian" 2 2; a scene that names none is filtered with a
/// box one pixel wide, so that each sample counts for its own pixel only.
struct PixelFilterDesc {
    std::string name = "box";
    float xwidth = 1.0f, ywidth = 1.0f;
};

struct SceneOptions {
    std::string file;  ///< the top-level RIB file
    int xres = 640, yres = 480;
    float pixelAspect = 1.0f;
    int spp = 16;
    /// PixelVariance: above 0, a pixel stops taking samples once its relative variance (its variance of
    /// the mean over its value squared, as RenderMan measures it) is at most this (adaptive sampling);
    /// 0, the default, gives every pixel spp samples.
    float pixelVariance = 0.0f;
    /// Hider "minsamples": the samples every pixel takes before its first test (0 or below: the square root
    /// of spp, as in RenderMan); "minextrasamples": how many more it takes between tests (0 or below: minsamples).
    int minSamples = -1, minExtraSamples = -1;
    /// Hider "darkfalloff": a pixel darker than this is held to the error allowed at this brightness.
    float darkFalloff = 0.025f;
    /// RelativeDetail: scales every Detail's raster area before DetailRange compares it.
    float relativeDetail = 1.0f;
    PixelFilterDesc pixelFilter;
    CameraDesc camera;
    /// Camera name: the camera description (transform and camera options) saved under that name, for a
    /// Display to be seen from.
    std::map<std::string, CameraDesc> namedCameras;
    DisplayDesc display;
    std::vector<DisplayDesc> moreDisplays;  ///< "+name" Displays: further images of the same render (AOVs)
    ImageFinish finish;  ///< Imager and DisplayFilter
    IntegratorDesc integrator;
    std::vector<std::string> pluginSearchPath;  ///< from Option "searchpath" "rixplugin"
    std::vector<std::string> textureSearchPath; ///< from Option "searchpath" "texture" (then the RIB's folder)
    /// What MakeTexture and MakeLatLongEnvironment made: texture name -> what it is made from.
    std::map<std::string, MadeTexture> madeTextures;
    int frame = -1;  ///< the FrameBegin number (-1: the file has no frames)
    /// Shutter open close: the span of time one image sees (motion blocks give times in the same units).
    /// Opening and closing at once (the default) sees each motion block at that one moment.
    float shutterOpen = 0.0f, shutterClose = 0.0f;
};

struct Scene : SceneOptions {
    std::vector<MaterialDesc> materials;
    std::vector<PatternDesc> patterns;
    std::vector<std::unique_ptr<Shape>> shapes;
    /// The name of every primvar some shape carries: a Bxdf or pattern
    /// parameter of the same name takes its values from the primvar.
    std::set<std::string> primvarNames;
    std::vector<std::unique_ptr<Light>> lights;
    /// Lights the scene gives that this renderer cannot render (a light shader or plugin it does not have).
    int unrenderableLights = 0;
    /// Light linking: lightLinks[k][l] says whether light l lights the shapes whose lightLink is k.
    std::vector<std::vector<bool>> lightLinks;
    /// The coordinate systems named by CoordinateSystem and ScopedCoordinateSystem
    /// (the last definition of each name), as transforms to world space.
    std::map<std::string, Mat4> coordinateSystems;
    /// Things dropped at load, e.g. "light 'fill' has zero intensity" (for the stats).
    std::vector<std::string> dropped;
    /// Textures the scene names that were not found, or hold no image (empty, a Git LFS pointer), when it
    /// was read (and said so, with the RIB line).
    std::set<std::string> missingTextures;

    /// Where the files textures name are found: the texture search path, then the RIB's folder.
    TextureLocator textureLocator() const {
        TextureLocator locator{textureSearchPath, madeTextures, missingTextures};
        std::string const folder = std::filesystem::path(file).parent_path().string();
        if (!folder.empty()) locator.folders.push_back(folder);
        return locator;
    }
};

}  // namespace bxdflab
