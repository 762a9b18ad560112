#include "parse/RequestNames.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <vector>

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

std::string lowered(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

/// Levenshtein distance (insertions, deletions, substitutions).
size_t editDistance(std::string const& a, std::string const& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            size_t const above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

bool isRibRequest(std::string const& name) {
    return std::find(kRequests.begin(), kRequests.end(), name) != kRequests.end();
}

std::string likelyRibRequest(std::string const& name) {
    std::string const wanted = lowered(name);
    std::string best;
    size_t bestDistance = 3;  // more than two letters off is no longer a slip
    for (char const* request : kRequests) {
        size_t const distance = editDistance(wanted, lowered(request));
        if (distance < bestDistance) {
            bestDistance = distance;
            best = request;
        }
    }
    return best;
}

}  // namespace bxdflab
