// Options, the camera and frames: what comes before WorldBegin, and the
// blocks that make frames.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>

#include "core/Folders.h"
#include "core/PixelFilter.h"
#include "scene/DisplayChannels.h"
#include "scene/SceneBuilder.h"

namespace bxdflab {
namespace fs = std::filesystem;

namespace {
constexpr int kMaxResolution = 16384;
constexpr int kMaxSamplesPerPixel = 1 << 20;  // as rixrender --spp

std::vector<std::string> splitPath(std::string const& list) {
    std::vector<std::string> parts;
    std::stringstream in(list);
    for (std::string item; std::getline(in, item, ':');)
        if (!item.empty()) parts.push_back(item);
    return parts;
}
}  // namespace

void SceneBuilder::display(RequestReader& in) {
    std::string name = in.string("image name");
    std::string type = in.string("display type");
    std::string mode = in.string("display mode");
    ParamList params = in.params();
    // "+" adds a display to those in effect; with none yet (as Blender's RIBMosaic writes every
    // frame's), it is the image. Without it, a display replaces all of them.
    bool const added = !name.empty() && name[0] == '+';
    if (added) name.erase(0, 1);
    bool const further = added && m_scene.display.where.known();
    DisplayLayout layout = displayLayout(mode);
    if (!layout.unknown.empty()) {
        // Shader outputs (arbitrary output variables) need a shading language this renderer does not have.
        std::string const problem = std::string("Display \"") + (added ? "+" : "") + name + "\" mode \"" + mode +
                                    "\": \"" + layout.unknown + "\" is not an output this renderer makes (it makes " +
                                    displayModeNames() + ")";
        if (further) {
            warnOnce("display mode " + layout.unknown, in.where(), problem + "; skipped");
            return;
        }
        warnOnce("display mode " + layout.unknown, in.where(), problem + "; the shaded image is written instead");
        mode = "rgba";
        layout = displayLayout(mode);
    }
    Param const* camera = params.find("camera");
    std::string const cameraName =
        camera && camera->decl.type == ParamType::String && !camera->strings.empty() ? camera->strings[0] : "";
    SourceLocation const cameraWhere = camera ? camera->location : in.where();
    if (further) {
        if (!cameraName.empty() && cameraName != m_scene.display.camera)
            warnOnce("further display camera", cameraWhere,
                     "Display \"+" + name + "\" asks to be seen from camera \"" + cameraName +
                         "\": every image of a render is seen from one camera, the first Display's");
        if (type == "framebuffer" || type == "it")
            warnOnce("further framebuffer", in.where(),
                     "Display \"+" + name + "\" \"" + type + "\" would show a further image in a window, which this "
                     "renderer does not open; skipped");
        else
            m_scene.moreDisplays.push_back({name, type, mode, in.where(), layout, cameraName, cameraWhere});
        return;
    }
    m_scene.display = {name, type, mode, in.where(), layout, cameraName, cameraWhere};
    m_scene.moreDisplays.clear();
    displayFilterAndExposure(params);
}

void SceneBuilder::displayFilterAndExposure(ParamList const& params) {
    // The driver's own settings (quantize, dither, compression, ...) are the output file's business: not
    // read.
    Param const* filter = params.find("filter");
    if (filter && filter->decl.type == ParamType::String && !filter->strings.empty()) {
        Param const* width = params.find("filterwidth");
        bool const widthGiven = width && width->decl.type == ParamType::Float && width->floats.size() == 2;
        setPixelFilter(filter->strings[0], widthGiven ? width->floats[0] : m_scene.pixelFilter.xwidth,
                       widthGiven ? width->floats[1] : m_scene.pixelFilter.ywidth, filter->location);
    }
    Param const* exposure = params.find("exposure");
    if (exposure && exposure->decl.type == ParamType::Float && exposure->floats.size() == 2)
        setExposure(exposure->floats[0], exposure->floats[1], exposure->location);
}

void SceneBuilder::format(RequestReader& in) {
    std::vector<float> v = in.numbers(3, "xresolution yresolution pixelaspectratio");
    in.finish();
    std::string const problem = resolutionProblem(v[0], v[1]);
    if (!problem.empty()) in.fail(in.where(), problem);
    setFormat(v[0], v[1], v[2]);
}

std::string SceneBuilder::resolutionProblem(float x, float y) {
    if (!(x >= 1 && y >= 1) || x != std::floor(x) || y != std::floor(y))
        return "resolution must be whole numbers of at least 1 pixel, got " + std::to_string(x) + " x " +
               std::to_string(y);
    if (x > kMaxResolution || y > kMaxResolution) {
        std::ostringstream size;  // the numbers as given: they may be far beyond any integer type
        size << x << " x " << y;
        return "resolution " + size.str() + " exceeds the limit of " + std::to_string(kMaxResolution) +
               " pixels per side";
    }
    return "";
}

void SceneBuilder::setFormat(float x, float y, float pixelAspect) {
    m_scene.xres = static_cast<int>(x);
    m_scene.yres = static_cast<int>(y);
    // A pixel aspect ratio of 0 or less means "square pixels" (RI specification).
    m_scene.pixelAspect = pixelAspect > 0.0f ? pixelAspect : 1.0f;
}

void SceneBuilder::projection(RequestReader& in) {
    std::string type = in.string("projection type");
    ParamList params = in.params();
    // RenderMan's camera plugins: PxrCamera and PxrPerspective are perspective cameras with a fov.
    if (type == "PxrCamera" || type == "PxrPerspective") {
        warnOnce("projection " + type, in.where(),
                 "Projection \"" + type + "\" is rendered as a perspective camera with a thin lens (its other lens "
                 "effects are not)");
        type = "perspective";
    }
    if (type == "PxrOrthographic")
        type = "orthographic";  // RenderMan's plugin for it, the screen window its only setting
    if (type != "perspective" && type != "orthographic")
        in.fail(in.where(), "unsupported projection \"" + type + "\" (use \"perspective\" or \"orthographic\")");
    m_scene.camera.projection = type;
    if (Param const* fov = params.take("fov")) {
        float value = params.getFloat("fov", 90.0f);
        if (!(value > 0.0f && value < 180.0f))
            throw RibError(fov->location, "Projection: fov must be between 0 and 180 degrees (exclusive), got " +
                                              std::to_string(value));
        m_scene.camera.fov = value;
    } else if (type == "perspective") {
        m_scene.camera.fov = 90.0f;  // the RI specification's default
    }
    // RenderMan's perspective cameras take DepthOfField's three numbers as parameters.
    params.typeUntyped({{"fStop", ParamType::Float}, {"focalLength", ParamType::Float}, {"focalDistance", ParamType::Float}},
                       "Projection");
    Param const* fStop = params.take("fStop");
    Param const* focalLength = params.take("focalLength");
    Param const* focalDistance = params.take("focalDistance");
    if (fStop && focalLength && focalDistance)
        setDepthOfField(params.getFloat("fStop", 0.0f), params.getFloat("focalLength", 0.0f),
                        params.getFloat("focalDistance", 0.0f), fStop->location);
    else if (fStop || focalLength || focalDistance)
        m_diagnostics.warn((fStop ? fStop : focalLength ? focalLength : focalDistance)->location,
                           "Projection: depth of field needs all of fStop, focalLength and focalDistance; the camera "
                           "stays a pinhole");
    params.warnUnused(m_diagnostics, "Projection");
}

void SceneBuilder::camera(RequestReader& in) {
    // RenderMan 22 and later write the camera as Projection, its transform and then Camera, which saves the
    // camera description of the moment under a name; a Display's "string camera" picks the one it is seen from.
    std::string const name = in.string("camera name");
    ParamList params = in.params();
    // Its nearClip and farClip set the clipping planes, as a Clipping request would. Its lens shape and
    // shutter curve (apertureNSides, shutterOpenTime, ...) are effects not modelled here: at RenderMan's
    // defaults, which exporters write, they describe the plain camera this renderer has and are taken
    // silently; any other value is warned about as unused.
    params.typeUntyped({{"nearClip", ParamType::Float}, {"farClip", ParamType::Float}}, "Camera");
    static std::pair<char const*, float> const kPlainCamera[] = {
        {"shutterOpenTime", 0.0f}, {"shutterCloseTime", 1.0f}, {"apertureNSides", 0.0f}, {"apertureAngle", 0.0f},
        {"apertureRoundness", 0.0f}, {"apertureDensity", 0.0f}, {"dofaspect", 1.0f}};
    for (auto const& [parameter, plain] : kPlainCamera) {
        Param const* written = params.find(parameter);
        if (!written || written->decl.reference) continue;
        bool const one = std::max(written->floats.size(), written->ints.size()) == 1;  // an int keeps both
        bool const isPlain =
            one && (written->floats.empty() ? static_cast<float>(written->ints[0]) : written->floats[0]) == plain;
        if (isPlain) params.take(parameter);
    }
    // RenderMan 21's shutter opening, [0 1]: open at once at the start and shut at once at the end.
    if (Param const* opening = params.find("shutteropening");
        opening && !opening->decl.reference && opening->floats == std::vector<float>{0.0f, 1.0f})
        params.take("shutteropening");
    Param const* nearClip = params.take("nearClip");
    Param const* farClip = params.take("farClip");
    if (nearClip || farClip)
        setClipping({params.getFloat("nearClip", m_scene.camera.clipNear),
                     params.getFloat("farClip", m_scene.camera.clipFar)},
                    (nearClip ? nearClip : farClip)->location, "Camera \"" + name + "\": nearClip and farClip");
    params.warnUnused(m_diagnostics, "Camera");
    CameraDesc& saved = m_scene.namedCameras[name];
    saved = m_scene.camera;
    saved.worldToCamera = state().transform;
    saved.motion = state().motion;
}

void SceneBuilder::chooseCamera() {
    std::string const& name = m_scene.display.camera;
    auto const named = m_scene.namedCameras.find(name);
    if (named != m_scene.namedCameras.end()) {
        m_scene.camera = named->second;
        return;
    }
    if (!name.empty())
        warnOnce("unknown camera", m_scene.display.cameraWhere,
                 "Display \"" + m_scene.display.name + "\" asks to be seen from camera \"" + name +
                     "\", which no Camera request has named: it is seen from the camera at WorldBegin");
    m_scene.camera.worldToCamera = state().transform;
    m_scene.camera.motion = state().motion;  // a motion block before WorldBegin moves the camera
}

void SceneBuilder::displayChannel(RequestReader& in) {
    // Declares an output channel ("color Ci", "float a", or a light path expression as its "source") that a
    // Display's mode may then name. The Display is what says whether this renderer makes it.
    in.string("channel declaration");
    ParamList params = in.params();
    for (auto const& p : params.all()) p.used = true;  // its own filter, exposure and source are not read
}

void SceneBuilder::relativeDetail(RequestReader& in) {
    float const scale = in.number("relativedetail");
    in.finish();
    if (!(scale >= 0.0f) || !std::isfinite(scale))
        in.fail(in.where(), "the scale must be a finite number of at least 0");
    m_scene.relativeDetail = scale;
}

void SceneBuilder::depthOfField(RequestReader& in) {
    if (in.atEnd()) {  // no arguments: a pinhole again
        m_scene.camera.fStop = 0.0f;
        return;
    }
    std::vector<float> v = in.numbers(3, "fstop focallength focaldistance");
    in.finish();
    setDepthOfField(v[0], v[1], v[2], in.where());
}

void SceneBuilder::setDepthOfField(float fStop, float focalLength, float focalDistance, SourceLocation const& where) {
    // Exporters write a pinhole as an fstop of 1e38 or a focal length of 0 (its focal distance then means nothing).
    bool const pinhole = fStop >= 1e30f || focalLength == 0.0f;
    if (!(fStop > 0.0f) || !(focalLength >= 0.0f) || !std::isfinite(focalLength) ||
        (!pinhole && !(focalDistance > 0.0f && std::isfinite(focalDistance))))
        throw RibError(where, "DepthOfField: fstop, focallength and focaldistance must be more than 0 (an infinite fstop "
                              "or a focal length of 0 is a pinhole)");
    m_scene.camera.fStop = fStop;
    m_scene.camera.focalLength = focalLength;
    m_scene.camera.focalDistance = focalDistance;
}

void SceneBuilder::screenWindow(RequestReader& in) {
    std::vector<float> v = in.numbers(4, "left right bottom top");
    in.finish();
    if (v[0] == v[1] || v[2] == v[3]) in.fail(in.where(), "screen window has zero width or height");
    setScreenWindow(v);
}

void SceneBuilder::setScreenWindow(std::vector<float> const& window) {
    m_scene.camera.hasScreenWindow = true;
    std::copy(window.begin(), window.end(), m_scene.camera.screenWindow);
}

void SceneBuilder::frameAspectRatio(RequestReader& in) {
    float const ratio = in.number("frameaspectratio");
    in.finish();
    setFrameAspectRatio(ratio);
}

void SceneBuilder::setFrameAspectRatio(float ratio) {
    // RenderMan writes -1 for "the Format's" (Option "Ri" "float FrameAspectRatio" [-1]).
    m_scene.camera.frameAspectRatio = std::max(ratio, 0.0f);
}

void SceneBuilder::pixelSamples(RequestReader& in) {
    std::vector<float> v = in.numbers(2, "xsamples ysamples");
    in.finish();
    if (!(v[0] >= 1.0f && v[1] >= 1.0f)) in.fail(in.where(), "sample counts must be at least 1");
    double spp = std::ceil(static_cast<double>(v[0]) * v[1]);
    if (spp > kMaxSamplesPerPixel)
        in.fail(in.where(), "asks for " + std::to_string(spp) + " samples per pixel, more than the limit of " +
                                std::to_string(kMaxSamplesPerPixel));
    m_scene.spp = static_cast<int>(spp);
}

void SceneBuilder::pixelFilter(RequestReader& in) {
    std::string const name = in.string("filter name");
    std::vector<float> const widths = in.numbers(2, "xwidth ywidth");
    in.finish();
    setPixelFilter(name, widths[0], widths[1], in.where());
}

void SceneBuilder::setPixelFilter(std::string const& name, float xwidth, float ywidth,
                                  SourceLocation const& where) {
    if (!(xwidth > 0.0f && ywidth > 0.0f && xwidth <= 16.0f && ywidth <= 16.0f))
        throw RibError(where, "PixelFilter widths must be above 0 and at most 16 pixels");
    std::vector<std::string> const& known = pixelFilterNames();
    if (std::find(known.begin(), known.end(), name) == known.end()) {
        std::ostringstream message;
        message << "PixelFilter \"" << name << "\" is not one this renderer has (";
        for (std::string const& k : known) message << k << (&k == &known.back() ? "" : ", ");
        message << "); the image is filtered with " << m_scene.pixelFilter.name << " "
                << m_scene.pixelFilter.xwidth << " " << m_scene.pixelFilter.ywidth;
        warnOnce("pixel filter " + name, where, message.str());
        return;
    }
    m_scene.pixelFilter = {name, xwidth, ywidth};
}

void SceneBuilder::hider(RequestReader& in) {
    std::string type = in.string("hider type");
    ParamList params = in.params();
    if (type != "raytrace") warnOnce("hider " + type, in.where(), "Hider \"" + type + "\" treated as \"raytrace\"");
    if (type == "raytrace") hiderSampleCounts(params, "Hider");
    for (auto const& p : params.all()) p.used = true;  // jitter, incremental, photon emission: not modelled
}

void SceneBuilder::hiderSampleCounts(ParamList const& params, std::string const& owner) {
    // minsamples and minextrasamples of 0 or -1 (RenderMan's default) ask for their automatic values.
    // The other controls of RenderMan's sampler (incremental, adaptivemetric, ...) are accepted by the callers.
    auto count = [&](char const* name, int least) -> std::optional<int> {
        Param const* p = params.take(name);
        if (!p) return std::nullopt;
        int const value = params.getInt(name, 0);
        if (value < least || value > kMaxSamplesPerPixel)
            throw RibError(p->location, owner + ": " + name + " must be between " + std::to_string(least) + " and " +
                                            std::to_string(kMaxSamplesPerPixel) + ", got " + std::to_string(value));
        return value;
    };
    if (std::optional<int> most = count("maxsamples", 1)) m_scene.spp = *most;
    if (std::optional<int> least = count("minsamples", -1)) m_scene.minSamples = *least;
    if (std::optional<int> extra = count("minextrasamples", -1)) m_scene.minExtraSamples = *extra;
    if (Param const* p = params.take("darkfalloff")) {
        float const falloff = params.getFloat("darkfalloff", 0.025f);
        if (!(falloff >= 0.0f && falloff <= 1.0f))
            throw RibError(p->location, owner + ": darkfalloff must be between 0 and 1");
        m_scene.darkFalloff = falloff;
    }
    if (Param const* p = params.take("pixelvariance"))
        setPixelVariance(params.getFloat("pixelvariance", 0.0f), p->location);
}

void SceneBuilder::errorHandler(RequestReader& in) {
    // Errors here always stop the read at their line and warnings are said once per kind, so the
    // standard handlers ("ignore", "print", "abort" and PRMan's "printonce") change nothing.
    std::string const handler = in.string("error handler name");
    in.finish();
    if (handler != "ignore" && handler != "print" && handler != "printonce" && handler != "abort")
        warnOnce("error handler", in.where(),
                 "ErrorHandler \"" + handler + "\" is not a standard handler (ignore, print, printonce, abort); "
                 "errors stop the read at their line and warnings are printed once per kind");
}

void SceneBuilder::pixelVariance(RequestReader& in) {
    float const variance = in.number("variance");
    in.finish();
    setPixelVariance(variance, in.where());
}

void SceneBuilder::setPixelVariance(float variance, SourceLocation const& where) {
    if (!(variance >= 0.0f && std::isfinite(variance)))
        throw RibError(where, "PixelVariance must be 0 (every pixel takes all its samples) or a number above 0");
    m_scene.pixelVariance = variance;
}

void SceneBuilder::imager(RequestReader& in) {
    // One imager at a time: the last Imager line wins; "null" or "" turns it off.
    std::string const name = in.string("imager shader name");
    ParamList params = in.params();
    ImageFinish& finish = m_scene.finish;
    finish.clampToAlpha = false;
    finish.overBackground = false;
    std::string const owner = "Imager \"" + name + "\"";
    if (name == "background") {
        // The colour goes by different names: the RenderMan Interface Specification's
        // "background", RenderMan 21's "color", and "bgcolor" in many scripts.
        params.typeUntyped({{"background", ParamType::Color}, {"color", ParamType::Color}, {"bgcolor", ParamType::Color},
                            {"alpha", ParamType::Float}},
                           owner);
        finish.overBackground = true;
        finish.background = Vec3(1.0f);  // the specification's default
        for (char const* colorName : {"background", "color", "bgcolor"})
            if (params.take(colorName)) finish.background = params.getColor(colorName, finish.background);
        finish.backgroundAlpha = params.take("alpha") ? params.getFloat("alpha", 1.0f) : 1.0f;
        params.warnUnused(m_diagnostics, owner);
    } else if (name == "clamptoalpha") {
        finish.clampToAlpha = true;
        params.warnUnused(m_diagnostics, owner);
    } else if (name != "null" && !name.empty()) {
        for (Param const& p : params.all()) p.used = true;
        warnOnce("imager " + name, in.where(),
                 owner + " is not an imager this renderer has (it has \"background\" and \"clamptoalpha\"); skipped");
    }
}

void SceneBuilder::exposure(RequestReader& in) {
    float const gain = in.number("gain");
    float const gamma = in.number("gamma");
    in.finish();
    setExposure(gain, gamma, in.where());
}

void SceneBuilder::setExposure(float gain, float gamma, SourceLocation const& where) {
    if (!(gain >= 0.0f) || !std::isfinite(gain))
        throw RibError(where, "Exposure: the gain must be 0 or more");
    if (!(gamma > 0.0f) || !std::isfinite(gamma))
        throw RibError(where, "Exposure: the gamma must be more than 0");
    m_scene.finish.exposureGain = gain;
    m_scene.finish.exposureGamma = gamma;
}

void SceneBuilder::displayFilter(RequestReader& in) {
    backgroundFilter(in, "DisplayFilter", "display filter", "PxrBackgroundDisplayFilter");
}

void SceneBuilder::sampleFilter(RequestReader& in) {
    backgroundFilter(in, "SampleFilter", "sample filter", "PxrBackgroundSampleFilter");
}

void SceneBuilder::backgroundFilter(RequestReader& in, std::string const& request, std::string const& what,
                                    std::string const& background) {
    std::string const name = in.string((what + " plugin name").c_str());
    in.string((what + " handle").c_str());
    ParamList params = in.params();
    if (name != background) {
        for (Param const& p : params.all()) p.used = true;
        warnOnce(request + " " + name, in.where(),
                 request + " \"" + name + "\" is not one this renderer has (it has " + background + "); skipped");
        return;
    }
    // Composes the image over a colour; alpha is left as rendered. The sample filter does it to each
    // camera sample, which, as compositing is linear, comes to the same pixels.
    std::string const owner = request + " \"" + name + "\"";
    params.typeUntyped({{"backgroundColor", ParamType::Color}}, owner);
    ImageFinish& finish = m_scene.finish;
    finish.overBackground = true;
    finish.background = params.getColor("backgroundColor", Vec3(0.0f));
    params.take("backgroundColor");
    finish.backgroundAlpha = 0.0f;
    params.warnUnused(m_diagnostics, owner);
}

void SceneBuilder::integrator(RequestReader& in) {
    // The last Integrator line wins, as in RenderMan.
    m_scene.integrator.name = in.string("integrator name");
    m_scene.integrator.handle = in.string("integrator handle");
    m_scene.integrator.params = in.params();
    m_scene.integrator.where = in.where();
    m_scene.integrator.given = true;
}

void SceneBuilder::option(RequestReader& in) {
    std::string category = in.string("option name");
    ParamList params = in.params();
    if (category == "user") {
        // Values a scene names in its search paths ("${RMSPROJ}") and conditions.
        for (Param const& p : params.all()) {
            p.used = true;
            if (std::optional<std::string> value = p.firstValueText()) m_userOptions[p.name()] = *value;
        }
        return;
    }
    if (category == "Ri") {
        riOptions(params, in.where());
        return;
    }
    if (category == "ribparse") {
        // RenderMan for Maya turns "$" substitution off ("") and on ("$") this way; it is always on here.
        params.typeUntyped({{"varsubst", ParamType::String}}, "Option \"ribparse\"");
        std::string const marker = params.getString("varsubst", "$");
        params.take("varsubst");
        if (marker != "$" && !marker.empty())
            warnOnce("option ribparse", in.where(),
                     "Option \"ribparse\" \"varsubst\" [\"" + marker +
                         "\"]: variables are always written $NAME or ${NAME} here; kept so");
        params.warnUnused(m_diagnostics, "Option \"ribparse\"");
        return;
    }
    if (category == "hider") {
        // RenderMan 21 and later write the Hider's sample counts and darkfalloff here; its other controls
        // (incremental, adaptivemetric, exposurebracket, ...) steer RenderMan's own sampler and are read quietly.
        hiderSampleCounts(params, "Option \"hider\"");
        for (auto const& p : params.all()) p.used = true;
        return;
    }
    if (category != "searchpath") {
        warnOnce("option " + category, in.where(), "Option \"" + category + "\" is not used by this renderer; skipped");
        return;
    }
    auto update = [&](std::vector<std::string>& list, std::string const& key) {
        Param const* p = params.take(key);
        if (!p) return;
        // "${RMSPROJ}", as RenderMan for Maya writes.
        std::string value = expanded(params.getString(key, ""));
        std::vector<std::string> previous = list;
        list.clear();
        // A folder is searched once, where it first appears: "&" twice (or repeated
        // options) would otherwise double the path each time.
        auto add = [&list](std::string const& folder) {
            if (std::find(list.begin(), list.end(), folder) == list.end()) list.push_back(folder);
        };
        for (std::string const& item : splitPath(value)) {
            if (item == "&") {
                for (std::string const& folder : previous) add(folder);  // the path so far
            } else if (item == "@") {
                continue;  // the built-in default is always searched last
            } else if (fs::path(item).is_absolute()) {
                add(item);
            } else {
                // RenderMan reads a relative folder from the folder it runs in, which is where a
                // Python script that renders with "__render" keeps its assets. A scene rendered
                // from elsewhere means its own folder: both are searched, the scene's first.
                fs::path const besideScene = (fs::path(currentDirectory()) / item).lexically_normal();
                add(besideScene.string());
                fs::path const fromWorkingFolder = absoluteFolder(item);
                if (!fromWorkingFolder.empty() && absoluteFolder(besideScene) != fromWorkingFolder)
                    add(fromWorkingFolder.string());
            }
        }
    };
    update(m_scene.pluginSearchPath, "rixplugin");
    update(m_archiveSearchPath, "archive");
    update(m_shaderSearchPath, "shader");
    update(m_scene.textureSearchPath, "texture");
    update(m_proceduralSearchPath, "procedural");
    for (auto const& p : params.all())
        if (!p.used) warnOnce("searchpath " + p.name(), p.location, "Option \"searchpath\" \"" + p.name() + "\" is not used; skipped");
}

void SceneBuilder::riOptions(ParamList const& params, SourceLocation const& where) {
    // RenderMan 21 and later write the camera and image requests as one Option "Ri",
    // each request a parameter of its own name (Format's values as "FormatResolution"
    // and "FormatPixelAspectRatio").
    if (m_inWorld) {
        warnOnce("option in world Ri", where,
                 "Option \"Ri\" inside a world block is ignored: the camera and image are set before WorldBegin");
        for (auto const& p : params.all()) p.used = true;
        return;
    }
    if (Param const* p = params.take("FormatResolution")) {
        std::vector<float> const* size = params.getFloats("FormatResolution", ParamType::Float);
        if (!size || size->size() != 2)
            throw RibError(p->location, "Option \"Ri\" \"FormatResolution\" takes two numbers (width, height)");
        std::string const problem = resolutionProblem((*size)[0], (*size)[1]);
        if (!problem.empty()) throw RibError(p->location, "Option \"Ri\" \"FormatResolution\": " + problem);
        setFormat((*size)[0], (*size)[1], params.getFloat("FormatPixelAspectRatio", m_scene.pixelAspect));
    } else if (params.has("FormatPixelAspectRatio")) {
        setFormat(static_cast<float>(m_scene.xres), static_cast<float>(m_scene.yres),
                  params.getFloat("FormatPixelAspectRatio", 1.0f));
    }
    if (Param const* p = params.take("ScreenWindow")) {
        std::vector<float> const* window = params.getFloats("ScreenWindow", ParamType::Float);
        if (!window || window->size() != 4 || (*window)[0] == (*window)[1] || (*window)[2] == (*window)[3])
            throw RibError(p->location,
                           "Option \"Ri\" \"ScreenWindow\" takes four numbers (left right bottom top) that span an area");
        setScreenWindow(*window);
    }
    if (params.take("FrameAspectRatio")) setFrameAspectRatio(params.getFloat("FrameAspectRatio", 0.0f));
    if (Param const* p = params.take("Clipping")) {
        std::vector<float> const* planes = params.getFloats("Clipping", ParamType::Float);
        setClipping(planes ? *planes : std::vector<float>{}, p->location, "Option \"Ri\" \"Clipping\"");
    }
    // The frame number is a label.
    params.ignore("Frame");
    if (Param const* p = params.take("Shutter")) {
        std::vector<float> const* times = params.getFloats("Shutter", ParamType::Float);
        if (!times || times->size() != 2)
            throw RibError(p->location, "Option \"Ri\" \"Shutter\" takes two numbers (open close)");
        setShutter((*times)[0], (*times)[1], p->location);
    }
    if (params.has("CropWindow")) {
        std::vector<float> const* crop = params.getFloats("CropWindow", ParamType::Float);
        checkCropWindow(crop ? *crop : std::vector<float>{}, params.find("CropWindow")->location,
                        "Option \"Ri\" \"CropWindow\"");
    }
    if (Param const* p = params.take("PixelFilterName")) {
        std::vector<float> const* widths = params.getFloats("PixelFilterWidth", ParamType::Float);
        setPixelFilter(params.getString("PixelFilterName", "box"),
                       widths && widths->size() == 2 ? (*widths)[0] : 2.0f,
                       widths && widths->size() == 2 ? (*widths)[1] : 2.0f, p->location);
    }
    if (Param const* p = params.take("PixelVariance"))
        setPixelVariance(params.getFloat("PixelVariance", 0.0f), p->location);
    // The rest are requests this renderer skips when written out (Exposure, ...).
    for (auto const& p : params.all())
        if (!p.used)
            warnOnce("option Ri " + p.name(), p.location,
                     "Option \"Ri\" \"" + p.name() + "\" is not used by this renderer; skipped");
}

void SceneBuilder::declare(RequestReader& in) {
    std::string name = in.string("parameter name");
    std::string decl = in.string("declaration");
    in.finish();
    m_declarations.declare(name, decl, in.where());
}

void SceneBuilder::colorSamples(RequestReader& in) {
    // RI's nRGB (n rows of 3: a colour of n numbers to RGB) and RGBn (its way back, unused here).
    std::vector<float> toRGB = in.numberArray("nRGB (the colour samples to RGB, 3 numbers a sample)");
    std::vector<float> fromRGB =
        in.numberArray("RGBn (RGB to the colour samples, n numbers for each of R, G, B)");
    in.finish();
    if (toRGB.empty() || toRGB.size() % 3 != 0 || fromRGB.size() != toRGB.size())
        in.fail(in.where(), "ColorSamples needs nRGB and RGBn of 3 numbers per colour sample each, got " +
                                std::to_string(toRGB.size()) + " and " + std::to_string(fromRGB.size()));
    ColorSamples samples;
    samples.count = toRGB.size() / 3;
    samples.toRGB = std::move(toRGB);
    m_declarations.setColorSamples(std::move(samples));
}

void SceneBuilder::frameBegin(RequestReader& in) {
    int number = in.atEnd() ? static_cast<int>(m_frames.size()) : in.integer("frame number");
    in.finish();
    // A frame's options and state are its own: FrameEnd restores those before it.
    m_frames.push_back({static_cast<SceneOptions const&>(m_scene), m_attributes, m_declarations.colorSamples()});
    m_frameNumber = number;
}

void SceneBuilder::frameEnd(RequestReader& in) {
    in.finish();
    if (m_frames.empty()) in.fail(in.where(), "FrameEnd without a matching FrameBegin");
    if (m_inWorld) {
        m_diagnostics.warn(in.where(), "FrameEnd inside a world block (WorldEnd missing)");
        m_inWorld = false;
        finishFrame();
    }
    static_cast<SceneOptions&>(m_scene) = m_frames.back().options;
    m_attributes = m_frames.back().attributes;
    m_declarations.setColorSamples(m_frames.back().colorSamples);
    m_frames.pop_back();
    m_frameNumber = m_frames.empty() ? -1 : m_frameNumber;
}

void SceneBuilder::worldBegin(RequestReader& in) {
    in.finish();
    if (m_inWorld) {
        // Most often an archive that is a whole scene, read into another. RenderMan
        // reports the nesting and goes on; so does this renderer, reading what lies
        // between into the enclosing world (its options and camera are ignored).
        warnOnce("nested world", in.where(),
                 "WorldBegin inside a world block (an archive that is a whole scene?): ignored with its WorldEnd; "
                 "what lies between is read into the enclosing world");
        ++m_nestedWorlds;
        return;
    }
    chooseCamera();
    std::vector<Mat4> poses = {m_scene.camera.worldToCamera};
    if (m_scene.camera.motion)
        poses.insert(poses.end(), m_scene.camera.motion->transforms.begin(),
                     m_scene.camera.motion->transforms.end());
    for (Mat4 const& pose : poses) {
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                if (!std::isfinite(pose[i][j])) in.fail(in.where(), "the camera transform is not finite");
        if (std::fabs(glm::determinant(pose)) < 1e-12f)
            in.fail(in.where(), "the camera transform is singular (a zero scale?)");
    }
    m_namedSpaces["camera"] = glm::inverse(m_scene.camera.worldToCamera);
    m_namedSpaces["world"] = Mat4(1.0f);
    state().transform = Mat4(1.0f);
    state().motion = nullptr;
    m_inWorld = true;
    // Worlds that are not wanted are read (for their errors and state) but not built.
    m_skipWorld = (!m_sink && m_keptFrame) || (m_options.frame >= 0 && m_frameNumber != m_options.frame);
    m_ambient = Vec3(0.0f);
    m_firstClassicLight.reset();
    m_lightHandles.clear();
    m_lightUse.clear();
    m_worldShapes = 0;
    m_shapesOutsideDetail = 0;
    m_listedLights = 0;
    m_lightsOff.clear();
    m_lightsOffIndex.clear();
    // Lights given before WorldBegin were placed in camera space; the world now knows where that is.
    if (building())
        for (CameraLight const& light : m_cameraLights)
            makeLightFrom(light.request, light.type, light.handle, light.params,
                          m_namedSpaces["camera"] * light.toCamera, light.where);
}

void SceneBuilder::worldEnd(RequestReader& in) {
    in.finish();
    if (m_nestedWorlds > 0) {
        --m_nestedWorlds;
        return;
    }
    if (!m_inWorld) in.fail(in.where(), "WorldEnd without WorldBegin");
    m_inWorld = false;
    finishFrame();
}

void SceneBuilder::clipping(RequestReader& in) {
    std::vector<float> planes = in.numbers(2, "near far");
    in.finish();
    setClipping(planes, in.where(), "Clipping");
}

void SceneBuilder::setClipping(std::vector<float> const& planes, SourceLocation const& where, std::string const& what) {
    // The RenderMan Interface asks for 0 < near < far (far may be infinite); the planes clip camera rays only.
    if (planes.size() != 2 || !(planes[0] >= 0.0f) || !(planes[1] > planes[0])) {
        warnOnce("clipping", where, what + " takes two distances, near and far, with 0 <= near < far; skipped");
        return;
    }
    m_scene.camera.clipNear = planes[0];
    m_scene.camera.clipFar = planes[1];
}

void SceneBuilder::cropWindow(RequestReader& in) {
    std::vector<float> v = in.numbers(4, "xmin xmax ymin ymax");
    in.finish();
    checkCropWindow(v, in.where(), "CropWindow");
}

void SceneBuilder::checkCropWindow(std::vector<float> const& window, SourceLocation const& where,
                                   std::string const& what) {
    // Exporters write the whole image (0 1 0 1) as a matter of course: that asks for nothing.
    bool const whole = window.size() == 4 && window[0] <= 0.0f && window[1] >= 1.0f && window[2] <= 0.0f &&
                       window[3] >= 1.0f;
    if (!whole)
        warnOnce("crop window", where, what + " (a part of the image) is not supported: the whole image is rendered");
}

void SceneBuilder::shutter(RequestReader& in) {
    std::vector<float> const times = in.numbers(2, "open close");
    in.finish();
    setShutter(times[0], times[1], in.where());
}

void SceneBuilder::setShutter(float open, float close, SourceLocation const& where) {
    if (!std::isfinite(open) || !std::isfinite(close)) throw RibError(where, "Shutter times must be finite numbers");
    if (close < open) throw RibError(where, "Shutter closes before it opens (open close, in that order)");
    m_scene.shutterOpen = open;
    m_scene.shutterClose = close;
}

void SceneBuilder::shadingRate(RequestReader& in) {
    // How finely a REYES renderer dices surfaces; a ray tracer shades where rays hit.
    in.number("shading rate");
    in.finish();
}

void SceneBuilder::shadingInterpolation(RequestReader& in) {
    // Whether a REYES renderer shades micropolygons flat or smoothly: both are finer than a pixel.
    std::string const kind = in.string("\"constant\" or \"smooth\"");
    in.finish();
    if (kind != "constant" && kind != "smooth")
        in.fail(in.where(), "ShadingInterpolation must be \"constant\" or \"smooth\", not \"" + kind + "\"");
}

void SceneBuilder::geometricApproximation(RequestReader& in) {
    // How finely a REYES renderer dices surfaces ("flatness", "motionfactor", ...): surfaces here are
    // intersected as they are, or tessellated by their own rule.
    in.string("approximation type");
    in.number("its value");
    in.finish();
}

void SceneBuilder::quantize(RequestReader& in) {
    std::string const channels = in.string("\"rgba\" or \"z\"");
    std::vector<float> const q = in.numbers(4, "one min max dither");
    in.finish();
    // RenderMan's 8-bit (255) and floating-point (0) settings are what the image formats here write;
    // other depths are the file format's, and dithering is not added.
    if (q[0] != 0.0f && q[0] != 255.0f)
        warnOnce("quantize", in.where(),
                 "Quantize \"" + channels + "\" " + std::to_string(static_cast<long>(q[0])) +
                     ": the image is written with its file format's own depth (8-bit PNG and JPEG, float EXR and "
                     "TIFF)");
}

}  // namespace bxdflab
