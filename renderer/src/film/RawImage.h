// The raw image rixrender writes to a descriptor with --raw-out-fd, for a
// program that reads the pixels directly (the autograder reads a sandboxed
// render this way): a header, then width x height pixels of 7 floats each,
// row-major from the top left -- red, green, blue, alpha of the mean, then
// red, green, blue of the variance of the mean.
#pragma once

#include <cstdint>
#include <vector>

namespace bxdflab {

struct RawImageHeader {
    static constexpr uint32_t kMagic = 0x4d495852u;  // "RXIM"
    static constexpr uint32_t kChannels = 7;
    uint32_t magic = kMagic, width = 0, height = 0, channels = kChannels;
};

class Film;
/// Writes the film to descriptor fd; returns false if the write failed.
bool writeRawImage(int fd, Film const& film);

}  // namespace bxdflab
