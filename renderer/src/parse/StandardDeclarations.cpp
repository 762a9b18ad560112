#include "parse/StandardDeclarations.h"

namespace bxdflab {

std::vector<std::pair<char const*, char const*>> const& standardDeclarations() {
    static std::vector<std::pair<char const*, char const*>> const table = {
        // Primitive variables (RI spec, section 5).
        {"P", "vertex point"}, {"Pz", "vertex float"}, {"Pw", "vertex hpoint"}, {"N", "varying normal"},
        {"Np", "uniform normal"}, {"Cs", "varying color"}, {"Os", "varying color"}, {"s", "varying float"},
        {"t", "varying float"}, {"st", "varying float[2]"}, {"width", "varying float"},
        {"constantwidth", "constant float"}, {"constantnormal", "constant normal"},
        // Camera and projection.
        {"fov", "float"},
        // Standard light shaders (ambientlight, distantlight, pointlight, spotlight).
        {"intensity", "float"}, {"lightcolor", "color"}, {"from", "point"}, {"to", "point"},
        {"coneangle", "float"}, {"conedeltaangle", "float"}, {"beamdistribution", "float"},
        // Standard surface and displacement shaders.
        {"Ka", "float"}, {"Kd", "float"}, {"Ks", "float"}, {"Kr", "float"}, {"roughness", "float"},
        {"specularcolor", "color"}, {"texturename", "string"}, {"mapname", "string"}, {"amplitude", "float"},
        {"sphere", "float"}, {"disk", "float"}, {"coordinatesystem", "string"},
        // Option "searchpath".
        {"archive", "string"}, {"shader", "string"}, {"texture", "string"}, {"display", "string"},
        {"procedural", "string"}, {"resource", "string"}, {"rixplugin", "string"}, {"dirmap", "string"},
        {"servershader", "string"}, {"servertexture", "string"}, {"serverarchive", "string"},
        // Option "limits" and "statistics", "shadow", "trace", "rib".
        {"bucketsize", "int[2]"}, {"gridsize", "int"}, {"texturememory", "int"}, {"eyesplits", "int"},
        {"othreshold", "color"}, {"zthreshold", "color"}, {"geocachememory", "int"}, {"brickmemory", "int"},
        {"octreememory", "int"}, {"threads", "int"}, {"deepshadowerror", "float"}, {"endofframe", "int"},
        {"filename", "string"}, {"xmlfilename", "string"}, {"bias0", "float"}, {"bias1", "float"},
        {"maxdepth", "int"}, {"format", "string"}, {"asciistyle", "string"},
        // Hider parameters.
        {"jitter", "int"}, {"depthfilter", "string"}, {"maxsamples", "int"}, {"minsamples", "int"},
        {"minextrasamples", "int"}, {"samplemotion", "int"}, {"extrememotiondof", "int"}, {"emit", "int"},
        {"incremental", "int"},
        {"pixelvariance", "float"}, {"darkfalloff", "float"}, {"integrationmode", "string"}, {"aperture", "float[4]"},
        // Display parameters.
        {"quantize", "float[4]"}, {"dither", "float"}, {"compression", "string"}, {"exrcompression", "string"},
        {"merge", "int"}, {"origin", "int[2]"}, {"dspyParams", "string"},
        // Attributes.
        {"name", "string"}, {"shadinggroup", "string"}, {"id", "int"}, {"camera", "int"}, {"diffuse", "int"},
        {"specular", "int"}, {"transmission", "int"}, {"indirect", "int"}, {"trace", "int"}, {"photon", "int"},
        {"midpoint", "int"},
        {"bias", "float"}, {"maxdiffusedepth", "int"}, {"maxspeculardepth", "int"}, {"displacements", "int"},
        {"importancethreshold", "float"}, {"binary", "int"}, {"rasterorient", "int"}, {"hair", "int"},
        {"strategy", "string"}, {"referencecamera", "string"}, {"displacement", "float"}, {"backfacing", "int"},
        {"hidden", "int"}, {"diffusehitmode", "string"}, {"specularhitmode", "string"},
        {"transmissionhitmode", "string"}, {"camerahitmode", "string"}, {"frequency", "string"},
        {"relativeshadingrate", "float"}, {"shadingrate", "float"}, {"maxerror", "float"}, {"handle", "string"},
        {"filemode", "string"}, {"shadingmodel", "string"}, {"causticmap", "string"}, {"globalmap", "string"},
        {"estimator", "int"}, {"sigma", "int"}, {"pointfalloff", "int"}, {"shadows", "string"}, {"samples", "int"},
        {"membership", "string"}, {"centered", "int"}, {"extrapolate", "int"}, {"sense", "string"},
        {"motionfactor", "float"}, {"offset", "float"}, {"velocity", "float"},
        {"casts_shadows", "string"},  // BMRT's Attribute "render"
    };
    return table;
}

}  // namespace bxdflab
