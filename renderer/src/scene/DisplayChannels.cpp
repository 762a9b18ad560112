#include "scene/DisplayChannels.h"

#include <algorithm>
#include <regex>
#include <sstream>

namespace bxdflab {
namespace {

/// The named quantities a mode may list, with the channel names an image gives their components.
struct NamedQuantity {
    char const* name;
    Quantity quantity;
    std::vector<char const*> channels;
};

std::vector<NamedQuantity> const& namedQuantities() {
    static std::vector<NamedQuantity> const table = {
        {"Ci", Quantity::Color, {"R", "G", "B"}},
        {"alpha", Quantity::Alpha, {"A"}},
        {"P", Quantity::P, {"P.x", "P.y", "P.z"}},
        {"N", Quantity::N, {"N.x", "N.y", "N.z"}},
        {"Nn", Quantity::N, {"Nn.x", "Nn.y", "Nn.z"}},
        {"Ng", Quantity::Ng, {"Ng.x", "Ng.y", "Ng.z"}},
        {"s", Quantity::S, {"s"}},
        {"t", Quantity::T, {"t"}},
        {"u", Quantity::U, {"u"}},
        {"v", Quantity::V, {"v"}},
    };
    return table;
}

std::string trimmed(std::string const& text) {
    size_t const first = text.find_first_not_of(" \t");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

/// Adds the channels of one name of a mode; false when the name is not known.
bool addChannels(std::string const& name, std::vector<DisplayChannel>& out) {
    // The RenderMan Interface's letters: rgb, a and z in that order, each optional.
    static std::regex const letters("(rgb)?(a)?(z)?");
    std::smatch match;
    if (std::regex_match(name, match, letters)) {
        if (match[1].matched)
            for (int c = 0; c < 3; ++c) out.push_back({Quantity::Color, c, std::string(1, "RGB"[c])});
        if (match[2].matched) out.push_back({Quantity::Alpha, 0, "A"});
        if (match[3].matched) out.push_back({Quantity::Depth, 0, "Z"});
        return true;
    }
    for (NamedQuantity const& named : namedQuantities())
        if (name == named.name) {
            for (size_t c = 0; c < named.channels.size(); ++c)
                out.push_back({named.quantity, static_cast<int>(c), named.channels[c]});
            return true;
        }
    return false;
}

}  // namespace

bool DisplayLayout::needsSurface() const {
    return std::any_of(channels.begin(), channels.end(), [](DisplayChannel const& channel) {
        return channel.quantity != Quantity::Color && channel.quantity != Quantity::Alpha;
    });
}

DisplayLayout displayLayout(std::string const& mode) {
    DisplayLayout layout;
    std::stringstream names(mode);
    for (std::string name; std::getline(names, name, ',');) {
        name = trimmed(name);
        // "normal N", "color Ci": the type a declaration would give is not needed.
        size_t const space = name.find_last_of(" \t");
        if (space != std::string::npos) name = name.substr(space + 1);
        if (name.empty()) continue;
        if (!addChannels(name, layout.channels)) {
            layout.channels.clear();
            layout.unknown = name;
            return layout;
        }
    }
    if (layout.channels.empty()) layout.unknown = "(nothing)";  // a blank mode
    return layout;
}

std::string displayModeNames() {
    std::string names = "rgb, rgba, a, z (and their combinations such as rgbaz)";
    for (NamedQuantity const& named : namedQuantities()) names += std::string(", ") + named.name;
    return names;
}

SurfaceRecord::SurfaceRecord(std::vector<DisplayLayout> const& layouts) {
    std::fill(std::begin(m_offset), std::end(m_offset), -1);
    for (DisplayLayout const& layout : layouts)
        for (DisplayChannel const& channel : layout.channels) {
            Quantity const q = channel.quantity;
            if (q == Quantity::Color || q == Quantity::Alpha) continue;
            if (q == Quantity::Depth) {
                m_depth = true;
                continue;
            }
            int& offset = m_offset[static_cast<int>(q)];
            if (offset >= 0) continue;
            offset = m_width;
            m_width += q == Quantity::P || q == Quantity::N || q == Quantity::Ng ? 3 : 1;
        }
}

}  // namespace bxdflab
