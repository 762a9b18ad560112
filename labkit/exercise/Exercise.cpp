#include "exercise/Exercise.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace fs = std::filesystem;

namespace bxdflab {

bool Exercise::isRenderCheck(std::string const& check) { return check == "renders" || check == "noise"; }

bool Exercise::gradedWith(std::string const& check) const {
    return std::any_of(checks.begin(), checks.end(), [&](auto const& c) { return c.first == check; });
}

std::string Exercise::notApplicableReason(std::string const& check) const {
    for (auto const& n : notApplicable)
        if (n.check == check) return n.because;
    return "";
}

std::string Exercise::withMode(std::string const& base, SamplingMode const& mode) const {
    if (mode.params.empty()) return base;
    return base.empty() ? mode.params : base + " " + mode.params;
}

double Exercise::ior(std::string const& parameters) const {
    if (!transmits) return 1.0;
    // The last "float <iorParam>" [value] in the string wins, as in a RIB parameter list.
    std::string const key = "\"float " + iorParam + "\"";
    size_t at = parameters.rfind(key);
    if (at == std::string::npos)
        throw std::runtime_error("the parameters [" + parameters + "] do not set \"float " + iorParam + "\"");
    size_t open = parameters.find('[', at + key.size());
    if (open == std::string::npos) throw std::runtime_error("no value after " + key + " in [" + parameters + "]");
    return std::stod(parameters.substr(open + 1));
}

Exercise loadExercise(std::string const& courseRoot, std::string const& manifestPath) {
    std::ifstream in(manifestPath);
    if (!in) throw std::runtime_error("cannot read the exercise manifest " + manifestPath);
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(in);
    } catch (std::exception const& e) {
        throw std::runtime_error(manifestPath + ": " + e.what());
    }
    auto field = [&](char const* name) -> nlohmann::json const& {
        if (!j.contains(name)) throw std::runtime_error(manifestPath + ": the manifest has no \"" + name + "\"");
        return j.at(name);
    };
    Exercise e;
    try {
        e.plugin = field("plugin").get<std::string>();
        e.chapter = field("chapter").get<std::string>();
        e.title = j.value("title", e.plugin);
        e.order = j.value("order", 0);
        e.kind = j.value("kind", std::string("bxdf"));
        e.folder = fs::relative(fs::path(manifestPath).parent_path(), courseRoot).generic_string();
        e.solutionFolder = j.value("solution", "solutions/" + fs::path(e.folder).lexically_relative("starter").generic_string());
        e.sources = field("sources").get<std::vector<std::string>>();
        e.identicalToSolution = j.value("identicalToSolution", std::vector<std::string>{});
        e.scenes = j.value("scenes", std::vector<std::string>{});
        e.scene = j.value("scene", e.scenes.empty() ? std::string() : e.scenes.front());
        if (e.scenes.empty() && !e.scene.empty()) e.scenes.push_back(e.scene);
        e.noiseLimit = j.value("noiseLimit", e.noiseLimit);
        e.sameNoiseScenes = j.value("sameNoiseScenes", std::vector<std::string>{});
        for (auto const& scene : e.sameNoiseScenes)
            if (std::find(e.scenes.begin(), e.scenes.end(), scene) == e.scenes.end())
                throw std::runtime_error("\"sameNoiseScenes\" names " + scene + ", which is not one of its scenes");
        e.compareBlock = j.value("compareBlock", e.compareBlock);
        e.renderSpp = j.value("renderSpp", e.renderSpp);
        if (e.compareBlock < 1 || e.compareBlock > 64) throw std::runtime_error("\"compareBlock\" must be 1 to 64");
        e.similarTo = j.value("similarTo", std::vector<std::string>{});
        e.writeYourself = j.value("writeYourself", std::vector<std::string>{});
        e.params = j.value("params", std::string());
        e.colorParams = j.value("colorParams", e.params);
        e.hardCaseParams = j.value("hardCaseParams", std::vector<std::string>{});
        for (auto const& m : j.value("samplingModes", nlohmann::json::array()))
            e.samplingModes.push_back({m.at("name").get<std::string>(), m.value("params", std::string()),
                                       m.value("singleDraw", true)});
        if (e.samplingModes.empty()) e.samplingModes.push_back({"default", "", j.value("singleDraw", true)});
        std::string sides = j.value("sides", std::string("two"));
        if (sides == "two")
            e.sides = Sidedness::TwoSided;
        else if (sides == "one")
            e.sides = Sidedness::OneSided;
        else if (sides == "either")
            e.sides = Sidedness::Either;
        else
            throw std::runtime_error("\"sides\" must be \"one\", \"two\" or \"either\"");
        e.emitsOnly = j.value("emitsOnly", false);
        e.anisotropic = j.value("anisotropic", false);
        e.reciprocal = j.value("reciprocal", true);
        e.notReciprocalBecause = j.value("notReciprocalBecause", std::string());
        e.conservesEnergy = j.value("conservesEnergy", true);
        if (j.contains("transmission")) {
            nlohmann::json const& t = j.at("transmission");
            e.transmits = true;
            e.iorParam = t.at("iorParam").get<std::string>();
            e.smoothParams = t.value("smoothParams", std::string());
            e.ior(e.params);  // the checks' parameters must say the index they test
        }
        nlohmann::json const notApplicable = j.value("notApplicable", nlohmann::json::object());
        for (auto const& [check, because] : notApplicable.items()) e.notApplicable.push_back({check, because.get<std::string>()});
        for (auto const& c : field("checks")) e.checks.emplace_back(c.at(0).get<std::string>(), c.at(1).get<double>());
        if (e.kind != "bxdf" && e.kind != "sampling" && e.kind != "integrator")
            throw std::runtime_error("\"kind\" must be \"bxdf\", \"sampling\" or \"integrator\"");
        for (auto const& [check, points] : e.checks)
            if (check == "smooth" && e.smoothParams.empty())
                throw std::runtime_error("the check \"smooth\" needs \"transmission\": {\"smoothParams\": ...}");
        for (auto const& [check, points] : e.checks)
            if (Exercise::isRenderCheck(check) && e.scene.empty())
                throw std::runtime_error("the check \"" + check + "\" needs a \"scene\"");
    } catch (nlohmann::json::exception const& error) {
        throw std::runtime_error(manifestPath + ": " + error.what());
    } catch (std::invalid_argument const& error) {  // std::stod on a value that is not a number
        throw std::runtime_error(manifestPath + ": the refractive index in \"params\" is not a number");
    } catch (std::runtime_error const& error) {
        std::string what = error.what();
        throw std::runtime_error(what.rfind(manifestPath, 0) == 0 ? what : manifestPath + ": " + what);
    }
    return e;
}

std::vector<Exercise> loadExercises(std::string const& courseRoot) {
    std::vector<std::string> manifests;
    std::error_code error;
    for (auto const& chapter : fs::directory_iterator(fs::path(courseRoot) / "starter", error)) {
        if (!chapter.is_directory()) continue;
        for (auto const& folder : fs::directory_iterator(chapter.path(), error)) {
            fs::path manifest = folder.path() / "exercise.json";
            if (fs::is_regular_file(manifest, error)) manifests.push_back(manifest.string());
        }
    }
    if (manifests.empty()) throw std::runtime_error("no exercise manifests under " + courseRoot + "/starter");
    std::vector<Exercise> exercises;
    for (auto const& m : manifests) exercises.push_back(loadExercise(courseRoot, m));
    std::sort(exercises.begin(), exercises.end(), [](Exercise const& a, Exercise const& b) {
        int ca = std::atoi(a.chapter.c_str()), cb = std::atoi(b.chapter.c_str());
        if (ca != cb) return ca < cb;
        return a.order != b.order ? a.order < b.order : a.plugin < b.plugin;
    });
    return exercises;
}

Exercise const* findExercise(std::vector<Exercise> const& exercises, std::string const& plugin) {
    for (auto const& e : exercises)
        if (e.plugin == plugin) return &e;
    return nullptr;
}

}  // namespace bxdflab
