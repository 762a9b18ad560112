// Helpers for tests that render small scenes written inline.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/Diagnostics.h"
#include "render/Film.h"
#include "render/Renderer.h"
#include "scene/Scene.h"
#include "scene/SceneBuilder.h"

namespace bxdflab::test {

struct RenderOutcome {
    std::vector<float> rgba;  ///< per-pixel mean, RGBA
    std::vector<float> variance;  ///< per-pixel variance of the mean, RGB
    std::vector<int> samples;     ///< camera samples each pixel took
    int width = 0, height = 0;
    RenderStats stats;
    std::vector<Diagnostics::Entry> messages;

    float channel(int x, int y, int c) const { return rgba[4 * (static_cast<size_t>(y) * width + x) + c]; }
    bool anyMessageContains(std::string const& text) const;
};

/// Renders RIB text. The test plugin folder is on the search path; `name`
/// is the file name used in messages.
RenderOutcome renderRib(std::string const& rib, RenderSettings settings = {}, std::string const& name = "test.rib");

/// Default settings but for the samples per pixel.
RenderSettings withSpp(int spp);

/// Parses RIB text into a scene (throws like the renderer does).
Scene parseRib(std::string const& rib, Diagnostics& diagnostics, std::string const& name = "test.rib",
               LoadOptions options = {});

/// How many warnings contain `text` (an empty text counts them all).
int warningsContaining(Diagnostics const& diagnostics, std::string const& text);
/// The texts of the warnings, in the order they were given.
std::vector<std::string> warningTexts(Diagnostics const& diagnostics);

/// Mean of channel c over the pixels for which keep(x, y) is true.
double meanChannel(RenderOutcome const& r, int c, std::function<bool(int, int)> const& keep);

/// The text of a course scene, by its path under scenes/ (e.g. "ch06/diffuse.rib"); empty if missing.
std::string readScene(std::string const& relative);

/// `rib` with its Integrator line replaced by `integrator`.
std::string withIntegrator(std::string rib, std::string const& integrator);

/// RIB that lifts RenderMan's per-object bounce limits (1 diffuse, 2 specular) out of the way,
/// so that maxPathLength alone bounds a path tracer's paths (written before WorldBegin, it holds
/// for every shape).
inline constexpr char const* kDeepTraceDepth =
    "Attribute \"trace\" \"int maxdiffusedepth\" [1000] \"int maxspeculardepth\" [1000]\n";

/// A folder under the build tree for files a test must write.
std::string outputDir();

}  // namespace bxdflab::test
