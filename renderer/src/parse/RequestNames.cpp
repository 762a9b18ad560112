#include "parse/RequestNames.h"

#include <algorithm>
#include <array>
#include <vector>

#include "core/Spelling.h"

namespace bxdflab {
namespace {

constexpr std::array kRequests = {
    // Options, camera and frames.
    "version",
    "Declare",
    "FrameBegin",
    "FrameEnd",
    "WorldBegin",
    "WorldEnd",
    "Format",
    "FrameAspectRatio",
    "ScreenWindow",
    "CropWindow",
    "Projection",
    "Clipping",
    "ClippingPlane",
    "DepthOfField",
    "Shutter",
    "PixelVariance",
    "PixelSamples",
    "PixelFilter",
    "Exposure",
    "Imager",
    "Quantize",
    "Display",
    "DisplayChannel",
    "Hider",
    "ColorSamples",
    "RelativeDetail",
    "Option",
    "Camera",
    "Integrator",
    "DisplayFilter",
    "SampleFilter",
    "PixelSampleImager",
    // Attributes and shading.
    "AttributeBegin",
    "AttributeEnd",
    "Attribute",
    "Color",
    "Opacity",
    "TextureCoordinates",
    "LightSource",
    "AreaLightSource",
    "Illuminate",
    "Surface",
    "Displacement",
    "Atmosphere",
    "Interior",
    "Exterior",
    "ShadingRate",
    "ShadingInterpolation",
    "Matte",
    "Bound",
    "Detail",
    "DetailRange",
    "GeometricApproximation",
    "GeometricRepresentation",
    "Orientation",
    "ReverseOrientation",
    "Sides",
    "Shader",
    "Bxdf",
    "Pattern",
    "Light",
    "LightFilter",
    "EnableLightFilter",
    "Displace",
    "ShaderLayer",
    "ConnectShaderLayers",
    "VPAtmosphere",
    "VPInterior",
    "VPSurface",
    "VolumePixelSamples",
    // Transformations.
    "Identity",
    "Transform",
    "ConcatTransform",
    "Perspective",
    "Translate",
    "Rotate",
    "Scale",
    "Skew",
    "Deformation",
    "CoordinateSystem",
    "ScopedCoordinateSystem",
    "CoordSysTransform",
    "TransformBegin",
    "TransformEnd",
    // Geometry.
    "Polygon",
    "GeneralPolygon",
    "PointsPolygons",
    "PointsGeneralPolygons",
    "Basis",
    "Patch",
    "PatchMesh",
    "NuPatch",
    "TrimCurve",
    "SubdivisionMesh",
    "HierarchicalSubdivisionMesh",
    "Sphere",
    "Cone",
    "Cylinder",
    "Hyperboloid",
    "Paraboloid",
    "Disk",
    "Torus",
    "Points",
    "Curves",
    "Blobby",
    "Procedural",
    "Procedural2",
    "Geometry",
    "Volume",
    "SolidBegin",
    "SolidEnd",
    "ObjectBegin",
    "ObjectEnd",
    "ObjectInstance",
    "MotionBegin",
    "MotionEnd",
    // Textures, archives, resources, conditionals, editing.
    "MakeTexture",
    "MakeBump",
    "MakeLatLongEnvironment",
    "MakeCubeFaceEnvironment",
    "MakeShadow",
    "MakeBrickMap",
    "MakeOcclusion",
    "ArchiveRecord",
    "ReadArchive",
    "ArchiveBegin",
    "ArchiveEnd",
    "IfBegin",
    "ElseIf",
    "Else",
    "IfEnd",
    "ErrorHandler",
    "Resource",
    "ResourceBegin",
    "ResourceEnd",
    "System",
    "EditBegin",
    "EditEnd",
    "EditWorldBegin",
    "EditWorldEnd",
    "EditAttributeBegin",
    "EditAttributeEnd",
};

// Directives of pbrt's scene format (versions 2 to 4), which looks like RIB
// but is not, that RIB has no request of the same name for.
constexpr std::array kPbrtDirectives = {
    "LookAt",         "Film",        "Sampler", "Shape",           "Material",          "MakeNamedMaterial",
    "NamedMaterial",  "Accelerator", "Texture", "MakeNamedMedium", "MediumInterface",   "ActiveTransform",
    "TransformTimes", "Include",     "Import",  "ColorSpace",      "SurfaceIntegrator", "VolumeIntegrator",
    "Renderer",
};

}  // namespace

bool isPbrtDirective(std::string const& name) {
    return std::find(kPbrtDirectives.begin(), kPbrtDirectives.end(), name) != kPbrtDirectives.end();
}

bool isRibRequest(std::string const& name) {
    return std::find(kRequests.begin(), kRequests.end(), name) != kRequests.end();
}

std::string likelyRibRequest(std::string const& name) {
    static std::vector<std::string> const requests(kRequests.begin(), kRequests.end());
    return closestSpelling(name, requests);
}

}  // namespace bxdflab
