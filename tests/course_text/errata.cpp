// The course text's errata, checked against the API headers. Compiled as
// printed (with -DAS_PRINTED_<NAME>) each form must fail; compiled as is,
// every corrected form must build (C++14, warnings as errors) -- the way
// chapters/appendix-course-text.md says a reader should fix it.
#include <cmath>
#include <new>

#include "RixBxdf.h"
#include "RixShadingUtils.h"

// Listing 6-5: the emissive plugin's BeginScatter builds a "SimpleDiffuse"
// named "diff"; inside the emissive plugin the class is the emissive Bxdf.
namespace listing_6_5 {
class Emissive;  // the plugin's own Bxdf class (its definition is in the listing)
#ifdef AS_PRINTED_6_5
inline void* build(void* mem) { return new (mem) SimpleDiffuse(); }
#else
inline Emissive* build(void* mem) { return static_cast<Emissive*>(mem); }
#endif
}  // namespace listing_6_5

// Listing 8-6: the fiber lobe's Gaussian divides by SQRT_2PI, which no header defines.
namespace listing_8_6 {
#ifndef AS_PRINTED_8_6
static float const SQRT_2PI = std::sqrt(F_TWOPI);  // define it next to the Gaussian
#endif
inline float gaussian(float beta, float x) {
    return std::exp(-x * x / (2.0f * beta * beta)) / (beta * SQRT_2PI);
}
}  // namespace listing_8_6

// Listings 8-1 and 8-3: the Ward weight is f * cos(theta_L) -- N.L, not N.V --
// and GenerateSample and EvaluateSample must return the same weight and pdf
// for the same direction (both call one function, as the solution does).
namespace listing_8_3 {
inline float wardWeight(float brdf, RtNormal3 const& N, RtVector3 const& Ln, RtVector3 const&) {
    return brdf * RixMax(N.Dot(Ln), 0.0f);
}
}  // namespace listing_8_3

// Finished wood: RixFresnelDielectric's T points away from the shading point,
// into the wood (where light must come from to leave along V); the light that
// leaves toward the viewer travels along -T. The fiber lobe's psi_r is built
// on that outgoing path (the behaviour is tested by the solution's values test
// and the grader's mutant wood_fiber_mirrored).
namespace finished_wood {
inline float halfAngle(RtVector3 const& Vn, RtVector3 const& Ln, RtNormal3 const& Nn, RtVector3 const& axis,
                       float eta) {
    float Kr;
    RtVector3 Rdir, ssInDir, ssOutDir;
    RixFresnelDielectric(Ln, Nn, 1.0f / eta, &Kr, &Rdir, &ssInDir);   // the light's path in: along ssInDir
    RixFresnelDielectric(Vn, Nn, 1.0f / eta, &Kr, &Rdir, &ssOutDir);  // the path out: along -ssOutDir
    float psiI = std::asin(RixClamp(-ssInDir.Dot(axis), -1.0f, 1.0f));
    float psiR = std::asin(RixClamp(-ssOutDir.Dot(axis), -1.0f, 1.0f));
    return psiR + psiI;
}
}  // namespace finished_wood

// Listing 8-2: the specular lobe is looked up as specular (the third argument).
namespace listing_8_2 {
inline RixBXLobeSampled specularLobe(RixContext& ctx) {
    return RixBXLookupLobeByName(ctx, /*discrete=*/false, /*specular=*/true, /*reflect=*/true, /*user=*/false, 1,
                                 "Specular");
}
}  // namespace listing_8_2

// Names the prose misspells.
namespace prose {
#ifdef AS_PRINTED_GetEvaluationDomain
auto const domain = &RixBxdf::GetEvaluationDomain;
#else
auto const domain = &RixBxdf::GetEvaluateDomain;
#endif
#ifdef AS_PRINTED_EvaluateSamples
auto const evaluate = &RixBxdf::EvaluateSamples;
#else
auto const evaluate = &RixBxdf::EvaluateSample;
#endif
#ifdef AS_PRINTED_EvaluateSampleAtIndex
auto const evaluateAtIndex = &RixBxdf::EvaluateSampleAtIndex;
#else
auto const evaluateAtIndex = &RixBxdf::EvaluateSamplesAtIndex;
#endif
#ifdef AS_PRINTED_RixBXLookupByName
auto const lookup = &RixBXLookupByName;
#else
auto const lookup = &RixBXLookupLobeByName;
#endif
#ifdef AS_PRINTED_RixLobeSampled
using Sampled = RixLobeSampled;
#else
using Sampled = RixBXLobeSampled;
#endif
}  // namespace prose

int main() {
    (void)listing_6_5::build;
    (void)listing_8_2::specularLobe;
    (void)finished_wood::halfAngle;
    (void)prose::domain;
    (void)prose::evaluate;
    (void)prose::evaluateAtIndex;
    (void)prose::lookup;
    prose::Sampled sampled;
    (void)sampled;
    return listing_8_6::gaussian(1.0f, 0.0f) > 0.0f && listing_8_3::wardWeight(1.0f, RtNormal3(0, 0, 1), RtVector3(0, 0, 1), RtVector3(0, 0, 1)) > 0.0f ? 0 : 1;
}
