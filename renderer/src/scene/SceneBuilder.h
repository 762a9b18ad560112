// Interprets RIB requests: keeps the graphics state (transform and attribute
// stacks, frames, named coordinate systems) and fills a Scene with the
// camera, materials, lights and shapes. The requests are handled by family,
// one file each under scene/requests/: options and frames, the graphics
// state, shading (Bxdfs, patterns, classic shaders, lights), shapes, and
// instancing (objects and archives).
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "core/Diagnostics.h"
#include "parse/ParamList.h"
#include "parse/RibRequest.h"
#include "scene/Motion.h"
#include "scene/ProceduralProgram.h"
#include "scene/ShaderSource.h"
#include "scene/Scene.h"
#include "scene/shapes/MeshBuilders.h"

namespace bxdflab {

struct LoadOptions {
    bool strict = false;  ///< a missing archive, texture or sky image is an error (else a warning, as in RenderMan)
    int frame = -1;       ///< render only the frame with this FrameBegin number (-1: every frame)
    /// Procedural "RunProgram" runs the program it names. A scene that runs programs is code, not data,
    /// so it is off unless the user asks for it.
    bool runPrograms = false;
};

/// Receives each frame as soon as its world is complete (at WorldEnd).
using FrameSink = std::function<void(Scene& frame)>;

class SceneBuilder {
public:
    SceneBuilder(Scene& scene, Diagnostics& diagnostics, LoadOptions options = {});

    /// Frames go to `sink` one by one, each scene emptied of its world after;
    /// without a sink the first frame (or the one asked for) stays in the scene.
    void setFrameSink(FrameSink sink) { m_sink = std::move(sink); }
    /// Reads a RIB file (and every archive it includes) into the scene.
    void readFile(std::string const& path);
    /// Reads RIB text; `fileName` is used in messages and to resolve relative paths.
    /// A world left open at the end is complete (no WorldEnd needed); text
    /// without a world (options alone) is fine too.
    void readText(std::string const& text, std::string const& fileName);

private:
    static constexpr int kMaxArchiveDepth = 32;  ///< archives and procedurals read inside one another

    /// What AttributeBegin saves and AttributeEnd restores.
    struct Attributes {
        Mat4 transform{1.0f};  ///< where the transform is when the shutter opens
        /// A transform that moves over time (a motion block's, and what was concatenated after it);
        /// null while it holds still.
        std::shared_ptr<TransformPath const> motion;
        int material = -1;
        Visibility visibility;
        RixTraceDepth traceDepth;
        std::string name;
        Vec3 color{1.0f};
        Vec3 opacity{1.0f};
        bool reverseOrientation = false;
        bool twoSided = true;  ///< Sides 2 (RIB's default); Sides 1 hides backs from the camera
        /// BMRT's Attribute "light" "shadows" "on": classic lights given from here on cast
        /// ray-traced shadows (without it, or a shadow map, they cast none).
        bool classicLightShadows = false;
        bool colorSet = false;
        bool volume = false;  ///< the Bxdf in effect is a volume's (PxrVolume): its shapes are not rendered
        /// Detail: the raster area (pixels) the current bound covers, times RelativeDetail (-1: none given).
        float detail = -1.0f;
        /// DetailRange: the shapes that follow are one representation of a model, not the one for its detail.
        bool outsideDetailRange = false;
        std::set<std::string> lightsOff;  ///< handles turned off with Illuminate for the shapes that follow
        /// The classic light list: LightSource lights on for the shapes that follow. It is an
        /// attribute, so a light given inside a block is off after the block ends.
        std::set<std::string> lightList;
        /// Attribute "lighting" "subset" and "excludesubset": the lights (by handle or group) that light
        /// the shapes that follow, when not empty, and those that do not. "grouping" "membership": the
        /// groups a light given here belongs to.
        std::vector<std::string> lightingSubset, lightingExclude, membership;
        bool lightMute = false;  ///< Attribute "lighting" "mute": a light given here emits nothing
        bool textureCoordinatesSet = false;
        std::array<float, 8> textureCoordinates{{0, 0, 1, 0, 0, 1, 1, 1}};
        SplineBasis uBasis = SplineBasis::bezier(), vBasis = SplineBasis::bezier();
        /// TrimCurve: the loops that trim the NuPatches that follow (null: none), and
        /// Attribute "trimcurve" "sense": whether they keep the outside of the loops.
        std::shared_ptr<TrimLoops const> trimLoops;
        bool trimKeepsOutside = false;
        std::map<std::string, Mat4> scopedSpaces;  ///< ScopedCoordinateSystem
        std::map<std::string, std::string> user;   ///< Attribute "user" values, which conditions read
        /// A classic Surface shader in effect (when no Bxdf is): its name and parameters.
        std::shared_ptr<MaterialDesc> surface;
        /// The colour that surface takes in place of Color, when its source never reads Cs.
        std::optional<Vec3> surfaceOwnColour;
        /// An AreaLightSource (or PxrMeshLight) in effect: the shapes that follow emit its light.
        std::shared_ptr<AreaLightDesc> areaLight;
    };
    /// A light defined before WorldBegin: placed in camera space, made at each WorldBegin.
    struct CameraLight {
        std::string request, type, handle;
        ParamList params;
        Mat4 toCamera;
        SourceLocation where;
    };
    enum class Block { Attribute, Transform };
    /// An open MotionBegin block: one request for each of its times, read as the transform or the
    /// shapes it makes at that time, and put together at MotionEnd.
    struct MotionBlock {
        std::vector<float> times;
        SourceLocation where;
        std::string request;  ///< the request of the first time (the others must repeat it)
        std::vector<RibValue> first;  ///< its arguments
        bool changes = false;         ///< some time's arguments differ from the first's (else nothing moves)
        int read = 0;         ///< how many requests have been read
        int current = -1;     ///< which time the request being read is for
        bool dispatching = false;  ///< a request of the block is being read
        struct Move {
            Mat4 matrix;
            bool absolute;  ///< Transform or Identity: the whole transform, not a change of it
        };
        std::vector<Move> moves;  ///< a transform request's, per time
        struct Made {
            std::unique_ptr<Shape> shape;
            SourceLocation where;
            PrimvarSet constants;
        };
        std::vector<std::vector<Made>> shapes;  ///< a shape request's shapes, per time
        bool madeShapes() const {
            for (auto const& made : shapes)
                if (!made.empty()) return true;
            return false;
        }
        /// Whether the block's request is one read at every time (a transform or a shape).
        bool captured() const { return !moves.empty() || madeShapes(); }
    };

    void handle(RibRequest const& request);
    /// Reads one request with its handler (handle() has dealt with recording, conditions and motion).
    void dispatch(RibRequest const& request);
    using Handler = void (SceneBuilder::*)(RequestReader&);
    static std::map<std::string, Handler> const& handlers();

    // Options, camera and frames (scene/requests/OptionRequests.cpp).
    void display(RequestReader& in);
    void format(RequestReader& in);
    /// Why a Format resolution cannot be rendered, or "" when it can.
    static std::string resolutionProblem(float xres, float yres);
    void setFormat(float xres, float yres, float pixelAspect);
    void projection(RequestReader& in);
    void camera(RequestReader& in);
    void relativeDetail(RequestReader& in);
    void displayChannel(RequestReader& in);
    /// At WorldBegin: the camera the image is seen from, the one its Display names or the current one.
    void chooseCamera();
    void screenWindow(RequestReader& in);
    void frameAspectRatio(RequestReader& in);
    void setFrameAspectRatio(float ratio);
    /// Clipping (the request, or Option "Ri" "Clipping"): the near and far planes of camera rays.
    void setClipping(std::vector<float> const& planes, SourceLocation const& where, std::string const& what);
    void setScreenWindow(std::vector<float> const& window);
    void pixelSamples(RequestReader& in);
    void colorSamples(RequestReader& in);
    void pixelFilter(RequestReader& in);
    /// PixelFilter's name and widths, checked (an unknown name keeps the filter as it was, with a warning).
    void setPixelFilter(std::string const& name, float xwidth, float ywidth, SourceLocation const& where);
    void hider(RequestReader& in);
    void pixelVariance(RequestReader& in);
    void errorHandler(RequestReader& in);
    void imager(RequestReader& in);
    void depthOfField(RequestReader& in);
    /// The camera's thin lens; a located error for numbers that make none.
    void setDepthOfField(float fStop, float focalLength, float focalDistance, SourceLocation const& where);
    void exposure(RequestReader& in);
    /// Exposure's gain and gamma, checked.
    void setExposure(float gain, float gamma, SourceLocation const& where);
    /// What the image's Display says of its own filter and exposure (RenderMan 21 and later
    /// write them there: "string filter", "float[2] filterwidth", "float[2] exposure").
    void displayFilterAndExposure(ParamList const& params);
    void displayFilter(RequestReader& in);
    void sampleFilter(RequestReader& in);
    /// DisplayFilter and SampleFilter: RenderMan's background filter of each, others skipped with a warning.
    /// `what` is how messages name the request ("display filter").
    void backgroundFilter(RequestReader& in, std::string const& request, std::string const& what,
                          std::string const& background);
    void integrator(RequestReader& in);
    void option(RequestReader& in);
    /// Option "Ri": the camera and image requests as RenderMan 21+ writes them.
    void riOptions(ParamList const& params, SourceLocation const& where);
    void declare(RequestReader& in);
    void frameBegin(RequestReader& in);
    void frameEnd(RequestReader& in);
    void worldBegin(RequestReader& in);
    void worldEnd(RequestReader& in);
    void clipping(RequestReader& in);
    void cropWindow(RequestReader& in);
    void shutter(RequestReader& in);
    void shadingRate(RequestReader& in);
    void shadingInterpolation(RequestReader& in);
    void geometricApproximation(RequestReader& in);
    void quantize(RequestReader& in);
    /// A crop window (xmin xmax ymin ymax): the whole image is accepted, a part of it warned about.
    void checkCropWindow(std::vector<float> const& window, SourceLocation const& where, std::string const& what);
    void ignore(RequestReader& in);
    /// The warning for a request the table does not handle: unsupported, or
    /// no request at all (with the one it was likely meant to be).
    static std::string unknownRequestMessage(std::string const& name);
    /// Requests that set the camera or the image, which a world block cannot change.
    static bool isCameraOption(std::string const& name);
    // Conditional RIB (IfBegin / ElseIf / Else / IfEnd): the first branch whose
    // condition holds is read, the others skipped.
    void ifBegin(RequestReader& in);
    void elseIf(RequestReader& in);
    void elseBranch(RequestReader& in);
    void ifEnd(RequestReader& in);
    /// Whether an IfBegin's or ElseIf's condition holds. One that cannot be read
    /// is warned about and taken to hold (the first branch is read, as before conditions were evaluated).
    bool conditionHolds(std::string const& condition, SourceLocation const& where);
    /// The value of a variable a condition or a search path names: "user:NAME" is
    /// Attribute "user" NAME, else Option "user" NAME; a bare NAME is Option "user"
    /// NAME, else the environment variable; "Frame" is the frame number.
    std::optional<std::string> variable(std::string const& name) const;
    /// `text` with the variables it names ("${RMSPROJ}/rib") replaced by their values (see variable()).
    std::string expanded(std::string const& text) const;
    // The graphics state (scene/requests/StateRequests.cpp).
    void detail(RequestReader& in);
    void detailRange(RequestReader& in);
    /// The raster area (pixels) of the bounding rectangle of where the box `bound` (xmin xmax ymin ymax
    /// zmin zmax, current space) lands on the image; infinite when it reaches the eye.
    float rasterArea(std::vector<float> const& bound);
    void attributeBegin(RequestReader& in);
    void attributeEnd(RequestReader& in);
    void transformBegin(RequestReader& in);
    void transformEnd(RequestReader& in);
    /// Opens an attribute or transform block: the state is saved to restore at its end.
    void beginBlock(RequestReader& in, Block block);
    /// Closes the innermost block, which must be of this kind: false when the end
    /// closes a begin that was skipped (nothing to restore).
    bool endBlock(RequestReader& in, Block block);
    void identity(RequestReader& in);
    void transform(RequestReader& in);
    void concatTransform(RequestReader& in);
    void translate(RequestReader& in);
    void rotate(RequestReader& in);
    void scale(RequestReader& in);
    void skew(RequestReader& in);
    void bound(RequestReader& in);
    /// Makes `transform` current (Transform, Identity: a transform that holds still), or fails at
    /// the request if it overflowed. Inside a motion block, keeps it for its time instead.
    void setTransform(RequestReader& in, Mat4 const& transform);
    /// Multiplies the current transform by `change` (Translate, Rotate, ...), moving or not.
    void concatenate(RequestReader& in, Mat4 const& change);
    /// MotionEnd: the block's transforms become a moving transform, its shapes one moving shape.
    void finishMotionTransform(MotionBlock& block, RequestReader& in);
    void finishMotionShapes(MotionBlock& block, SourceLocation const& where);
    void setShutter(float open, float close, SourceLocation const& where);
    void setPixelVariance(float variance, SourceLocation const& where);
    /// Hider's (or Option "hider"'s) maxsamples, minsamples and minextrasamples.
    void hiderSampleCounts(ParamList const& params, std::string const& owner);
    /// Lights are placed once: one under a moving transform is warned about.
    void warnIfLightMoves(SourceLocation const& where);
    void coordinateSystem(RequestReader& in);
    void scopedCoordinateSystem(RequestReader& in);
    void coordSysTransform(RequestReader& in);
    void motionBegin(RequestReader& in);
    void motionEnd(RequestReader& in);
    void attribute(RequestReader& in);
    void color(RequestReader& in);
    void opacity(RequestReader& in);
    void reverseOrientation(RequestReader& in);
    void orientation(RequestReader& in);
    /// Orientation's value ("outside", "inside", "lh", "rh"); false for any other.
    bool setOrientation(std::string const& value);
    /// Attribute "Ri": the state requests as RenderMan 21+ writes them.
    void riAttributes(ParamList const& params);
    /// Attribute "trace" "maxdiffusedepth" or "maxspeculardepth", if given, into `limit`
    /// (a negative value is warned about and leaves it as it was).
    void traceDepthLimit(ParamList const& params, std::string const& name, int& limit);
    void sides(RequestReader& in);
    void matte(RequestReader& in);
    void geometricRepresentation(RequestReader& in);
    void solidBegin(RequestReader& in);
    void solidEnd(RequestReader& in);
    void resourceBegin(RequestReader& in);
    void resourceEnd(RequestReader& in);
    void resource(RequestReader& in);
    void basis(RequestReader& in);
    void textureCoordinates(RequestReader& in);
    // Shading: Bxdfs, classic shaders, lights (scene/requests/ShadingRequests.cpp).
    void bxdf(RequestReader& in);
    void pattern(RequestReader& in);
    /// The connections of a parameter list's "reference" parameters, to the
    /// patterns declared so far (a located warning, and no connection, for a handle not declared before).
    std::map<std::string, Connection> connectionsOf(ParamList const& params, std::string const& owner);
    /// Gives a classic shader's texture map to `shader` through a pattern node that reads it.
    void classicTexture(std::string const& file, SourceLocation const& where, MaterialDesc& shader,
                        std::string const& owner);
    /// A texture file the scene names: one that is not found is a missing file, said once
    /// with what `owner` does without it (`consequence`).
    void checkTexture(std::string const& file, SourceLocation const& where, std::string const& owner,
                      std::string const& consequence);
    /// The OSL shader (name.oso, or its source name.osl) on the shader search path, beside the
    /// scene or in the working folder; empty when there is none.
    std::string oslShaderNamed(std::string const& name) const;
    /// The file name + one of `extensions` on the shader search path, beside the scene or in the
    /// working folder; empty when there is none.
    std::string shaderFileNamed(std::string const& name, std::vector<char const*> const& extensions) const;
    /// The source of surface shader `name` (name.sl, found as shaderFileNamed finds it) and the
    /// defaults it declares; looked for and read once per name and shader search path.
    DeclaredDefaults const& declaredDefaults(std::string const& name);
    /// MakeTexture, MakeLatLongEnvironment: the texture named is read from the picture.
    void makeTexture(RequestReader& in);
    void makeLatLongEnvironment(RequestReader& in);
    void surface(RequestReader& in);
    void light(RequestReader& in);
    void lightSource(RequestReader& in);
    void areaLightSource(RequestReader& in);
    /// A LightSource's or AreaLightSource's handle, read next; one is made up when it is left out.
    std::string lightHandle(RequestReader& in, std::string const& request);
    /// Makes the shapes in the current attribute block emit the light `shader` describes.
    void startAreaLight(std::string const& shader, std::string const& handle, ParamList const& params,
                        SourceLocation const& where);
    void illuminate(RequestReader& in);
    int defaultMaterial();
    /// The default material of a shape with "Cs" primvars: the classic matte shader, which reads them.
    int primvarColorMaterial();
    /// In a world lit by classic light shaders, the materials of shapes given no shader at all
    /// become PRMan's defaultsurface, as they were before RIS.
    void shadeUnshadedAsClassic();
    /// The material of the classic Surface shader in effect, with the current Color.
    int classicMaterial();
    /// With an area light in effect, a shape that has a light of its own kind (a
    /// full sphere, disk or rectangle) becomes that light: true when it did.
    bool shapeAsLight(char const* lightType, Mat4 const& lightToWorld, ParamList params = {});
    /// With an area light in effect, a polygon mesh of at most MeshLight::kMaxTriangles
    /// triangles becomes a mesh light: true when it did.
    bool meshAsLight(Shape const& shape);
    /// Adds a light made for the area light in effect, with its radiance, handle and visibility.
    void addAreaLight(std::unique_ptr<Light> light, AreaLightDesc const& area, Vec3 radiance);
    /// The emissive material of the area light in effect (for shapes with no light of their own kind).
    int emissiveMaterial(SourceLocation const& where);
    /// The warning for a Light type this renderer does not make.
    static std::string unsupportedLightMessage(std::string const& type);
    void resolvePortals();
    /// Warns when an area light closed with its block never met a shape.
    void warnIfUnshaped(std::shared_ptr<AreaLightDesc> const& closing, std::shared_ptr<AreaLightDesc> const& outer);
    /// Makes a light of either request (Light or LightSource) at lightToWorld.
    void makeLightFrom(std::string const& request, std::string const& type, std::string const& handle,
                       ParamList const& params, Mat4 const& lightToWorld, SourceLocation const& where);
    // Shapes (scene/requests/ShapeRequests.cpp).
    void sphere(RequestReader& in);
    void cylinder(RequestReader& in);
    void disk(RequestReader& in);
    void cone(RequestReader& in);
    void paraboloid(RequestReader& in);
    void hyperboloid(RequestReader& in);
    void torus(RequestReader& in);
    void polygon(RequestReader& in);
    void generalPolygon(RequestReader& in);
    void pointsPolygons(RequestReader& in);
    void pointsGeneralPolygons(RequestReader& in);
    void patch(RequestReader& in);
    void patchMesh(RequestReader& in);
    void geometry(RequestReader& in);
    /// Adds a shape with the material and attributes in effect, and its primvars that do not vary.
    void addShape(std::unique_ptr<Shape> shape, SourceLocation const& where, PrimvarSet constants = {});
    /// What every quadric request starts with: its numbers (the radius among them, made
    /// positive with the orientation flipped, when radiusArgument names it), and its
    /// primvars, the parameters it does not use warned about.
    struct QuadricRequest {
        std::vector<float> v;
        PrimvarSet primvars;
        bool reverse = false;
        float radius = 0.0f;
    };
    QuadricRequest readQuadric(RequestReader& in, char const* request, int count, char const* arguments,
                               int radiusArgument);
    /// A shape whose numbers leave it no area (a radius of 0, a polygon of two points) is nothing
    /// to see, as in RenderMan: warned about once per request, and skipped.
    void skipWithoutSurface(RequestReader& in, char const* request, char const* why);
    /// Adds the polygons a polygon request describes, with its primvars.
    void addPolygonMesh(char const* request, std::vector<int> const& loops, std::vector<int> const& nverts,
                        std::vector<int> const& verts, ParamList& params, RequestReader& in);
    /// Adds a surface tessellated to triangles (its orientation is in the triangles already).
    void addTessellated(MeshData mesh, char const* request, RequestReader& in, PrimvarSet primvars);
    /// The warning for a mesh request with no faces.
    void warnEmptyMesh(char const* request, RequestReader& in);
    // Free-form shapes (scene/requests/FreeformRequests.cpp).
    void subdivisionMesh(RequestReader& in);
    void hierarchicalSubdivisionMesh(RequestReader& in);
    void readSubdivisionMesh(RequestReader& in, bool hierarchical);
    void nuPatch(RequestReader& in);
    void trimCurve(RequestReader& in);
    void blobby(RequestReader& in);
    void points(RequestReader& in);
    void curves(RequestReader& in);
    // Instancing: objects and archives (scene/requests/InstanceRequests.cpp).
    void readArchive(RequestReader& in);
    /// Reads an archive by name: an inline archive, a file (beside the file that
    /// names it, in the working folder, on the search path) or a zip member.
    void readArchiveNamed(std::string const& name, SourceLocation const& where);
    /// Where a file named by the scene (an archive, a procedural's program or plugin) is looked for, in
    /// order, each place once: beside the file that names it, in the folder the renderer runs in, then in
    /// the folders of `searchPath`. An absolute name is looked for where it says.
    std::vector<std::filesystem::path> placesToLook(std::string const& name,
                                                    std::vector<std::string> const& searchPath) const;
    void procedural(RequestReader& in);
    void procedural2(RequestReader& in);
    /// The warning for a procedural that is not read (`program`: its first argument, if any).
    void warnProcedural(std::string const& kind, std::string const& program, SourceLocation const& where);
    /// Procedural "RunProgram" with programs allowed: reads what the program writes for this procedural.
    void runProgram(std::string const& program, std::string const& datablock, std::vector<float> const& bound,
                    SourceLocation const& where);
    /// Starts the program a "RunProgram" names (its first word; the others are its arguments).
    std::unique_ptr<ProceduralProgram> startProgram(std::string const& program, std::string& file,
                                                    SourceLocation const& where);
    void objectBegin(RequestReader& in);
    void objectInstance(RequestReader& in);
    void archiveBegin(RequestReader& in);
    using Recording = std::shared_ptr<std::vector<RibRequest>>;
    /// Starts recording requests into a new list (replacing any of that name) until `end`.
    void startRecording(Recording& slot, std::string const& end);
    /// Replays recorded requests (an object instance or an inline archive); `what` names
    /// it in messages. The recording is held for the replay: a redefinition inside it
    /// makes a new list instead of changing this one.
    void replay(std::string const& what, Recording requests, SourceLocation const& where);

    /// Notes the texture a MakeTexture (with `wrapModes`) or MakeLatLongEnvironment makes, and from what.
    void madeTexture(RequestReader& in, bool wrapModes);
    /// A file the scene names that is not there: an error with --strict, else a warning.
    void missingFile(SourceLocation const& where, std::string const& message);
    std::string currentDirectory() const;
    /// Where an image a light names is found: beside the file being read, then as any texture.
    TextureLocator textures() const;
    /// Warns once per request (or parameter) kind, counting the rest.
    void warnOnce(std::string const& kind, SourceLocation const& where, std::string const& message);
    /// True the first time `kind` is asked about; later times are counted as repeated warnings.
    bool firstOfKind(std::string const& kind);
    Attributes& state() { return m_attributes.back(); }
    /// Whether the world being read is kept (a frame not asked for is read, not built).
    bool building() const { return !m_skipWorld; }
    /// The world is complete: hand the frame over (or keep it), clear it for the next.
    void finishFrame();
    /// The end of the top-level file or text: close what is open, restore a kept frame's options.
    void finishInput(std::string const& name);

    Scene& m_scene;
    Diagnostics& m_diagnostics;
    LoadOptions m_options;
    FrameSink m_sink;
    Declarations m_declarations;
    std::vector<Attributes> m_attributes{Attributes{}};
    std::vector<Block> m_blocks;
    /// A misspelt AttributeBegin or TransformBegin that was skipped ("TransforBegin"
    /// in a real exporter's output). When its End comes, the block it meant is
    /// closed after all: the state it saved is restored.
    struct SkippedBegin {
        Block block;
        size_t depth;  ///< m_blocks.size() where it stood: its End comes back to this depth
        std::string word;
        SourceLocation where;
        Attributes saved;
    };
    std::vector<SkippedBegin> m_skippedBegins;
    /// True (with a warning) when an unmatched End closes a skipped misspelt Begin.
    bool closesSkippedBegin(Block block, SourceLocation const& where, std::string const& end);
    /// Stops reading at a second, different pbrt directive (see isPbrtDirective).
    void refuseIfPbrt(RibRequest const& request);
    struct {
        std::string word;
        SourceLocation where;
    } m_pbrtDirective;  ///< the first pbrt directive met, if any
    std::vector<std::string> m_fileStack;
    std::vector<std::string> m_archiveSearchPath;
    std::map<std::string, DeclaredDefaults> m_declaredDefaults;  ///< by shader name and search path
    std::vector<std::string> m_shaderSearchPath;  ///< where RenderMan finds OSL shaders (.oso)
    // Where a DynamicLoad plugin or a RunProgram program is looked for.
    std::vector<std::string> m_proceduralSearchPath;
    /// The programs of "RunProgram" procedurals, running while the scene is read, by the string naming them.
    struct RunningProgram {
        std::unique_ptr<ProceduralProgram> process;
        std::string file;  ///< the program's file, where its output's messages point
    };
    std::map<std::string, RunningProgram> m_programs;
    /// Programs that did not start or stopped: said once, then skipped.
    std::set<std::string> m_failedPrograms;
    std::map<std::string, std::string> m_userOptions;  // Option "user" values, for "${NAME}" and conditions
    bool m_archiveMissing = false;  // an archive was not found: objects it defined may be missing too
    int m_archivesNotFound = 0;     // the first few list the places tried, the rest one line each
    std::map<std::string, int> m_defaultMaterials;
    /// The materials of shapes given no Surface and no Bxdf, with the Color and Opacity then in effect.
    struct Unshaded {
        int material;
        Vec3 color, opacity;
    };
    std::vector<Unshaded> m_unshaded;
    std::map<std::string, int> m_patternHandles;  ///< handle -> the latest Pattern of that name
    std::map<std::shared_ptr<AreaLightDesc>, int> m_emissiveMaterials;
    std::map<std::string, Mat4> m_namedSpaces;  ///< CoordinateSystem
    std::set<std::string> m_warnedKinds;
    int m_repeatedWarnings = 0;
    /// Requests being recorded into an object or inline archive (null when not recording).
    std::vector<RibRequest>* m_recording = nullptr;
    std::string m_recordingEnd;  ///< the request that stops the recording
    std::map<std::string, Recording> m_objects;
    std::map<std::string, Recording> m_inlineArchives;
    std::set<std::string> m_replaying;  ///< objects and archives being replayed: entering one again is a cycle
    long m_replayedRequests = 0;        ///< bounds what instancing may expand to
    bool m_inWorld = false;
    int m_nestedWorlds = 0;  ///< WorldBegins inside the world, ignored until their WorldEnds
    int m_framesDone = 0;       ///< worlds completed so far
    bool m_skipWorld = false;   ///< this world's frame is not wanted
    bool m_keptFrame = false;   ///< without a sink: the frame asked for is in the scene already
    SceneOptions m_keptOptions; ///< ...and its options, which later frames' options must not change
    int m_frameNumber = -1;     ///< of the FrameBegin in effect
    /// Options and state saved by FrameBegin, restored by FrameEnd.
    struct SavedFrame {
        SceneOptions options;
        std::vector<Attributes> attributes;
        ColorSamples colorSamples;  ///< an option too, though kept with the declarations
    };
    std::vector<SavedFrame> m_frames;
    /// An open IfBegin block.
    struct ConditionBlock {
        bool enclosingRead;  ///< the block itself is in a part being read
        bool branchTaken;    ///< one of its branches has been read (or is being read)
        bool reading;        ///< the current branch is read
        bool elseSeen;
    };
    std::vector<ConditionBlock> m_conditions;  ///< innermost last
    std::optional<MotionBlock> m_motion;
    /// The standard light shaders' ambientlight: light the classic shaders add as Ka * ambient.
    Vec3 m_ambient{0.0f};
    /// Where the world's first light made from a classic light shader (LightSource, or an
    /// AreaLightSource that is not RenderMan's own) was given, if it has one.
    std::optional<SourceLocation> m_firstClassicLight;
    std::vector<CameraLight> m_cameraLights;
    /// A PxrPortalLight of the world: what it is depends on whether the world has a sky, known only
    /// at its end (resolvePortals).
    struct PortalLight {
        std::string handle;
        ParamList params;
        Mat4 toWorld;
        SourceLocation where;
        Visibility visibility;
    };
    std::vector<PortalLight> m_portals;
    std::map<std::string, size_t> m_lightHandles;  ///< handle -> index in the scene's lights
    /// For each light handle named by Illuminate, and each classic LightSource: how many
    /// shapes it is on and off for, and (a classic light) how many came before it.
    struct LightUse {
        int shapesOn = 0, shapesOff = 0;
        bool listed = false;  ///< a classic light: on only for shapes it is on the light list of
        bool illuminated = false;  ///< named by Illuminate
        int shapesBefore = 0;
        int listedOrder = -1;  ///< a classic light: how many classic lights came before it in this world
        SourceLocation where;  ///< a classic light's LightSource
    };
    std::map<std::string, LightUse> m_lightUse;
    int m_worldShapes = 0;  ///< shapes read in this world so far
    int m_shapesOutsideDetail = 0;  ///< shapes of this world left out by DetailRange
    int m_solidDepth = 0;           ///< SolidBegin blocks open
    std::map<std::string, Attributes> m_savedAttributes;  ///< Resource "attributes" saved, by name
    /// What m_savedAttributes held at each open ResourceBegin (ResourceEnd forgets names saved since).
    std::vector<std::map<std::string, Attributes>> m_resourceScopes;
    int m_listedLights = 0;  ///< classic lights given in this world so far
    /// Light linking, as a shape is read: the handles that are off for it (sorted), how many
    /// classic lights had been given (the later ones are off for it too), and its "lighting" subsets.
    /// Each distinct set is kept once; a shape's lightLink indexes this list until the world ends
    /// (see linkLights).
    struct LightsOff {
        std::vector<std::string> handles;
        int listedBefore = 0;
        std::vector<std::string> subset, exclude;
        auto key() const { return std::tie(handles, listedBefore, subset, exclude); }
        bool operator<(LightsOff const& other) const { return key() < other.key(); }
    };
    std::vector<LightsOff> m_lightsOff;
    std::map<LightsOff, int> m_lightsOffIndex;
    /// At the world's end, with the lights that are kept: each shape's Scene::lightLinks entry.
    void linkLights();
};

/// Parses a RIB file into a new Scene (a convenience for tools and tests):
/// its first frame, or the one LoadOptions::frame names.
Scene loadScene(std::string const& path, Diagnostics& diagnostics, LoadOptions options = {});

}  // namespace bxdflab
