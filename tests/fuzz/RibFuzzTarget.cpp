// The RIB fuzz target: feeds arbitrary bytes to the scene builder (lexer,
// parser, graphics state, shapes and lights) and checks the promises the rest
// of the renderer relies on:
//   - bad input is reported as a RenderError; a RibError carries a location
//     inside the text (line and column from 1) — anything else escaping, and
//     any crash, leak or undefined behaviour the sanitizers see, is a bug;
//   - a scene that parses is one the renderer can use: a valid resolution and
//     sample count, a finite camera, materials that exist, and meshes whose
//     indices and attribute arrays agree and whose points are finite.
// The same function runs under libFuzzer (clang, tests/fuzz/libfuzzer) and
// under a plain driver that replays kept inputs (RibFuzzReplay.cpp).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "scene/SceneBuilder.h"
#include "scene/shapes/TriangleMesh.h"

using namespace bxdflab;

namespace {

[[noreturn]] void broken(std::string const& promise) {
    std::fprintf(stderr, "RIB fuzz target: broken promise: %s\n", promise.c_str());
    std::abort();
}

bool finite(Vec3 const& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

template <typename T>
void requireEmptyOrPerVertex(std::vector<T> const& values, size_t vertices, const char* name) {
    if (!values.empty() && values.size() != vertices)
        broken(std::string("a mesh has ") + std::to_string(values.size()) + " " + name + " values for " +
               std::to_string(vertices) + " vertices");
}

void checkMesh(MeshData const& mesh) {
    size_t const vertices = mesh.P.size();
    if (mesh.indices.size() % 3 != 0) broken("a mesh's index count is not a multiple of 3");
    for (unsigned index : mesh.indices)
        if (index >= vertices) broken("a mesh index is out of range");
    for (Vec3 const& p : mesh.P)
        if (!finite(p)) broken("a mesh vertex is not finite");
    requireEmptyOrPerVertex(mesh.N, vertices, "N");
    requireEmptyOrPerVertex(mesh.uv, vertices, "uv");
    requireEmptyOrPerVertex(mesh.st, vertices, "st");
    requireEmptyOrPerVertex(mesh.dPdu, vertices, "dPdu");
    requireEmptyOrPerVertex(mesh.dPdv, vertices, "dPdv");
}

void checkScene(Scene const& scene) {
    if (scene.xres < 1 || scene.yres < 1 || scene.xres > 16384 || scene.yres > 16384)
        broken("the resolution is out of range");
    if (scene.spp < 1) broken("fewer than 1 sample per pixel");
    if (!(scene.camera.fov > 0.0f && scene.camera.fov < 180.0f)) broken("the field of view is out of range");
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(scene.camera.worldToCamera[i][j])) broken("the camera transform is not finite");
    for (auto const& shape : scene.shapes) {
        if (shape->material < -1 || shape->material >= static_cast<int>(scene.materials.size()))
            broken("a shape refers to a material that does not exist");
        if (auto const* mesh = dynamic_cast<TriangleMesh const*>(shape.get())) checkMesh(mesh->data());
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string const text(reinterpret_cast<const char*>(data), size);
    Scene scene;
    Diagnostics diagnostics(false);
    try {
        SceneBuilder builder(scene, diagnostics);
        builder.readText(text, "fuzz.rib");
    } catch (RibError const& error) {
        if (error.location.line < 1 || error.location.column < 1) broken(std::string("an unlocated RibError: ") + error.what());
        return 0;
    } catch (RenderError const&) {
        return 0;  // e.g. an archive that cannot be read: reported, not located in this text
    } catch (std::exception const& error) {
        broken(std::string("an exception other than RenderError escaped: ") + error.what());
    }
    checkScene(scene);
    return 0;
}
