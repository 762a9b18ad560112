#include "integrate/DirectLighting.h"
#include "integrate/Integrator.h"
#include "integrate/PathTracer.h"
#include "integrate/ValidateBxdf.h"
#include "scene/lights/HeadLight.h"

namespace bxdflab {
namespace {

int sampleCount(ParamList const& params, const char* name, int dflt) {
    int value = params.getInt(name, dflt);
    if (value < 0 || value > 4096)
        throw RibError(params.find(name)->location,
                       std::string(name) + " must be between 0 and 4096, got " + std::to_string(value));
    return value;
}

}  // namespace

std::unique_ptr<Integrator> makeIntegrator(IntegratorDesc const& desc, Scene const&, Vec3 const& cameraPosition,
                                           Diagnostics& diagnostics) {
    std::unique_ptr<Integrator> integrator;
    if (desc.name == "PxrDirectLighting") {
        integrator = std::make_unique<DirectLighting>(sampleCount(desc.params, "numLightSamples", 1),
                                                      sampleCount(desc.params, "numBxdfSamples", 1));
    } else if (desc.name == "PxrDefault") {
        integrator = std::make_unique<DirectLighting>(1, 0, std::make_unique<HeadLight>(cameraPosition));
    } else if (desc.name == "PxrPathTracer") {
        int maxPathLength = desc.params.getInt("maxPathLength", 10);
        if (maxPathLength < 1 || maxPathLength > 1000)
            throw RibError(desc.where, "PxrPathTracer: maxPathLength must be between 1 and 1000");
        integrator = std::make_unique<PathTracer>(maxPathLength, sampleCount(desc.params, "numLightSamples", 1),
                                                  std::max(1, sampleCount(desc.params, "numBxdfSamples", 1)),
                                                  desc.params.getInt("allowCaustics", 0) != 0);
    } else if (desc.name == "PxrValidateBxdf") {
        integrator = std::make_unique<ValidateBxdf>(std::max(1, sampleCount(desc.params, "numSamples", 4)));
    } else if (desc.name == "PxrDebugShadingContext") {
        integrator = std::make_unique<DebugShadingContext>(desc.params.getString("viewchannel", "Nn"), desc.where);
    } else if (desc.name == "PxrOcclusion") {
        float maxDistance = desc.params.getFloat("maxDistance", 1e30f);
        if (!(maxDistance > 0.0f)) throw RibError(desc.where, "PxrOcclusion: maxDistance must be positive");
        integrator = std::make_unique<Occlusion>(std::max(1, sampleCount(desc.params, "numSamples", 16)), maxDistance);
    } else {
        throw RibError(desc.where, "unknown integrator \"" + desc.name +
                                       "\" (available: PxrPathTracer, PxrDirectLighting, PxrDefault, PxrValidateBxdf, "
                                       "PxrDebugShadingContext, PxrOcclusion)");
    }
    desc.params.warnUnused(diagnostics, "Integrator \"" + desc.name + "\"");
    return integrator;
}

}  // namespace bxdflab
