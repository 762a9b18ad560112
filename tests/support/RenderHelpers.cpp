#include "support/RenderHelpers.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/SceneBuilder.h"

namespace bxdflab::test {

bool RenderOutcome::anyMessageContains(std::string const& text) const {
    for (auto const& m : messages)
        if (m.text.find(text) != std::string::npos) return true;
    return false;
}

Scene parseRib(std::string const& rib, Diagnostics& diagnostics, std::string const& name, LoadOptions options) {
    Scene scene;
    SceneBuilder builder(scene, diagnostics, options);
    builder.readText(rib, name);
    return scene;
}

RenderSettings withSpp(int spp) {
    RenderSettings settings;
    settings.spp = spp;
    return settings;
}

RenderOutcome renderRib(std::string const& rib, RenderSettings settings, std::string const& name) {
    Diagnostics diagnostics(false);
    Scene scene = parseRib(rib, diagnostics, name);
    if (settings.pluginPath.empty()) settings.pluginPath = TEST_PLUGIN_DIR;
    RenderOutcome out;
    {
        Renderer renderer(scene, settings, diagnostics);
        Film film = renderer.render();
        out.rgba = film.rgba();
        out.variance = film.varianceOfMean();
        out.width = film.width();
        out.height = film.height();
        for (int y = 0; y < out.height; ++y)
            for (int x = 0; x < out.width; ++x) out.samples.push_back(film.samplesTaken(x, y));
        out.stats = renderer.stats();
    }
    out.messages = diagnostics.entries();
    return out;
}

double meanChannel(RenderOutcome const& r, int c, std::function<bool(int, int)> const& keep) {
    double sum = 0.0;
    long count = 0;
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x)
            if (keep(x, y)) {
                sum += r.channel(x, y, c);
                ++count;
            }
    return count ? sum / static_cast<double>(count) : 0.0;
}

std::string outputDir() {
    std::filesystem::create_directories(TEST_OUTPUT_DIR);
    return TEST_OUTPUT_DIR;
}

std::string readScene(std::string const& relative) {
    std::ifstream in(std::string(SCENES_DIR) + "/" + relative);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string withIntegrator(std::string rib, std::string const& integrator) {
    size_t start = rib.find("Integrator ");
    size_t end = rib.find('\n', start);
    return rib.replace(start, end - start, integrator);
}

int warningsContaining(Diagnostics const& diagnostics, std::string const& text) {
    int n = 0;
    for (std::string const& warning : warningTexts(diagnostics)) n += warning.find(text) != std::string::npos;
    return n;
}

std::vector<std::string> warningTexts(Diagnostics const& diagnostics) {
    std::vector<std::string> texts;
    for (auto const& entry : diagnostics.entries())
        if (entry.severity == Diagnostics::Severity::Warning) texts.push_back(entry.text);
    return texts;
}

}  // namespace bxdflab::test
