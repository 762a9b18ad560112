#include "film/Film.h"

#include <unistd.h>

#include <cerrno>


#include <algorithm>

#include "core/Error.h"
#include "film/RawImage.h"

namespace bxdflab {

Film::Film(int width, int height)
    : m_width(width), m_height(height), m_pixels(static_cast<size_t>(width) * static_cast<size_t>(height)) {}

void Film::addSample(int x, int y, RtColorRGB const& radiance, float alpha) {
    Pixel& p = m_pixels[static_cast<size_t>(y) * static_cast<size_t>(m_width) + static_cast<size_t>(x)];
    for (int c = 0; c < 3; ++c) {
        double v = radiance[c];
        p.sum[c] += v;
        p.sumSq[c] += v * v;
    }
    p.alpha += alpha;
    ++p.count;
}

std::vector<float> Film::rgba() const {
    std::vector<float> out(m_pixels.size() * 4, 0.0f);
    for (size_t i = 0; i < m_pixels.size(); ++i) {
        Pixel const& p = m_pixels[i];
        if (p.count == 0) continue;
        for (int c = 0; c < 3; ++c) out[4 * i + static_cast<size_t>(c)] = static_cast<float>(p.sum[c] / p.count);
        out[4 * i + 3] = static_cast<float>(p.alpha / p.count);
    }
    return out;
}

std::vector<float> Film::varianceOfMean() const {
    std::vector<float> out(m_pixels.size() * 3, 0.0f);
    for (size_t i = 0; i < m_pixels.size(); ++i) {
        Pixel const& p = m_pixels[i];
        if (p.count < 2) continue;
        for (int c = 0; c < 3; ++c) {
            double mean = p.sum[c] / p.count;
            double variance = std::max(0.0, (p.sumSq[c] - p.count * mean * mean) / (p.count - 1));
            out[3 * i + static_cast<size_t>(c)] = static_cast<float>(variance / p.count);
        }
    }
    return out;
}

}  // namespace bxdflab

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
