#include "scene/SceneBuilder.h"

#include <algorithm>
#include <filesystem>

#include "core/Variables.h"
#include "parse/RequestNames.h"
#include "parse/RibCondition.h"
#include "parse/RibParser.h"
#include "parse/ZipMember.h"
#include "scene/PatternReach.h"

namespace bxdflab {
namespace fs = std::filesystem;

SceneBuilder::SceneBuilder(Scene& scene, Diagnostics& diagnostics, LoadOptions options)
    : m_scene(scene), m_diagnostics(diagnostics), m_options(options) {}

std::map<std::string, SceneBuilder::Handler> const& SceneBuilder::handlers() {
    static const std::map<std::string, Handler> table = {
        // Options, camera, frames.
        {"version", &SceneBuilder::ignore},
        {"IfBegin", &SceneBuilder::ifBegin},
        {"ElseIf", &SceneBuilder::elseIf},
        {"Else", &SceneBuilder::elseBranch},
        {"IfEnd", &SceneBuilder::ifEnd},
        {"Display", &SceneBuilder::display},
        {"Format", &SceneBuilder::format},
        {"Projection", &SceneBuilder::projection},
        {"Camera", &SceneBuilder::camera},
        {"RelativeDetail", &SceneBuilder::relativeDetail},
        {"DisplayChannel", &SceneBuilder::displayChannel},
        {"ScreenWindow", &SceneBuilder::screenWindow},
        {"FrameAspectRatio", &SceneBuilder::frameAspectRatio},
        {"PixelSamples", &SceneBuilder::pixelSamples},
        {"ColorSamples", &SceneBuilder::colorSamples},
        {"PixelVariance", &SceneBuilder::pixelVariance},
        {"PixelFilter", &SceneBuilder::pixelFilter},
        {"Hider", &SceneBuilder::hider},
        {"DepthOfField", &SceneBuilder::depthOfField},
        {"Imager", &SceneBuilder::imager},
        {"Exposure", &SceneBuilder::exposure},
        {"DisplayFilter", &SceneBuilder::displayFilter},
        {"SampleFilter", &SceneBuilder::sampleFilter},
        {"Integrator", &SceneBuilder::integrator},
        {"Option", &SceneBuilder::option},
        {"Declare", &SceneBuilder::declare},
        {"FrameBegin", &SceneBuilder::frameBegin},
        {"FrameEnd", &SceneBuilder::frameEnd},
        {"WorldBegin", &SceneBuilder::worldBegin},
        {"WorldEnd", &SceneBuilder::worldEnd},
        {"Clipping", &SceneBuilder::clipping},
        {"CropWindow", &SceneBuilder::cropWindow},
        {"Shutter", &SceneBuilder::shutter},
        {"ShadingRate", &SceneBuilder::shadingRate},
        {"ShadingInterpolation", &SceneBuilder::shadingInterpolation},
        {"GeometricApproximation", &SceneBuilder::geometricApproximation},
        {"Quantize", &SceneBuilder::quantize},
        {"ErrorHandler", &SceneBuilder::errorHandler},
        // The graphics state.
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
        {"Skew", &SceneBuilder::skew},
        {"CoordinateSystem", &SceneBuilder::coordinateSystem},
        {"ScopedCoordinateSystem", &SceneBuilder::scopedCoordinateSystem},
        {"CoordSysTransform", &SceneBuilder::coordSysTransform},
        {"MotionBegin", &SceneBuilder::motionBegin},
        {"MotionEnd", &SceneBuilder::motionEnd},
        {"Attribute", &SceneBuilder::attribute},
        {"Matte", &SceneBuilder::matte},
        {"GeometricRepresentation", &SceneBuilder::geometricRepresentation},
        {"SolidBegin", &SceneBuilder::solidBegin},
        {"SolidEnd", &SceneBuilder::solidEnd},
        {"Resource", &SceneBuilder::resource},
        {"ResourceBegin", &SceneBuilder::resourceBegin},
        {"ResourceEnd", &SceneBuilder::resourceEnd},
        {"Bound", &SceneBuilder::bound},
        {"Detail", &SceneBuilder::detail},
        {"DetailRange", &SceneBuilder::detailRange},
        {"Color", &SceneBuilder::color},
        {"Opacity", &SceneBuilder::opacity},
        {"ReverseOrientation", &SceneBuilder::reverseOrientation},
        {"Orientation", &SceneBuilder::orientation},
        {"Sides", &SceneBuilder::sides},
        {"Basis", &SceneBuilder::basis},
        {"TextureCoordinates", &SceneBuilder::textureCoordinates},
        // Shading and lights.
        {"Bxdf", &SceneBuilder::bxdf},
        {"Pattern", &SceneBuilder::pattern},
        {"Surface", &SceneBuilder::surface},
        {"MakeTexture", &SceneBuilder::makeTexture},
        {"MakeLatLongEnvironment", &SceneBuilder::makeLatLongEnvironment},
        {"Light", &SceneBuilder::light},
        {"LightSource", &SceneBuilder::lightSource},
        {"AreaLightSource", &SceneBuilder::areaLightSource},
        {"Illuminate", &SceneBuilder::illuminate},
        // Shapes.
        {"Sphere", &SceneBuilder::sphere},
        {"Cylinder", &SceneBuilder::cylinder},
        {"Disk", &SceneBuilder::disk},
        {"Cone", &SceneBuilder::cone},
        {"Paraboloid", &SceneBuilder::paraboloid},
        {"Hyperboloid", &SceneBuilder::hyperboloid},
        {"Torus", &SceneBuilder::torus},
        {"Polygon", &SceneBuilder::polygon},
        {"GeneralPolygon", &SceneBuilder::generalPolygon},
        {"PointsPolygons", &SceneBuilder::pointsPolygons},
        {"PointsGeneralPolygons", &SceneBuilder::pointsGeneralPolygons},
        {"Patch", &SceneBuilder::patch},
        {"PatchMesh", &SceneBuilder::patchMesh},
        {"Geometry", &SceneBuilder::geometry},
        {"SubdivisionMesh", &SceneBuilder::subdivisionMesh},
        {"HierarchicalSubdivisionMesh", &SceneBuilder::hierarchicalSubdivisionMesh},
        {"NuPatch", &SceneBuilder::nuPatch},
        {"TrimCurve", &SceneBuilder::trimCurve},
        {"Blobby", &SceneBuilder::blobby},
        {"Points", &SceneBuilder::points},
        {"Curves", &SceneBuilder::curves},
        // Instancing.
        {"ReadArchive", &SceneBuilder::readArchive},
        {"Procedural", &SceneBuilder::procedural},
        {"Procedural2", &SceneBuilder::procedural2},
        {"ObjectBegin", &SceneBuilder::objectBegin},
        {"ObjectInstance", &SceneBuilder::objectInstance},
        {"ArchiveBegin", &SceneBuilder::archiveBegin},
    };
    return table;
}

void SceneBuilder::readFile(std::string const& path) {
    bool const top = m_fileStack.empty();
    if (top) m_scene.file = path;
    if (static_cast<int>(m_fileStack.size()) >= kMaxArchiveDepth)
        throw RenderError("archives nested more than " + std::to_string(kMaxArchiveDepth) + " deep (at \"" + path + "\")");
    m_fileStack.push_back(path);
    parseRibFile(path, [this](RibRequest const& r) { handle(r); });
    m_fileStack.pop_back();
    if (!top) return;
    if (m_repeatedWarnings > 0)
        m_diagnostics.info(std::to_string(m_repeatedWarnings) + " more statement" + (m_repeatedWarnings > 1 ? "s" : "") +
                           " of the kinds warned about above " + (m_repeatedWarnings > 1 ? "were" : "was") + " skipped");
    if (m_inWorld) {
        // A world left open at the end of the file is still a frame to render.
        m_diagnostics.warn(path + ": WorldEnd missing at the end of the file");
        m_inWorld = false;
        finishFrame();
    }
    bool const onlyMakesTextures = m_framesDone == 0 && !m_scene.madeTextures.empty();
    if (onlyMakesTextures && m_sink) {
        // A texture-making step of a pipeline (RenderMan's txmake as RIB): the
        // program reading frames writes the textures instead.
        finishInput(path);
        return;
    }
    if (m_framesDone == 0)
        throw RenderError(path + ": there is no WorldBegin, so the file describes nothing to render" +
                          (onlyMakesTextures ? std::string(" (it only makes textures)")
                                             : " (a file of shapes alone is an archive, read from a scene with"
                                               " ReadArchive)"));
    if (m_options.frame >= 0 && !m_keptFrame && !m_sink)
        throw RenderError(path + ": there is no frame " + std::to_string(m_options.frame));
    finishInput(path);
}

void SceneBuilder::readText(std::string const& text, std::string const& fileName) {
    if (m_fileStack.empty()) m_scene.file = fileName;
    m_fileStack.push_back(fileName);
    parseRib(text, fileName, [this](RibRequest const& r) { handle(r); });
    m_fileStack.pop_back();
    if (!m_fileStack.empty()) return;
    if (m_inWorld) {
        // Text is often a world without its WorldEnd (tests, tools): complete it.
        m_inWorld = false;
        finishFrame();
    }
    finishInput(fileName);
}

void SceneBuilder::finishInput(std::string const& name) {
    m_programs.clear();  // the scene is read: RunProgram helpers end
    if (m_keptFrame) static_cast<SceneOptions&>(m_scene) = m_keptOptions;
    if (m_recording) m_diagnostics.warn(name + ": " + m_recordingEnd + " missing at the end of the file");
    if (!m_conditions.empty()) {
        m_diagnostics.warn(name + ": " + std::to_string(m_conditions.size()) +
                           " IfBegin left open at the end of the file");
        m_conditions.clear();
    }
    if (!m_blocks.empty())
        m_diagnostics.warn(name + ": " + std::to_string(m_blocks.size()) +
                           " AttributeBegin/TransformBegin left open at end of file");
}

std::string SceneBuilder::currentDirectory() const {
    if (m_fileStack.empty()) return ".";
    // A member of a zip file is beside the zip file.
    std::optional<ZipMemberName> zipped = splitZipMemberName(m_fileStack.back());
    fs::path parent = fs::path(zipped ? zipped->zipFile : m_fileStack.back()).parent_path();
    return parent.empty() ? "." : parent.string();
}

TextureLocator SceneBuilder::textures() const {
    TextureLocator locator = m_scene.textureLocator();
    std::string const here = currentDirectory();  // beside the file being read first
    if (here != "." && std::find(locator.folders.begin(), locator.folders.end(), here) == locator.folders.end())
        locator.folders.insert(locator.folders.begin(), here);
    return locator;
}

void SceneBuilder::warnOnce(std::string const& kind, SourceLocation const& where, std::string const& message) {
    if (firstOfKind(kind)) m_diagnostics.warn(where, message);
}

bool SceneBuilder::firstOfKind(std::string const& kind) {
    if (m_warnedKinds.insert(kind).second) return true;
    ++m_repeatedWarnings;
    return false;
}

void SceneBuilder::missingFile(SourceLocation const& where, std::string const& message) {
    if (m_options.strict) throw RibError(where, message);
    m_diagnostics.warn(where, message + " (rendering without it; --strict makes this an error)");
}

namespace {
/// Whether two requests' arguments are the same values (wherever they were written).
bool sameArguments(std::vector<RibValue> const& a, std::vector<RibValue> const& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](RibValue const& x, RibValue const& y) {
        return x.kind == y.kind && x.numbers == y.numbers && x.strings == y.strings;
    });
}
}  // namespace

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
    // A branch of conditional RIB that is not read: only its nesting counts.
    bool const conditional = request.name == "IfBegin" || request.name == "ElseIf" || request.name == "Else" ||
                             request.name == "IfEnd";
    if (!conditional && !m_conditions.empty() && !m_conditions.back().reading) return;
    // A motion block holds one request per time. Transforms and shapes are read at each time
    // (and put together at MotionEnd); anything else keeps its first time's value. Requests that
    // one of them reads in turn (an instance's) belong to it, not to the block.
    if (m_motion && !m_motion->dispatching && request.name != "MotionEnd") {
        MotionBlock& block = *m_motion;
        // A block or frame boundary cannot be one time of a motion: its MotionEnd is missing.
        static std::set<std::string> const boundaries = {"WorldBegin",     "WorldEnd",      "FrameBegin",
                                                         "FrameEnd",       "AttributeBegin", "AttributeEnd",
                                                         "TransformBegin", "TransformEnd",  "ObjectBegin",
                                                         "ObjectEnd"};
        if (boundaries.count(request.name))
            throw RibError(request.where, request.name + " inside the motion block at " + block.where.str() +
                                              " (is its MotionEnd missing?): a motion block holds one request for "
                                              "each of its times");
        int const time = block.read++;
        if (time == 0) {
            block.request = request.name;
            block.first = request.args;
        }
        if (time > 0 && (request.name != block.request || time >= static_cast<int>(block.times.size()))) {
            warnOnce("motion block requests", request.where,
                     request.name + " in the motion block at " + block.where.str() + " is not another time of its " +
                         block.request + " (a motion block holds one request, repeated once for each of its " +
                         "times): ignored");
            return;
        }
        if (time > 0 && !block.captured()) return;  // an attribute: its first value holds
        if (time > 0) block.changes = block.changes || !sameArguments(request.args, block.first);
        block.current = time;
        block.dispatching = true;
        block.shapes.emplace_back();
        dispatch(request);
        if (m_motion) {
            m_motion->current = -1;
            m_motion->dispatching = false;
        }
        return;
    }
    dispatch(request);
}

void SceneBuilder::dispatch(RibRequest const& request) {
    // The camera and image are fixed at WorldBegin (RenderMan reports these as
    // misplaced). A first Display after it only names the file, as older test
    // files expect, and is kept.
    bool const firstDisplay = request.name == "Display" && !m_scene.display.where.known();
    if (m_inWorld && isCameraOption(request.name) && !firstDisplay) {
        warnOnce("option in world " + request.name, request.where,
                 request.name + " inside a world block is ignored: the camera and image are set before WorldBegin");
        return;
    }
    auto found = handlers().find(request.name);
    if (found == handlers().end()) {
        refuseIfPbrt(request);
        warnOnce("request " + request.name, request.where, unknownRequestMessage(request.name));
        if (!isRibRequest(request.name)) {
            std::string const meant = likelyRibRequest(request.name);
            if (meant == "AttributeBegin" || meant == "TransformBegin")
                m_skippedBegins.push_back({meant == "AttributeBegin" ? Block::Attribute : Block::Transform,
                                           m_blocks.size(), request.name, request.where, state()});
        }
        return;
    }
    RequestReader reader(request, m_declarations, &m_diagnostics);
    (this->*found->second)(reader);
}

void SceneBuilder::ignore(RequestReader&) {}

bool SceneBuilder::isCameraOption(std::string const& name) {
    return name == "Display" || name == "Format" || name == "Projection" || name == "Camera" ||
           name == "DisplayChannel" || name == "ScreenWindow" ||
           name == "FrameAspectRatio" || name == "PixelSamples" || name == "PixelFilter" || name == "Hider" ||
           name == "Integrator";
}

bool SceneBuilder::closesSkippedBegin(Block block, SourceLocation const& where, std::string const& end) {
    // RenderMan reports an unmatched End and reads on. Here an End is let pass
    // only when the cause is plain: it closes a Begin misspelt at this depth.
    while (!m_skippedBegins.empty() && m_skippedBegins.back().depth > m_blocks.size()) m_skippedBegins.pop_back();
    if (m_skippedBegins.empty()) return false;
    SkippedBegin const& skipped = m_skippedBegins.back();
    if (skipped.block != block || skipped.depth != m_blocks.size()) return false;
    std::string const meant = block == Block::Attribute ? "AttributeBegin" : "TransformBegin";
    m_diagnostics.warn(where, end + " closes the " + skipped.word + " at " + skipped.where.str() +
                                  ", which is no request: read as the " + meant +
                                  " it was meant to be, so the state it saved comes back");
    // As the matching End would: an attribute block restores everything, a
    // transform block only the transform.
    if (block == Block::Attribute) {
        state() = skipped.saved;
    } else {
        state().transform = skipped.saved.transform;
    }
    m_skippedBegins.pop_back();
    return true;
}

void SceneBuilder::refuseIfPbrt(RibRequest const& request) {
    // One pbrt word may be a stray one in a RIB file; two different ones make a
    // pbrt scene, which would otherwise stop later at some puzzling error.
    if (!isPbrtDirective(request.name)) return;
    if (m_pbrtDirective.word.empty()) {
        m_pbrtDirective = {request.name, request.where};
    } else if (m_pbrtDirective.word != request.name) {
        throw RibError(request.where, "this looks like a pbrt scene file, not a RIB file: " + m_pbrtDirective.word +
                                          " (at " + m_pbrtDirective.where.str() + ") and " + request.name +
                                          " are pbrt directives that RIB does not have, and BxdfLab reads RIB only");
    }
}

std::string SceneBuilder::unknownRequestMessage(std::string const& name) {
    // What a skipped shading request takes out of the image, for the requests scenes use most.
    static std::map<std::string, std::string> const lost = {
        {"Displace", "displacement is not rendered, so surfaces keep their own shape"},
        {"Displacement", "displacement is not rendered, so surfaces keep their own shape"},
        {"Atmosphere", "volumes are not rendered, so light crosses the space between surfaces unchanged"},
        {"Interior", "volumes are not rendered, so light crosses the space between surfaces unchanged"},
        {"Exterior", "volumes are not rendered, so light crosses the space between surfaces unchanged"},
        {"Shader", "co-shaders are not run, so the surfaces that call them render without what they add"},
        {"VolumePixelSamples", "it sets how finely volumes are sampled, and volumes are not rendered"},
    };
    if (auto const found = lost.find(name); found != lost.end())
        return "unsupported request " + name + " skipped: " + found->second;
    if (isRibRequest(name)) return "unsupported request " + name + " skipped";
    if (isPbrtDirective(name)) return name + " is not a RIB request but a directive of pbrt's scene format; skipped";
    // Not a RIB request at all: usually a slip of the keyboard, which RIB
    // (case-sensitive) does not forgive.
    std::string message = name + " is not a RIB request; skipped";
    std::string const meant = likelyRibRequest(name);
    if (!meant.empty()) message += " (did you mean " + meant + "?)";
    return message;
}

void SceneBuilder::ifBegin(RequestReader& in) {
    std::string const condition = in.string("condition");
    in.finish();
    bool const enclosingRead = m_conditions.empty() || m_conditions.back().reading;
    // A skipped part's conditions are not evaluated: only its nesting counts.
    bool const holds = enclosingRead && conditionHolds(condition, in.where());
    m_conditions.push_back({enclosingRead, holds, holds, false});
}

void SceneBuilder::elseIf(RequestReader& in) {
    std::string const condition = in.string("condition");
    in.finish();
    if (m_conditions.empty()) throw RibError(in.where(), "ElseIf without an IfBegin");
    ConditionBlock& block = m_conditions.back();
    if (block.elseSeen)
        warnOnce("ElseIf after Else", in.where(), "ElseIf after Else: its branch is never read");
    block.reading =
        block.enclosingRead && !block.branchTaken && !block.elseSeen && conditionHolds(condition, in.where());
    block.branchTaken = block.branchTaken || block.reading;
}

void SceneBuilder::elseBranch(RequestReader& in) {
    in.skipRemaining();  // Else takes nothing; a stray argument is not worth stopping a file for
    if (m_conditions.empty()) throw RibError(in.where(), "Else without an IfBegin");
    ConditionBlock& block = m_conditions.back();
    if (block.elseSeen)
        warnOnce("second Else", in.where(), "a second Else in one IfBegin block: its branch is never read");
    block.reading = block.enclosingRead && !block.branchTaken && !block.elseSeen;
    block.branchTaken = true;
    block.elseSeen = true;
}

void SceneBuilder::ifEnd(RequestReader& in) {
    in.finish();
    if (m_conditions.empty()) throw RibError(in.where(), "IfEnd without an IfBegin");
    m_conditions.pop_back();
}

bool SceneBuilder::conditionHolds(std::string const& condition, SourceLocation const& where) {
    try {
        return evaluateCondition(condition, [this](std::string const& name) { return variable(name); });
    } catch (ConditionError const& e) {
        warnOnce("unreadable condition " + condition, where,
                 "IfBegin/ElseIf \"" + condition + "\": " + e.message + " (at character " +
                     std::to_string(e.offset + 1) + "); the condition is taken to hold");
        return true;
    }
}

std::optional<std::string> SceneBuilder::variable(std::string const& name) const {
    bool const userClass = name.rfind("user:", 0) == 0;
    std::string const bare = userClass ? name.substr(5) : name;
    if (userClass) {
        Attributes const& attributes = m_attributes.back();
        if (auto found = attributes.user.find(bare); found != attributes.user.end()) return found->second;
    }
    if (auto found = m_userOptions.find(bare); found != m_userOptions.end()) return found->second;
    if (userClass) return std::nullopt;
    if (name == "Frame" && m_frameNumber >= 0) return std::to_string(m_frameNumber);
    return environmentVariable(name);
}

std::string SceneBuilder::expanded(std::string const& text) const {
    return expandVariables(text, [this](std::string const& name) { return variable(name); });
}

void SceneBuilder::finishFrame() {
    ++m_framesDone;
    if (m_skipWorld) return;  // read, not built
    m_scene.frame = m_frameNumber;
    // A texture a used stock image pattern names and that is not there, said with its RIB line
    // (the texture service, which does not know the line, then stays quiet about it).
    static std::map<std::string, std::string> const imagePatterns = {
        {"PxrTexture", "its lookups return missingColor"},
        {"PxrNormalMap", "the normal is left as it is"},
        {"PxrBump", "the normal is left as it is"},
    };
    std::vector<char> const reached = patternsReached(m_scene.materials, m_scene.patterns);
    for (size_t i = 0; i < reached.size(); ++i) {
        PatternDesc const& node = m_scene.patterns[i];
        auto const image = imagePatterns.find(node.plugin);
        if (!reached[i] || image == imagePatterns.end()) continue;
        for (Param const& p : node.params.all())
            if (p.name() == "filename" && !p.decl.reference && !p.strings.empty())
                checkTexture(p.strings[0], p.location, "Pattern \"" + node.plugin + "\" \"" + node.handle + "\"",
                             image->second);
    }
    std::map<std::string, std::string> oslShaders;  // plugin name -> its OSL shader file, looked for once
    for (size_t i = 0; i < reached.size(); ++i) {
        if (!reached[i]) continue;
        PatternDesc& node = m_scene.patterns[i];
        auto [known, firstTime] = oslShaders.try_emplace(node.plugin);
        if (firstTime) known->second = oslShaderNamed(node.plugin);
        node.oslShader = known->second;
    }
    // A file lit by classic light shaders and naming no integrator was written for RenderMan before
    // RIS, whose surface shaders gathered those lights: PxrDirectLighting renders it that way, where
    // RIS's PxrDefault would light it from the camera and leave its lights unused. Its shapes given
    // no shader were PRMan's defaultsurface then.
    bool const classicLit = !m_scene.integrator.given && m_firstClassicLight && !m_scene.lights.empty();
    if (classicLit) shadeUnshadedAsClassic();
    // The classic shaders' ambient term sums every ambientlight of the world, wherever it was given.
    for (MaterialDesc& material : m_scene.materials)
        if (material.plugin == "ClassicSurface")
            material.params.add(colorParam("ambient", m_ambient));
    resolvePortals();
    if (m_shapesOutsideDetail > 0)
        m_scene.dropped.push_back(
            std::to_string(m_shapesOutsideDetail) +
            (m_shapesOutsideDetail == 1 ? " shape is a representation" : " shapes are representations") +
            " that DetailRange does not draw at its model's detail (level of detail)");
    if (classicLit) {
        m_scene.integrator.name = "PxrDirectLighting";
        m_scene.integrator.where = *m_firstClassicLight;
        // Said for the first frame only: the frames of one file are lit alike.
        if (m_warnedKinds.insert("note: classic lighting").second)
            m_diagnostics.info(m_firstClassicLight->str() +
                               ": the scene names no Integrator and is lit by classic light shaders, so it renders "
                               "with PxrDirectLighting and its lights, as RenderMan before RIS did (Integrator "
                               "\"PxrDefault\" \"d\" before WorldBegin lights it from the camera, as RIS does)");
    }
    // Illuminate: a light off for every shape lights nothing and is dropped; one on
    // for some shapes and off for others lights only the first (linkLights). A
    // classic light is off, too, for the shapes before it and after the attribute
    // block that gave it ended.
    std::vector<std::unique_ptr<Light>> kept;
    for (auto& light : m_scene.lights) {
        auto found = m_lightUse.find(light->handle);
        if (found == m_lightUse.end()) {
            kept.push_back(std::move(light));
            continue;
        }
        LightUse const& use = found->second;
        int off = use.shapesOff + use.shapesBefore;
        std::string why = use.listed ? "not on the light list of" : "turned off with Illuminate for";
        std::string which = use.listed ? " (before its LightSource, after the attribute block that gave it, or where "
                                         "Illuminate turned it off)"
                                       : "";
        if (use.shapesOn == 0 && (off > 0 || use.illuminated)) {
            std::string what = "light \"" + light->handle + "\" is " + why + " every shape" + which;
            m_scene.dropped.push_back(what);
            // Illuminate says so in so many words; a light list that ends before any shape may surprise.
            if (use.listed) warnOnce("light list", use.where, what + ", so it lights nothing, as in RenderMan");
            continue;
        }
        kept.push_back(std::move(light));
    }
    m_scene.lights = std::move(kept);
    linkLights();
    if (!m_sink) {
        m_keptFrame = true;  // the frame stays in the scene; later worlds are read without being built
        m_keptOptions = m_scene;
        return;
    }
    m_sink(m_scene);
    // Ready for the next world: the options stay, the world goes.
    m_scene.materials.clear();
    m_scene.patterns.clear();
    m_patternHandles.clear();
    m_scene.shapes.clear();
    m_scene.primvarNames.clear();
    m_scene.lights.clear();
    m_scene.lightLinks.clear();
    m_scene.dropped.clear();
    m_defaultMaterials.clear();
    m_unshaded.clear();
    m_emissiveMaterials.clear();
    m_lightHandles.clear();
    for (auto& a : m_attributes) a.material = -1;
    for (auto& f : m_frames)
        for (auto& a : f.attributes) a.material = -1;
}

void SceneBuilder::linkLights() {
    // Each distinct set of lights that are off becomes one entry of lightLinks; a shape every
    // light lights needs none, which keeps the common case (no Illuminate) free.
    std::vector<int> linkOf(m_lightsOff.size(), -1);
    for (size_t key = 0; key < m_lightsOff.size(); ++key) {
        LightsOff const& off = m_lightsOff[key];
        std::vector<bool> lit(m_scene.lights.size(), true);
        bool someOff = false;
        for (size_t l = 0; l < lit.size(); ++l) {
            Light const& light = *m_scene.lights[l];
            auto use = m_lightUse.find(light.handle);
            bool const listed = use != m_lightUse.end() && use->second.listed;
            bool const givenLater = listed && use->second.listedOrder >= off.listedBefore;
            bool const turnedOff = std::binary_search(off.handles.begin(), off.handles.end(), light.handle);
            // A "lighting" subset names lights by handle or by group.
            auto named = [&light](std::vector<std::string> const& names) {
                return std::any_of(names.begin(), names.end(), [&light](std::string const& name) {
                    return name == light.handle ||
                           std::find(light.groups.begin(), light.groups.end(), name) != light.groups.end();
                });
            };
            bool const outsideSubset = (!off.subset.empty() && !named(off.subset)) || named(off.exclude);
            if (givenLater || turnedOff || outsideSubset) {
                lit[l] = false;
                someOff = true;
            }
        }
        if (!someOff) continue;
        linkOf[key] = static_cast<int>(m_scene.lightLinks.size());
        m_scene.lightLinks.push_back(std::move(lit));
    }
    for (auto& shape : m_scene.shapes)
        if (shape->lightLink >= 0) shape->lightLink = linkOf[static_cast<size_t>(shape->lightLink)];
}

Scene loadScene(std::string const& path, Diagnostics& diagnostics, LoadOptions options) {
    Scene scene;
    SceneBuilder builder(scene, diagnostics, options);
    builder.readFile(path);
    return scene;
}

}  // namespace bxdflab
