// Where light tracing adds what light subpaths bring to the camera: any pixel,
// from any thread (the film implements it).
#pragma once

#include <cstdint>

#include "RiTypesHelper.h"

namespace bxdflab {

class SplatTarget {
public:
    virtual ~SplatTarget() = default;
    virtual int width() const = 0;
    virtual int height() const = 0;
    virtual void addSplat(int x, int y, RtColorRGB const& value) = 0;
    /// How many light subpaths could have added: the image gets the sum divided by this.
    virtual void countSplatPaths(uint64_t paths) = 0;
};

}  // namespace bxdflab
