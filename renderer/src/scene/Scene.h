// Everything a RIB file describes, ready to render: options, camera,
// materials (Bxdf statements), lights and shapes.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/Error.h"
#include "core/Math.h"
#include "parse/ParamList.h"
#include "scene/lights/Light.h"
#include "scene/shapes/Shape.h"

namespace bxdflab {

struct CameraDesc {
    Mat4 worldToCamera{1.0f};  ///< the transform in effect at WorldBegin
    std::string projection = "perspective";
    float fov = 90.0f;  ///< degrees, across the shorter image axis
    bool hasScreenWindow = false;
    float screenWindow[4] = {-1.0f, 1.0f, -1.0f, 1.0f};  ///< left right bottom top
};

struct DisplayDesc {
    std::string name = "rixrender.exr";
    std::string type = "file";
    std::string mode = "rgba";
    SourceLocation where;
};

struct IntegratorDesc {
    std::string name = "PxrDefault";
    std::string handle;
    ParamList params;
    SourceLocation where;
    bool given = false;
};

/// One `Bxdf "plugin" "handle" ...` statement.
struct MaterialDesc {
    std::string plugin;
    std::string handle;
    ParamList params;
    SourceLocation where;
};

struct Scene {
    std::string file;  ///< the top-level RIB file
    int xres = 640, yres = 480;
    float pixelAspect = 1.0f;
    int spp = 16;
    CameraDesc camera;
    DisplayDesc display;
    IntegratorDesc integrator;
    std::vector<std::string> pluginSearchPath;  ///< from Option "searchpath" "rixplugin"
    std::vector<MaterialDesc> materials;
    std::vector<std::unique_ptr<Shape>> shapes;
    std::vector<std::unique_ptr<Light>> lights;
    /// Things dropped at load, e.g. "light 'fill' has zero intensity" (for the stats).
    std::vector<std::string> dropped;
};

}  // namespace bxdflab
