#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>

#include "core/TextureLocator.h"
#include "parse/ParamList.h"
#include "scene/lights/Light.h"

namespace bxdflab {

/// Reports a file a light names that is not there (an error or a warning, as the caller decides).
using MissingFileReport = std::function<void(SourceLocation const& where, std::string const& message)>;

/// The light a `Light "<type>" ...` statement describes, or nullptr when the
/// type is not one this renderer knows. `textures` finds the images it
/// names; a missing image goes to `missing` (the light then has its plain
/// colour), other problems with it that do not stop the render are warned about.
std::unique_ptr<Light> makeLight(std::string const& type, ParamList const& params, Mat4 const& lightToWorld,
                                 TextureLocator const& textures, SourceLocation const& where, Diagnostics& diagnostics,
                                 MissingFileReport const& missing);

/// The shadow and bookkeeping controls every RIS light has. enableShadows 0 turns the light's
/// shadows off; "diffuse" and "specular" scale what diffuse and specular lobes take straight from
/// the light (a negative or non-finite multiplier is an error at `where`). The others are taken where their value changes nothing here (a light group only
/// names an AOV; the rest at their defaults); a value that would change the image stays unread,
/// so that the caller's "not used" warning names it. makeLight applies it; an area light whose
/// shape comes later (PxrMeshLight, RenderMan 20's PxrStdAreaLight) is given it with its shape.
void readCommonLightControls(ParamList const& params, Light& light, SourceLocation const& where);

/// A classic light shader's "__nondiffuse" and "__nonspecular": set to 1, the shading language's
/// diffuse() or specular() leaves the light out, which is a multiplier of 0 for those lobes.
void readClassicLobeSwitches(ParamList const& params, Light& light);

/// The types of the RenderMan light parameters this renderer reads, as
/// RenderMan's own declarations give them: a RIB may write them without a
/// type ("exposure" [2]), as RenderMan types them from the light's declaration.
std::map<std::string, ParamType> const& lightParameterTypes();

/// What a RenderMan (RIS) light's parameters make of its radiance:
/// intensity * 2^exposure * lightColor, tinted by a black body's colour when
/// enableTemperature is on.
Vec3 risLightRadiance(std::string const& type, ParamList const& params, SourceLocation const& where);

/// What the shape of a classic area light shader emits, its area given: for
/// RenderMan 16's physically plausible plausibleArealight the radiance
/// intensity * lightcolor (per unit area under "areanormalize"); for the older
/// ones (BMRT's arealight) pi intensity * lightcolor / area, which gives what a
/// point light of that intensity would whatever the size (the pi as for every
/// classic light: the classic diffuse() has no 1/pi).
Vec3 classicAreaLightRadiance(std::string const& shader, ParamList const& params, float area);

/// The classic light shaders of a LightSource request: "pointlight",
/// "spotlight" and "distantlight" become lights; "ambientlight" adds its
/// colour to `ambient` (the classic surface shaders' Ka term) and makes no
/// light. Another shader is placed by its name when it says spot, distant
/// (direction, sun) or point (omni), else by its parameters when they say
/// enough (a cone: a spot; "to": a distant light; "from" alone: a point);
/// else nullptr. A shader whose name says it is an area light ("arealight")
/// becomes a light of the shape its "shape" names, without geometry, emitting
/// what classicAreaLightRadiance says. `guess`
/// says what a shader placed in one of these ways was taken for ("skipped"
/// when nothing), and is empty for the standard ones. A light
/// that cannot shine (a distant light whose "from" and "to" coincide, so it
/// has no direction) is also nullptr, with the reason in `leftOut`: the file
/// still renders, as it does in RenderMan, where such a light adds nothing.
/// Intensities are scaled by pi: the classic shaders' diffuse() has no 1/pi,
/// the physically based Bxdfs do, so this keeps their images as bright. As
/// then, the light casts shadows only when given a shadow map or told to trace
/// them (a non-empty "shadowname", a "raytraceshadow" of 1).
std::unique_ptr<Light> makeClassicLight(std::string const& shader, ParamList const& params, Mat4 const& lightToWorld,
                                        SourceLocation const& where, Vec3& ambient, std::string& guess,
                                        std::string& leftOut);

}  // namespace bxdflab
