// RixPredefinedStrings.hpp — names plugins use often, made once.
//
// RenderMan's header of the same name declares hundreds of RtUStrings in
// namespace Rix; plugins write `Rix::k_st` instead of building RtUString("st")
// on every call. This is the part of it a shading plugin needs: the standard
// primvar names and the coordinate-system names. Each source that includes it
// gets its own copies, made when the plugin is loaded.
//
//   RtFloat2 const* st;
//   RtFloat const* radius;
//   sCtx->GetPrimVar(Rix::k_st, RtFloat2(0.0f, 0.0f), &st, &radius);
#pragma once

#include "RiTypesHelper.h"

namespace Rix {

/// The empty string: what a string parameter left alone holds.
static RtUString const k_empty("");

// Standard primvars (RIB: "P", "N", "Cs", "Os", "st", ...).
static RtUString const k_P("P");
static RtUString const k_N("N");
static RtUString const k_Cs("Cs");
static RtUString const k_Os("Os");
static RtUString const k_st("st");  ///< texture coordinates; every shape has them (its (s, t) builtins)
static RtUString const k_s("s");
static RtUString const k_t("t");
static RtUString const k_width("width");
static RtUString const k_constantwidth("constantwidth");
// Reference positions and normals (an undeformed copy of the surface, for
// texturing that sticks to a deforming shape), as exporters name them.
static RtUString const k_Pref("__Pref");
static RtUString const k_Nref("__Nref");
static RtUString const k_WPref("__WPref");
static RtUString const k_WNref("__WNref");

// Coordinate systems, as RIB names them.
static RtUString const k_current("current");
static RtUString const k_world("world");
static RtUString const k_object("object");
static RtUString const k_camera("camera");
static RtUString const k_screen("screen");
static RtUString const k_raster("raster");
static RtUString const k_NDC("NDC");

}  // namespace Rix
