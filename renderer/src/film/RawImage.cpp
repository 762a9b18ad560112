#include "film/RawImage.h"

#include <unistd.h>

#include <cerrno>
#include <cstddef>

#include "render/Film.h"

namespace bxdflab {

bool writeRawImage(int fd, Film const& film) {
    RawImageHeader header;
    header.width = static_cast<uint32_t>(film.width());
    header.height = static_cast<uint32_t>(film.height());
    std::vector<float> rgba = film.rgba(), variance = film.varianceOfMean();
    size_t pixels = static_cast<size_t>(film.width()) * static_cast<size_t>(film.height());
    std::vector<float> out;
    out.reserve(pixels * RawImageHeader::kChannels);
    for (size_t p = 0; p < pixels; ++p) {
        out.insert(out.end(), rgba.begin() + static_cast<std::ptrdiff_t>(4 * p), rgba.begin() + static_cast<std::ptrdiff_t>(4 * p + 4));
        out.insert(out.end(), variance.begin() + static_cast<std::ptrdiff_t>(3 * p),
                   variance.begin() + static_cast<std::ptrdiff_t>(3 * p + 3));
    }
    auto writeAll = [fd](void const* data, size_t bytes) {
        char const* p = static_cast<char const*>(data);
        while (bytes > 0) {
            ssize_t n = ::write(fd, p, bytes);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) return false;
            p += n;
            bytes -= static_cast<size_t>(n);
        }
        return true;
    };
    return writeAll(&header, sizeof header) && writeAll(out.data(), out.size() * sizeof(float));
}

}  // namespace bxdflab
