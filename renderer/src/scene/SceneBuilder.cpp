#include "scene/SceneBuilder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <sstream>

#include "parse/RibParser.h"
#include "scene/lights/LightFactory.h"
#include "scene/shapes/MeshBuilders.h"
#include "scene/shapes/Quadric.h"

namespace bxdflab {
namespace fs = std::filesystem;

namespace {
constexpr int kMaxArchiveDepth = 32;
constexpr int kMaxResolution = 16384;
constexpr int kMaxSamplesPerPixel = 1 << 20;  // as rixrender --spp
constexpr long kMaxReplayedRequests = 4'000'000;  // what instancing may expand to

std::vector<std::string> splitPath(std::string const& list) {
    std::vector<std::string> parts;
    std::stringstream in(list);
    for (std::string item; std::getline(in, item, ':');)
        if (!item.empty()) parts.push_back(item);
    return parts;
}
}  // namespace

SceneBuilder::SceneBuilder(Scene& scene, Diagnostics& diagnostics) : m_scene(scene), m_diagnostics(diagnostics) {}

std::map<std::string, SceneBuilder::Handler> const& SceneBuilder::handlers() {
    static const std::map<std::string, Handler> table = {
        {"version", &SceneBuilder::ignore},
        {"FrameBegin", &SceneBuilder::ignore},
        {"FrameEnd", &SceneBuilder::ignore},
        {"Display", &SceneBuilder::display},
        {"Format", &SceneBuilder::format},
        {"Projection", &SceneBuilder::projection},
        {"ScreenWindow", &SceneBuilder::screenWindow},
        {"PixelSamples", &SceneBuilder::pixelSamples},
        {"Hider", &SceneBuilder::hider},
        {"Integrator", &SceneBuilder::integrator},
        {"Option", &SceneBuilder::option},
        {"Declare", &SceneBuilder::declare},
        {"WorldBegin", &SceneBuilder::worldBegin},
        {"WorldEnd", &SceneBuilder::worldEnd},
        {"AttributeBegin", &SceneBuilder::attributeBegin},
        {"AttributeEnd", &SceneBuilder::attributeEnd},
        {"TransformBegin", &SceneBuilder::transformBegin},
        {"TransformEnd", &SceneBuilder::transformEnd},
        {"Identity", &SceneBuilder::identity},
        {"Transform", &SceneBuilder::transform},
        {"ConcatTransform", &SceneBuilder::concatTransform},
        {"Translate", &SceneBuilder::translate},
        {"Rotate", &SceneBuilder::rotate},
        {"Scale", &SceneBuilder::scale},
        {"Attribute", &SceneBuilder::attribute},
        {"Color", &SceneBuilder::color},
        {"ReverseOrientation", &SceneBuilder::reverseOrientation},
        {"Orientation", &SceneBuilder::orientation},
        {"Bxdf", &SceneBuilder::bxdf},
        {"Light", &SceneBuilder::light},
        {"Sphere", &SceneBuilder::sphere},
        {"Cylinder", &SceneBuilder::cylinder},
        {"Disk", &SceneBuilder::disk},
        {"Polygon", &SceneBuilder::polygon},
        {"PointsPolygons", &SceneBuilder::pointsPolygons},
        {"PointsGeneralPolygons", &SceneBuilder::pointsGeneralPolygons},
        {"Patch", &SceneBuilder::patch},
        {"Geometry", &SceneBuilder::geometry},
        {"ReadArchive", &SceneBuilder::readArchive},
        {"Cone", &SceneBuilder::cone},
        {"Paraboloid", &SceneBuilder::paraboloid},
        {"Hyperboloid", &SceneBuilder::hyperboloid},
        {"Torus", &SceneBuilder::torus},
        {"Basis", &SceneBuilder::basis},
        {"PatchMesh", &SceneBuilder::patchMesh},
        {"ObjectBegin", &SceneBuilder::objectBegin},
        {"ObjectInstance", &SceneBuilder::objectInstance},
        {"ArchiveBegin", &SceneBuilder::archiveBegin},
        {"Clipping", &SceneBuilder::clipping},
        {"Sides", &SceneBuilder::sides},
    };
    return table;
}

void SceneBuilder::readFile(std::string const& path) {
    if (m_fileStack.empty()) m_scene.file = path;
    if (static_cast<int>(m_fileStack.size()) >= kMaxArchiveDepth)
        throw RenderError("archives nested more than " + std::to_string(kMaxArchiveDepth) + " deep (at \"" + path + "\")");
    m_fileStack.push_back(path);
    parseRibFile(path, [this](RibRequest const& r) { handle(r); });
    m_fileStack.pop_back();
    if (m_fileStack.empty() && m_repeatedWarnings > 0)
        m_diagnostics.info(std::to_string(m_repeatedWarnings) + " more statement" + (m_repeatedWarnings > 1 ? "s" : "") +
                           " of the kinds warned about above " + (m_repeatedWarnings > 1 ? "were" : "was") + " skipped");
    if (m_fileStack.empty() && m_recording)
        m_diagnostics.warn(path + ": " + m_recordingEnd + " missing at the end of the file");
    if (m_fileStack.empty() && !m_sawWorld)
        throw RenderError(path + ": there is no WorldBegin, so the file describes nothing to render" +
                          " (a file of shapes alone is an archive, read from a scene with ReadArchive)");
    if (m_fileStack.empty() && m_blocks.size() > 0)
        m_diagnostics.warn(path + ": " + std::to_string(m_blocks.size()) + " AttributeBegin/TransformBegin left open at end of file");
}

void SceneBuilder::readText(std::string const& text, std::string const& fileName) {
    if (m_fileStack.empty()) m_scene.file = fileName;
    m_fileStack.push_back(fileName);
    parseRib(text, fileName, [this](RibRequest const& r) { handle(r); });
    m_fileStack.pop_back();
}

std::string SceneBuilder::currentDirectory() const {
    if (m_fileStack.empty()) return ".";
    fs::path parent = fs::path(m_fileStack.back()).parent_path();
    return parent.empty() ? "." : parent.string();
}

void SceneBuilder::warnOnce(std::string const& kind, SourceLocation const& where, std::string const& message) {
    if (m_warnedKinds.insert(kind).second)
        m_diagnostics.warn(where, message);
    else
        ++m_repeatedWarnings;
}

void SceneBuilder::handle(RibRequest const& request) {
    if (m_recording) {
        // Inside ObjectBegin/ArchiveBegin: keep the requests for later.
        if (request.name == m_recordingEnd) {
            RequestReader(request, m_declarations).finish();
            m_recording = nullptr;
        } else {
            m_recording->push_back(request);
        }
        return;
    }
    if (request.name == "ObjectEnd" || request.name == "ArchiveEnd")
        throw RibError(request.where, request.name + " without a matching " +
                                          (request.name == "ObjectEnd" ? "ObjectBegin" : "ArchiveBegin"));
    auto found = handlers().find(request.name);
    if (found == handlers().end()) {
        warnOnce("request " + request.name, request.where, "unsupported request " + request.name + " skipped");
        return;
    }
    RequestReader reader(request, m_declarations);
    (this->*found->second)(reader);
}

void SceneBuilder::ignore(RequestReader&) {}

// ------------------------------------------------------------------ options

void SceneBuilder::display(RequestReader& in) {
    std::string name = in.string("image name");
    std::string type = in.string("display type");
    std::string mode = in.string("display mode");
    ParamList params = in.params();
    if (!name.empty() && name[0] == '+') {
        warnOnce("secondary Display", in.where(), "secondary Display \"" + name + "\" (AOV output) is not supported; skipped");
        return;
    }
    m_scene.display = {name, type, mode, in.where()};
}

void SceneBuilder::format(RequestReader& in) {
    std::vector<float> v = in.numbers(3, "xresolution yresolution pixelaspectratio");
    in.finish();
    if (v[0] < 1 || v[1] < 1 || v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]))
        in.fail(in.where(), "resolution must be whole numbers of at least 1 pixel, got " + std::to_string(v[0]) + " x " +
                                std::to_string(v[1]));
    if (v[0] > kMaxResolution || v[1] > kMaxResolution) {
        std::ostringstream size;  // the numbers as given: they may be far beyond any integer type
        size << v[0] << " x " << v[1];
        in.fail(in.where(), "resolution " + size.str() + " exceeds the limit of " + std::to_string(kMaxResolution) +
                                " pixels per side");
    }
    m_scene.xres = static_cast<int>(v[0]);
    m_scene.yres = static_cast<int>(v[1]);
    m_scene.pixelAspect = v[2] > 0.0f ? v[2] : 1.0f;
}

void SceneBuilder::projection(RequestReader& in) {
    std::string type = in.string("projection type");
    ParamList params = in.params();
    if (type != "perspective" && type != "orthographic")
        in.fail(in.where(), "unsupported projection \"" + type + "\" (use \"perspective\" or \"orthographic\")");
    m_scene.camera.projection = type;
    if (Param const* fov = params.find("fov")) {
        float value = params.getFloat("fov", 90.0f);
        if (!(value > 0.0f && value < 180.0f))
            throw RibError(fov->location, "Projection: fov must be between 0 and 180 degrees (exclusive), got " +
                                              std::to_string(value));
        m_scene.camera.fov = value;
    }
    params.warnUnused(m_diagnostics, "Projection");
}

void SceneBuilder::screenWindow(RequestReader& in) {
    std::vector<float> v = in.numbers(4, "left right bottom top");
    in.finish();
    if (v[0] == v[1] || v[2] == v[3]) in.fail(in.where(), "screen window has zero width or height");
    m_scene.camera.hasScreenWindow = true;
    std::copy(v.begin(), v.end(), m_scene.camera.screenWindow);
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
    m_sppFromPixelSamples = true;
}

void SceneBuilder::hider(RequestReader& in) {
    std::string type = in.string("hider type");
    ParamList params = in.params();
    if (type != "raytrace") warnOnce("hider " + type, in.where(), "Hider \"" + type + "\" treated as \"raytrace\"");
    if (Param const* p = params.find("maxsamples")) {
        int spp = params.getInt("maxsamples", 16);
        if (spp < 1 || spp > kMaxSamplesPerPixel)
            throw RibError(p->location, "Hider: maxsamples must be between 1 and " + std::to_string(kMaxSamplesPerPixel) +
                                            ", got " + std::to_string(spp));
        m_scene.spp = spp;
    }
    params.find("minsamples");  // adaptive sampling is not implemented: every pixel gets maxsamples
    params.warnUnused(m_diagnostics, "Hider");
}

void SceneBuilder::integrator(RequestReader& in) {
    m_scene.integrator.name = in.string("integrator name");
    m_scene.integrator.handle = in.string("integrator handle");
    m_scene.integrator.params = in.params();
    m_scene.integrator.where = in.where();
    m_scene.integrator.given = true;
}

void SceneBuilder::option(RequestReader& in) {
    std::string category = in.string("option name");
    ParamList params = in.params();
    if (category != "searchpath") {
        warnOnce("option " + category, in.where(), "Option \"" + category + "\" is not supported; skipped");
        return;
    }
    auto update = [&](std::vector<std::string>& list, std::string const& key) {
        Param const* p = params.find(key);
        if (!p) return;
        std::string value = params.getString(key, "");
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
            } else {
                fs::path path(item);
                add(path.is_relative() ? (fs::path(currentDirectory()) / path).string() : item);
            }
        }
    };
    update(m_scene.pluginSearchPath, "rixplugin");
    update(m_archiveSearchPath, "archive");
    for (auto const& p : params.all())
        if (!p.used) warnOnce("searchpath " + p.name(), p.location, "Option \"searchpath\" \"" + p.name() + "\" is not used; skipped");
}

void SceneBuilder::declare(RequestReader& in) {
    std::string name = in.string("parameter name");
    std::string decl = in.string("declaration");
    in.finish();
    m_declarations.declare(name, decl, in.where());
}

void SceneBuilder::worldBegin(RequestReader& in) {
    in.finish();
    if (m_inWorld) in.fail(in.where(), "WorldBegin inside a world block");
    m_scene.camera.worldToCamera = state().transform;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(m_scene.camera.worldToCamera[i][j])) in.fail(in.where(), "the camera transform is not finite");
    if (std::fabs(glm::determinant(m_scene.camera.worldToCamera)) < 1e-12f)
        in.fail(in.where(), "the camera transform is singular (a zero scale?)");
    state().transform = Mat4(1.0f);
    m_inWorld = true;
    m_sawWorld = true;
}

void SceneBuilder::worldEnd(RequestReader& in) {
    in.finish();
    if (!m_inWorld) in.fail(in.where(), "WorldEnd without WorldBegin");
    m_inWorld = false;
}

// ------------------------------------------------------------------ graphics state

void SceneBuilder::attributeBegin(RequestReader& in) {
    in.finish();
    m_attributes.push_back(state());
    m_blocks.push_back(Block::Attribute);
}

void SceneBuilder::attributeEnd(RequestReader& in) {
    in.finish();
    if (m_blocks.empty() || m_blocks.back() != Block::Attribute)
        in.fail(in.where(), m_blocks.empty() ? "AttributeEnd without a matching AttributeBegin"
                                             : "AttributeEnd closes a TransformBegin block (expected TransformEnd)");
    m_blocks.pop_back();
    m_attributes.pop_back();
}

void SceneBuilder::transformBegin(RequestReader& in) {
    in.finish();
    m_attributes.push_back(state());
    m_blocks.push_back(Block::Transform);
}

void SceneBuilder::transformEnd(RequestReader& in) {
    in.finish();
    if (m_blocks.empty() || m_blocks.back() != Block::Transform)
        in.fail(in.where(), m_blocks.empty() ? "TransformEnd without a matching TransformBegin"
                                             : "TransformEnd closes an AttributeBegin block (expected AttributeEnd)");
    m_blocks.pop_back();
    // Only the transform is restored; attributes set inside the block persist.
    Attributes inner = m_attributes.back();
    m_attributes.pop_back();
    inner.transform = state().transform;
    state() = inner;
}

void SceneBuilder::identity(RequestReader& in) {
    in.finish();
    state().transform = Mat4(1.0f);
}

// RIB matrices are row-major for row vectors (p' = p M); read as column-major
// they are exactly the column-vector matrix GLM uses.
void SceneBuilder::transform(RequestReader& in) {
    std::vector<float> m = in.numbers(16, "a 4x4 matrix");
    in.finish();
    setTransform(in, glm::make_mat4(m.data()));
}

void SceneBuilder::concatTransform(RequestReader& in) {
    std::vector<float> m = in.numbers(16, "a 4x4 matrix");
    in.finish();
    setTransform(in, state().transform * glm::make_mat4(m.data()));
}

void SceneBuilder::setTransform(RequestReader& in, Mat4 const& transform) {
    // Each number is a valid float, yet products of large ones overflow; say where it happened.
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(transform[i][j]))
                in.fail(in.where(), "the current transform is no longer finite (the numbers overflow a float)");
    state().transform = transform;
}

void SceneBuilder::translate(RequestReader& in) {
    std::vector<float> v = in.numbers(3, "dx dy dz");
    in.finish();
    setTransform(in, glm::translate(state().transform, Vec3(v[0], v[1], v[2])));
}

void SceneBuilder::rotate(RequestReader& in) {
    std::vector<float> v = in.numbers(4, "angle dx dy dz");
    in.finish();
    Vec3 axis(v[1], v[2], v[3]);
    if (glm::length(axis) == 0.0f) in.fail(in.where(), "rotation axis is the zero vector");
    setTransform(in, glm::rotate(state().transform, glm::radians(v[0]), glm::normalize(axis)));
}

void SceneBuilder::scale(RequestReader& in) {
    std::vector<float> v = in.numbers(3, "sx sy sz");
    in.finish();
    if (v[0] == 0.0f || v[1] == 0.0f || v[2] == 0.0f)
        m_diagnostics.warn(in.where(), "Scale by zero collapses everything that follows");
    setTransform(in, glm::scale(state().transform, Vec3(v[0], v[1], v[2])));
}

void SceneBuilder::attribute(RequestReader& in) {
    std::string category = in.string("attribute name");
    ParamList params = in.params();
    if (category == "visibility") {
        Visibility& vis = state().visibility;
        vis.camera = params.getInt("camera", vis.camera) != 0;
        vis.indirect = params.getInt("indirect", vis.indirect) != 0;
        vis.transmission = params.getInt("transmission", vis.transmission) != 0;
    } else if (category == "identifier") {
        state().name = params.getString("name", state().name);
    } else {
        warnOnce("attribute " + category, in.where(), "Attribute \"" + category + "\" is not supported; skipped");
        return;
    }
    for (auto const& p : params.all())
        if (!p.used)
            warnOnce("attribute " + category + " " + p.name(), p.location,
                     "Attribute \"" + category + "\" \"" + p.name() + "\" is not supported; skipped");
}

void SceneBuilder::color(RequestReader& in) {
    std::vector<float> c = in.numbers(3, "red green blue");
    in.finish();
    state().color = Vec3(c[0], c[1], c[2]);
    state().colorSet = true;
}

void SceneBuilder::reverseOrientation(RequestReader& in) {
    in.finish();
    state().reverseOrientation = !state().reverseOrientation;
}

void SceneBuilder::orientation(RequestReader& in) {
    std::string value = in.string("orientation");
    in.finish();
    if (value == "outside" || value == "lh")
        state().reverseOrientation = false;
    else if (value == "inside" || value == "rh")
        state().reverseOrientation = true;
    else
        in.fail(in.where(), "orientation must be \"outside\", \"inside\", \"lh\" or \"rh\", not \"" + value + "\"");
}

// ------------------------------------------------------------------ materials and lights

void SceneBuilder::bxdf(RequestReader& in) {
    MaterialDesc material;
    material.plugin = in.string("Bxdf plugin name");
    material.handle = in.string("Bxdf handle");
    material.params = in.params();
    material.where = in.where();
    if (material.plugin.empty()) in.fail(in.where(), "the plugin name is empty");
    state().material = static_cast<int>(m_scene.materials.size());
    m_scene.materials.push_back(std::move(material));
}

int SceneBuilder::defaultMaterial() {
    // RenderMan shades surfaces without a Bxdf with the stock PxrDiffuse; the
    // legacy `Color` attribute, when set, is its colour.
    Vec3 c = state().color;
    bool colored = state().colorSet;
    std::string key = colored ? std::to_string(c.x) + " " + std::to_string(c.y) + " " + std::to_string(c.z) : "";
    auto found = m_defaultMaterials.find(key);
    if (found != m_defaultMaterials.end()) return found->second;
    MaterialDesc material;
    material.plugin = "PxrDiffuse";
    material.handle = colored ? "default material (Color " + key + ")" : "default material";
    if (colored) {
        Param color;
        color.decl.name = "diffuseColor";
        color.decl.type = ParamType::Color;
        color.floats = {c.x, c.y, c.z};
        material.params.add(color);
    }
    int index = static_cast<int>(m_scene.materials.size());
    m_scene.materials.push_back(std::move(material));
    m_defaultMaterials[key] = index;
    return index;
}

void SceneBuilder::light(RequestReader& in) {
    std::string type = in.string("light type");
    std::string handle = in.string("light handle");
    ParamList params = in.params();
    std::unique_ptr<Light> light = makeLight(type, params, state().transform, currentDirectory(), in.where(), m_diagnostics);
    if (!light) {
        warnOnce("light " + type, in.where(), "unsupported light type \"" + type + "\" skipped");
        return;
    }
    params.warnUnused(m_diagnostics, type + " \"" + handle + "\"");
    light->handle = handle;
    light->visibility = state().visibility;
    if (light->color.IsBlack()) {
        m_scene.dropped.push_back("light \"" + handle + "\" (" + type + ") has zero intensity");
        return;
    }
    m_scene.lights.push_back(std::move(light));
}

// ------------------------------------------------------------------ geometry

void SceneBuilder::addShape(std::unique_ptr<Shape> shape, SourceLocation const& where) {
    if (!m_inWorld) throw RibError(where, "geometry must come between WorldBegin and WorldEnd");
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(state().transform[i][j])) throw RibError(where, "the current transform is not finite");
    if (auto const* mesh = dynamic_cast<TriangleMesh const*>(shape.get()))
        for (Vec3 const& p : mesh->data().P)
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw RibError(where, std::string("a point of this ") + shape->kind() +
                                          " is not finite once transformed to world space (values near the float limit?)");
    shape->visibility = state().visibility;
    shape->name = state().name;
    shape->where = where;
    if (!shape->visibility.any()) {
        m_scene.dropped.push_back(std::string(shape->kind()) + " at " + where.str() + " is invisible to every ray type");
        return;
    }
    shape->material = state().material >= 0 ? state().material : defaultMaterial();
    m_scene.shapes.push_back(std::move(shape));
}

void SceneBuilder::sphere(RequestReader& in) {
    std::vector<float> v = in.numbers(4, "radius zmin zmax thetamax");
    in.params().warnUnused(m_diagnostics, "Sphere");
    if (!(v[0] > 0.0f)) in.fail(in.where(), "radius must be positive, got " + std::to_string(v[0]));
    addShape(std::make_unique<Sphere>(v[0], v[1], v[2], v[3], state().transform, state().reverseOrientation), in.where());
}

void SceneBuilder::cylinder(RequestReader& in) {
    std::vector<float> v = in.numbers(4, "radius zmin zmax thetamax");
    in.params().warnUnused(m_diagnostics, "Cylinder");
    if (!(v[0] > 0.0f)) in.fail(in.where(), "radius must be positive, got " + std::to_string(v[0]));
    addShape(std::make_unique<Cylinder>(v[0], v[1], v[2], v[3], state().transform, state().reverseOrientation), in.where());
}

void SceneBuilder::disk(RequestReader& in) {
    std::vector<float> v = in.numbers(3, "height radius thetamax");
    in.params().warnUnused(m_diagnostics, "Disk");
    if (!(v[1] > 0.0f)) in.fail(in.where(), "radius must be positive, got " + std::to_string(v[1]));
    addShape(std::make_unique<Disk>(v[0], v[1], v[2], state().transform, state().reverseOrientation), in.where());
}

namespace {
bool mirrors(Mat4 const& m) { return glm::determinant(Mat3(m)) < 0.0f; }

std::vector<Vec3> pointsOf(ParamList const& params, RequestReader& in) {
    std::vector<float> const* P = params.getFloats("P", ParamType::Point);
    if (!P || P->empty() || P->size() % 3 != 0) in.fail(in.where(), "needs a \"P\" parameter with control points");
    std::vector<Vec3> points;
    for (size_t i = 0; i + 2 < P->size(); i += 3) points.emplace_back((*P)[i], (*P)[i + 1], (*P)[i + 2]);
    return points;
}
}  // namespace

void SceneBuilder::polygon(RequestReader& in) {
    ParamList params = in.params();
    std::vector<float> const* P = params.getFloats("P", ParamType::Point);
    if (!P) in.fail(in.where(), "needs a \"P\" parameter with the vertex positions");
    int count = static_cast<int>(P->size() / 3);
    if (count < 3) in.fail(in.where(), "a polygon needs at least 3 vertices, got " + std::to_string(count));
    std::vector<int> indices(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) indices[static_cast<size_t>(i)] = i;
    MeshData mesh = buildPolygonMesh({1}, {count}, indices, params, state().transform, in.where(), m_diagnostics);
    params.find("Cs");  // per-vertex colour is read by no Bxdf yet; accepted quietly
    params.warnUnused(m_diagnostics, "Polygon");
    addShape(std::make_unique<TriangleMesh>(std::move(mesh), "Polygon", state().reverseOrientation), in.where());
}

void SceneBuilder::pointsPolygons(RequestReader& in) {
    std::vector<int> nverts = in.intArray("nvertices (vertex count per face)");
    std::vector<int> verts = in.intArray("vertices (point indices)");
    ParamList params = in.params();
    std::vector<int> loops(nverts.size(), 1);
    MeshData mesh = buildPolygonMesh(loops, nverts, verts, params, state().transform, in.where(), m_diagnostics);
    params.find("Cs");
    params.warnUnused(m_diagnostics, "PointsPolygons");
    addShape(std::make_unique<TriangleMesh>(std::move(mesh), "PointsPolygons", state().reverseOrientation), in.where());
}

void SceneBuilder::pointsGeneralPolygons(RequestReader& in) {
    std::vector<int> nloops = in.intArray("nloops (loop count per face)");
    std::vector<int> nverts = in.intArray("nvertices (vertex count per loop)");
    std::vector<int> verts = in.intArray("vertices (point indices)");
    ParamList params = in.params();
    MeshData mesh = buildPolygonMesh(nloops, nverts, verts, params, state().transform, in.where(), m_diagnostics);
    params.find("Cs");
    params.warnUnused(m_diagnostics, "PointsGeneralPolygons");
    addShape(std::make_unique<TriangleMesh>(std::move(mesh), "PointsGeneralPolygons", state().reverseOrientation),
             in.where());
}

void SceneBuilder::patch(RequestReader& in) {
    std::string type = in.string("patch type");
    ParamList params = in.params();
    std::vector<Vec3> points = pointsOf(params, in);
    params.warnUnused(m_diagnostics, "Patch");
    bool flip = state().reverseOrientation != mirrors(state().transform);
    MeshData mesh;
    if (type == "bilinear") {
        if (points.size() != 4) in.fail(in.where(), "a bilinear patch needs \"P\" with exactly 4 points");
        mesh = buildBilinearPatch({points[0], points[1], points[2], points[3]}, state().transform, flip);
    } else if (type == "bicubic") {
        if (points.size() != 16) in.fail(in.where(), "a bicubic patch needs \"P\" with exactly 16 points");
        mesh = buildBicubicPatchMesh(points, 4, false, 4, false, state().uBasis, state().vBasis, state().transform, flip,
                                     in.where());
    } else {
        in.fail(in.where(), "unknown patch type \"" + type + "\" (bilinear or bicubic)");
    }
    addShape(std::make_unique<TriangleMesh>(std::move(mesh), "Patch", false), in.where());
}

void SceneBuilder::geometry(RequestReader& in) {
    std::string type = in.string("geometry type");
    ParamList params = in.params();
    if (type != "teapot") {
        warnOnce("geometry " + type, in.where(), "Geometry \"" + type + "\" is not supported; skipped");
        return;
    }
    params.warnUnused(m_diagnostics, "Geometry \"teapot\"");
    bool flip = state().reverseOrientation != mirrors(state().transform);
    addShape(std::make_unique<TriangleMesh>(buildTeapot(state().transform, flip), "teapot", false), in.where());
}

void SceneBuilder::readArchive(RequestReader& in) {
    std::string name = in.string("archive file name");
    in.params().warnUnused(m_diagnostics, "ReadArchive");
    auto inlineArchive = m_inlineArchives.find(name);
    if (inlineArchive != m_inlineArchives.end()) {
        replay("archive \"" + name + "\"", inlineArchive->second, in.where());
        return;
    }
    std::vector<std::string> tried;
    std::vector<std::string> folders;
    if (fs::path(name).is_absolute()) {
        folders.push_back("");
    } else {
        folders.push_back(currentDirectory());
        folders.insert(folders.end(), m_archiveSearchPath.begin(), m_archiveSearchPath.end());
    }
    for (std::string const& folder : folders) {
        fs::path candidate = folder.empty() ? fs::path(name) : fs::path(folder) / name;
        tried.push_back(candidate.string());
        std::error_code error;  // a name the file system rejects (too long, ...) is simply not found
        if (fs::is_regular_file(candidate, error)) {
            readFile(candidate.string());
            return;
        }
    }
    std::string list;
    for (auto const& t : tried) list += "\n    " + t;
    in.fail(in.where(), "archive \"" + name + "\" not found; tried:" + list);
}

void SceneBuilder::cone(RequestReader& in) {
    std::vector<float> v = in.numbers(3, "height radius thetamax");
    in.params().warnUnused(m_diagnostics, "Cone");
    if (!(v[1] > 0.0f) || v[0] == 0.0f) in.fail(in.where(), "needs a positive radius and a non-zero height");
    addShape(std::make_unique<Cone>(v[0], v[1], v[2], state().transform, state().reverseOrientation), in.where());
}

void SceneBuilder::paraboloid(RequestReader& in) {
    std::vector<float> v = in.numbers(4, "rmax zmin zmax thetamax");
    in.params().warnUnused(m_diagnostics, "Paraboloid");
    if (!(v[0] > 0.0f) || !(std::max(v[1], v[2]) > 0.0f))
        in.fail(in.where(), "needs a positive rmax and zmax");
    addShape(std::make_unique<Paraboloid>(v[0], v[1], v[2], v[3], state().transform, state().reverseOrientation),
             in.where());
}

void SceneBuilder::hyperboloid(RequestReader& in) {
    std::vector<float> v = in.numbers(7, "point1 point2 thetamax");
    in.params().warnUnused(m_diagnostics, "Hyperboloid");
    if (v[2] == v[5]) {
        warnOnce("flat hyperboloid", in.where(), "Hyperboloid with both points at the same height is not supported; skipped");
        return;
    }
    addShape(std::make_unique<Hyperboloid>(Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5]), v[6], state().transform,
                                           state().reverseOrientation),
             in.where());
}

void SceneBuilder::torus(RequestReader& in) {
    std::vector<float> v = in.numbers(5, "majorrad minorrad phimin phimax thetamax");
    in.params().warnUnused(m_diagnostics, "Torus");
    if (!(v[0] > 0.0f) || !(v[1] > 0.0f)) in.fail(in.where(), "radii must be positive");
    bool flip = state().reverseOrientation != mirrors(state().transform);
    addShape(std::make_unique<TriangleMesh>(buildTorus(v[0], v[1], v[2], v[3], v[4], state().transform, flip), "Torus",
                                            false),
             in.where());
}

void SceneBuilder::basis(RequestReader& in) {
    SplineBasis bases[2];
    for (int k = 0; k < 2; ++k) {
        const char* what = k == 0 ? "u basis" : "v basis";
        if (in.nextIsString()) {
            std::string name = in.string(what);
            if (!SplineBasis::named(name, bases[k]))
                in.fail(in.where(), "unknown basis \"" + name + "\" (bezier, b-spline, catmull-rom, hermite, power)");
        } else {
            std::vector<float> m = in.numbers(16, what);
            for (int i = 0; i < 16; ++i) bases[k].matrix[i / 4][i % 4] = m[static_cast<size_t>(i)];
        }
        int step = in.integer(k == 0 ? "u step" : "v step");
        if (step < 1) in.fail(in.where(), "basis steps must be whole numbers of at least 1");
        bases[k].step = step;
    }
    in.finish();
    state().uBasis = bases[0];
    state().vBasis = bases[1];
}


void SceneBuilder::patchMesh(RequestReader& in) {
    std::string type = in.string("patch type");
    int nu = in.integer("nu");
    std::string uwrap = in.string("uwrap");
    int nv = in.integer("nv");
    std::string vwrap = in.string("vwrap");
    ParamList params = in.params();
    std::vector<Vec3> points = pointsOf(params, in);
    params.warnUnused(m_diagnostics, "PatchMesh");
    bool flip = state().reverseOrientation != mirrors(state().transform);
    MeshData mesh;
    if (type == "bicubic")
        mesh = buildBicubicPatchMesh(points, nu, uwrap == "periodic", nv, vwrap == "periodic", state().uBasis,
                                     state().vBasis, state().transform, flip, in.where());
    else if (type == "bilinear")
        mesh = buildBilinearPatchMesh(points, nu, uwrap == "periodic", nv, vwrap == "periodic", state().transform, flip,
                                      in.where());
    else
        in.fail(in.where(), "unknown patch type \"" + type + "\" (bilinear or bicubic)");
    addShape(std::make_unique<TriangleMesh>(std::move(mesh), "PatchMesh", false), in.where());
}

void SceneBuilder::objectBegin(RequestReader& in) {
    // The handle may be a string (RenderMan 19+) or a number (older RIBs).
    std::string handle = in.nextIsString() ? in.string("object handle") : std::to_string(in.number("object handle"));
    in.finish();
    startRecording(m_objects[handle], "ObjectEnd");
}

void SceneBuilder::objectInstance(RequestReader& in) {
    std::string handle = in.nextIsString() ? in.string("object handle") : std::to_string(in.number("object handle"));
    in.finish();
    auto found = m_objects.find(handle);
    if (found == m_objects.end()) in.fail(in.where(), "no object \"" + handle + "\" was defined with ObjectBegin");
    replay("object \"" + handle + "\"", found->second, in.where());
}

void SceneBuilder::archiveBegin(RequestReader& in) {
    std::string name = in.string("archive name");
    in.params();
    startRecording(m_inlineArchives[name], "ArchiveEnd");
}

void SceneBuilder::startRecording(Recording& slot, std::string const& end) {
    slot = std::make_shared<std::vector<RibRequest>>();
    m_recording = slot.get();
    m_recordingEnd = end;
}

void SceneBuilder::replay(std::string const& what, Recording requests, SourceLocation const& where) {
    if (!m_replaying.insert(what).second)
        throw RibError(where, what + " is used inside its own definition (directly or through another one)");
    m_replayedRequests += static_cast<long>(requests->size());
    if (m_replayedRequests > kMaxReplayedRequests)
        throw RibError(where, "instancing expands to more than " + std::to_string(kMaxReplayedRequests) +
                                  " requests (objects that instance others many times over?)");
    // An instance sees the graphics state in effect where it is used, and
    // leaves it as it found it.
    m_attributes.push_back(state());
    size_t depth = m_blocks.size();
    for (RibRequest const& request : *requests) handle(request);
    if (m_blocks.size() != depth) throw RibError(requests->back().where, "unbalanced blocks inside an object or archive");
    m_attributes.pop_back();
    m_replaying.erase(what);
}

void SceneBuilder::clipping(RequestReader& in) {
    // Ray tracing needs no near and far planes; accepted for compatibility.
    in.numbers(2, "near far");
    in.finish();
}

void SceneBuilder::sides(RequestReader& in) {
    // Every surface is shaded from the side it is seen from, so one- and
    // two-sided surfaces render alike here; accepted for compatibility.
    float sides = in.number("number of sides");
    in.finish();
    if (sides != 1.0f && sides != 2.0f) in.fail(in.where(), "Sides must be 1 or 2");
}

Scene loadScene(std::string const& path, Diagnostics& diagnostics) {
    Scene scene;
    SceneBuilder builder(scene, diagnostics);
    builder.readFile(path);
    return scene;
}

}  // namespace bxdflab
