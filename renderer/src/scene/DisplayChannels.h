// What a Display's mode asks to be written: the image's channels, each read
// either from the shaded result (colour, alpha) or from the surface the
// camera saw (depth, position, normals, surface parameters).
//
//   Display "beauty.exr" "openexr" "rgba"
//   Display "+normal.exr" "openexr" "N"
//   Display "+depth.exr" "openexr" "z"
//
// A mode is one name or several separated by commas ("Ci,a,z"); "rgb", "a"
// and "z" also combine without commas ("rgbaz"), as the RenderMan Interface
// writes them. A name may carry a type ("normal N"), which is not needed.
#pragma once

#include <string>
#include <vector>

namespace bxdflab {

/// Where a channel's value comes from.
enum class Quantity {
    Color,  ///< the shaded colour (Ci)
    Alpha,  ///< coverage
    Depth,  ///< camera-space z of the nearest surface the pixel's samples saw
    P,      ///< position, camera space
    N,      ///< shading normal, camera space
    Ng,     ///< geometric normal, camera space
    S,
    T,
    U,
    V
};

struct DisplayChannel {
    Quantity quantity;
    int component;     ///< 0-2 for the three-component quantities, else 0
    std::string name;  ///< the name the image file gives the channel (R, G, B, A, Z, N.x, ...)
};

struct DisplayLayout {
    std::vector<DisplayChannel> channels;
    std::string unknown;  ///< the first name of the mode not understood here (then channels is empty)
    /// Whether any channel is read from the surface rather than the shaded result.
    bool needsSurface() const;
    /// Whether the layout is the shaded image alone (rgb, rgba, Ci, a, ...).
    bool shadedOnly() const { return !channels.empty() && !needsSurface(); }
};

/// The channels a Display mode asks for.
DisplayLayout displayLayout(std::string const& mode);

/// The names displayLayout understands, for messages.
std::string displayModeNames();

/// The surface values the camera records at each sample, for the displays
/// that ask for them: one record of `width` floats a sample, each quantity
/// at its offset (-1 when no display asks for it). Depth is kept apart: a
/// pixel's depth is its nearest sample's, where the others are means.
class SurfaceRecord {
public:
    SurfaceRecord() : SurfaceRecord(std::vector<DisplayLayout>()) {}  ///< records nothing
    explicit SurfaceRecord(std::vector<DisplayLayout> const& layouts);
    int width() const { return m_width; }
    bool needsDepth() const { return m_depth; }
    /// Whether anything at all is recorded.
    bool any() const { return m_depth || m_width > 0; }
    int offset(Quantity quantity) const { return m_offset[static_cast<int>(quantity)]; }

private:
    static constexpr int kQuantities = static_cast<int>(Quantity::V) + 1;
    int m_offset[kQuantities];
    int m_width = 0;
    bool m_depth = false;
};

}  // namespace bxdflab
