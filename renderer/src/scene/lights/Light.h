// Analytic lights. They are not Embree geometry: integrators sample them
// directly (next-event estimation) and intersect them explicitly when a
// Bxdf-sampled ray may hit one (for multiple importance sampling).
//
// Every light's radiance is intensity * 2^exposure * lightColor.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "RiTypesHelper.h"
#include "core/Math.h"
#include "scene/shapes/Shape.h"

namespace bxdflab {

/// A direction toward a light, as chosen by Light::sample.
struct LightSample {
    Vec3 wi{0.0f};                ///< unit direction from the shading point toward the light
    float distance = kInfinity;   ///< to the sampled point on the light
    RtColorRGB radiance;          ///< arriving along -wi (zero when the light faces away)
    float pdf = 0.0f;             ///< per unit solid angle; 1 for delta lights
    bool delta = false;           ///< a direction no Bxdf sample can ever hit
};

/// A ray leaving a light, as chosen by Light::sampleEmission (the first
/// vertex of a light subpath, for bidirectional integrators).
struct LightEmission {
    Vec3 origin{0.0f};           ///< on the light
    Vec3 normal{0.0f};           ///< the light's unit normal there; zero for a point light
    Vec3 dir{0.0f};              ///< unit direction of the ray
    RtColorRGB radiance;         ///< leaving origin along dir (radiant intensity for a point light)
    float pdfArea = 0.0f;        ///< per unit area of the light; 1 for a point light
    float pdfDir = 0.0f;         ///< per unit solid angle around dir
};

/// The densities Light::sampleEmission gives a ray leaving `point` along a direction.
struct EmissionDensity {
    float pdfArea = 0.0f;
    float pdfDir = 0.0f;
    float cosine = 1.0f;         ///< |normal . dir| at the point (1 for a point light)
};

class Light {
public:
    virtual ~Light() = default;
    virtual const char* kind() const = 0;
    /// Chooses a direction toward the light from P, using a 2-D sample xi.
    virtual LightSample sample(Vec3 const& P, Vec2 const& xi) const = 0;
    /// If the ray (org, unit dir) hits the light: the distance, the radiance
    /// it carries back along -dir, and the pdf sample() would assign to dir.
    virtual bool intersect(Vec3 const& org, Vec3 const& dir, float& distance, RtColorRGB& radiance,
                           float& pdf) const = 0;
    /// Lights that can start a light subpath (those at a finite distance).
    virtual bool canEmit() const { return false; }
    /// Chooses a point on the light and a direction of emission from two 2-D
    /// samples; false when the light sends nothing (a black light).
    virtual bool sampleEmission(Vec2 const& xiPosition, Vec2 const& xiDirection, LightEmission& out) const {
        (void)xiPosition;
        (void)xiDirection;
        (void)out;
        return false;
    }
    /// The densities sampleEmission gives the ray leaving `point` (on the light) along unit `dir`.
    virtual EmissionDensity emissionDensity(Vec3 const& point, Vec3 const& dir) const {
        (void)point;
        (void)dir;
        return {};
    }
    /// The area of the surface that emits (0 for lights that have none: points, directions, skies).
    virtual float surfaceArea() const { return 0.0f; }
    /// Delta lights (a distant light with no angular extent) cannot be hit.
    virtual bool isDelta() const { return false; }
    /// Lights at infinity are seen by rays that miss all geometry.
    virtual bool isInfinite() const { return false; }
    /// A sphere holding every point of the light, or false when there is none
    /// (lights at infinity). It lets the camera skip lights out of its view.
    virtual bool boundingSphere(Vec3& center, float& radius) const {
        (void)center;
        (void)radius;
        return false;
    }

    RtColorRGB color;  ///< intensity * 2^exposure * lightColor
    bool castsShadows = true;  ///< false for classic lights given no shadow map or ray-traced shadows
    /// RenderMan's non-physical "diffuse" and "specular" controls: what the light's light is
    /// multiplied by where a diffuse or a specular lobe reflects it straight from the light.
    float diffuseMultiplier = 1.0f, specularMultiplier = 1.0f;
    Visibility visibility;
    std::string handle;
    /// Attribute "grouping" "membership": the groups a shape's "lighting" subsets may name it by
    /// (besides its handle).
    std::vector<std::string> groups;
};

/// What a ray sees of the lights: the nearest light it hits.
struct LightAlongRay {
    Light const* light = nullptr;  ///< null: no light in reach
    int index = -1;                ///< its place in the list searched
    float distance = kInfinity;
    RtColorRGB radiance;
    float pdf = 0.0f;
};

/// The nearest of `lights` hit by the ray (org, unit dir) closer than
/// maxDistance; a light at infinity only when maxDistance is infinite (the
/// ray left the scene). Delta lights are never hit. The camera and the
/// integrators both ask this, so they agree on what a ray sees.
inline LightAlongRay nearestLightAlong(std::vector<Light const*> const& lights, Vec3 const& org, Vec3 const& dir,
                                       float maxDistance) {
    LightAlongRay nearest;
    for (size_t k = 0; k < lights.size(); ++k) {
        Light const* light = lights[k];
        if (light->isDelta()) continue;
        LightAlongRay candidate;
        if (!light->intersect(org, dir, candidate.distance, candidate.radiance, candidate.pdf)) continue;
        bool inReach = candidate.distance < maxDistance || (std::isinf(maxDistance) && light->isInfinite());
        if (inReach && (!nearest.light || candidate.distance < nearest.distance)) {
            candidate.light = light;
            candidate.index = static_cast<int>(k);
            nearest = candidate;
        }
    }
    return nearest;
}

}  // namespace bxdflab
