// Interprets RIB requests: keeps the graphics state (transform and attribute
// stacks) and fills a Scene with the camera, materials, lights and shapes.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/Diagnostics.h"
#include "parse/ParamList.h"
#include "parse/RibRequest.h"
#include "scene/Scene.h"
#include "scene/shapes/MeshBuilders.h"

namespace bxdflab {

class SceneBuilder {
public:
    SceneBuilder(Scene& scene, Diagnostics& diagnostics);

    /// Reads a RIB file (and every archive it includes) into the scene.
    void readFile(std::string const& path);
    /// Reads RIB text; `fileName` is used in messages and to resolve relative paths.
    void readText(std::string const& text, std::string const& fileName);

private:
    struct Attributes {
        Mat4 transform{1.0f};
        int material = -1;
        Visibility visibility;
        std::string name;
        Vec3 color{1.0f};
        bool reverseOrientation = false;
        bool colorSet = false;
        SplineBasis uBasis = SplineBasis::bezier(), vBasis = SplineBasis::bezier();
    };
    enum class Block { Attribute, Transform };

    void handle(RibRequest const& request);
    using Handler = void (SceneBuilder::*)(RequestReader&);
    static std::map<std::string, Handler> const& handlers();

    // Options and camera (before WorldBegin).
    void display(RequestReader& in);
    void format(RequestReader& in);
    void projection(RequestReader& in);
    void screenWindow(RequestReader& in);
    void pixelSamples(RequestReader& in);
    void hider(RequestReader& in);
    void integrator(RequestReader& in);
    void option(RequestReader& in);
    void declare(RequestReader& in);
    void worldBegin(RequestReader& in);
    void worldEnd(RequestReader& in);
    void ignore(RequestReader& in);
    // Graphics state.
    void attributeBegin(RequestReader& in);
    void attributeEnd(RequestReader& in);
    void transformBegin(RequestReader& in);
    void transformEnd(RequestReader& in);
    void identity(RequestReader& in);
    void transform(RequestReader& in);
    void concatTransform(RequestReader& in);
    void translate(RequestReader& in);
    void rotate(RequestReader& in);
    void scale(RequestReader& in);
    /// Makes `transform` current, or fails at the request if it overflowed.
    void setTransform(RequestReader& in, Mat4 const& transform);
    void attribute(RequestReader& in);
    void color(RequestReader& in);
    void reverseOrientation(RequestReader& in);
    void orientation(RequestReader& in);
    // Materials and lights.
    void bxdf(RequestReader& in);
    void light(RequestReader& in);
    // Geometry.
    void sphere(RequestReader& in);
    void cylinder(RequestReader& in);
    void disk(RequestReader& in);
    void polygon(RequestReader& in);
    void pointsPolygons(RequestReader& in);
    void pointsGeneralPolygons(RequestReader& in);
    void patch(RequestReader& in);
    void geometry(RequestReader& in);
    void readArchive(RequestReader& in);
    void cone(RequestReader& in);
    void paraboloid(RequestReader& in);
    void hyperboloid(RequestReader& in);
    void torus(RequestReader& in);
    void basis(RequestReader& in);
    void patchMesh(RequestReader& in);
    void objectBegin(RequestReader& in);
    void objectInstance(RequestReader& in);
    void archiveBegin(RequestReader& in);
    void clipping(RequestReader& in);
    void sides(RequestReader& in);
    using Recording = std::shared_ptr<std::vector<RibRequest>>;
    /// Starts recording requests into a new list (replacing any of that name) until `end`.
    void startRecording(Recording& slot, std::string const& end);
    /// Replays recorded requests (an object instance or an inline archive); `what` names
    /// it in messages. The recording is held for the replay: a redefinition inside it
    /// makes a new list instead of changing this one.
    void replay(std::string const& what, Recording requests, SourceLocation const& where);

    void addShape(std::unique_ptr<Shape> shape, SourceLocation const& where);
    int defaultMaterial();
    std::string currentDirectory() const;
    /// Warns once per request (or parameter) kind, counting the rest.
    void warnOnce(std::string const& kind, SourceLocation const& where, std::string const& message);
    Attributes& state() { return m_attributes.back(); }

    Scene& m_scene;
    Diagnostics& m_diagnostics;
    Declarations m_declarations;
    std::vector<Attributes> m_attributes{Attributes{}};
    std::vector<Block> m_blocks;
    std::vector<std::string> m_fileStack;
    std::vector<std::string> m_archiveSearchPath;
    std::map<std::string, int> m_defaultMaterials;
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
    bool m_sawWorld = false;
    bool m_sppFromPixelSamples = false;
};

/// Parses a RIB file into a new Scene (a convenience for tools and tests).
Scene loadScene(std::string const& path, Diagnostics& diagnostics);

}  // namespace bxdflab
