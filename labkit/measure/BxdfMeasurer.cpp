#include "measure/BxdfMeasurer.h"

#include <cstdlib>

namespace bxdflab {

namespace {

char const kVaryingMark[] = "# each value varies from point to point, starting at share ";
char const kColoursVaryingMark[] = "# each colour varies from point to point, starting at share ";
char const kTogetherMark[] = "# asked by two threads at once, rounds: ";

std::string withMark(std::string const& mark, int number, std::string const& params) {
    return mark + std::to_string(number) + "\n" + params;
}

/// The number of `mark` on the first line of `params`, which loses that line.
std::optional<int> takeMark(std::string const& mark, std::string& params) {
    size_t const end = params.find('\n');
    if (params.rfind(mark, 0) != 0 || end == std::string::npos) return std::nullopt;
    char const* digits = params.c_str() + mark.size();
    char* stop = nullptr;
    long const number = std::strtol(digits, &stop, 10);
    if (stop == digits || stop != params.c_str() + end) return std::nullopt;  // not our mark after all
    params.erase(0, end + 1);
    return static_cast<int>(number);
}

}  // namespace

std::string varyingParams(std::string const& params, int firstShare) {
    return withMark(kVaryingMark, firstShare, params);
}

std::string varyingColours(std::string const& params) { return withMark(kColoursVaryingMark, 0, params); }

std::optional<VaryingMark> takeVaryingMark(std::string& params) {
    if (std::optional<int> const share = takeMark(kVaryingMark, params)) return VaryingMark{*share, false};
    if (std::optional<int> const share = takeMark(kColoursVaryingMark, params)) return VaryingMark{*share, true};
    return std::nullopt;
}

std::string askedTogether(std::string const& params, int rounds) { return withMark(kTogetherMark, rounds, params); }

std::optional<int> takeTogetherMark(std::string& params) { return takeMark(kTogetherMark, params); }

std::vector<SampleSpec> stratifiedSamples(size_t count, uint32_t seed, uint32_t first) {
    std::vector<SampleSpec> samples(count);
    for (size_t i = 0; i < count; ++i)
        samples[i] = {RixRNG::Hash(seed ^ 0x3c6ef372u), first + static_cast<uint32_t>(i), 0, -1.0f, -1.0f};
    return samples;
}

std::vector<SampleSpec> independentSamples(size_t count, uint32_t seed, uint32_t first) {
    // An independently scrambled sequence per point makes its first sample uniform random.
    std::vector<SampleSpec> samples(count);
    for (size_t i = 0; i < count; ++i) {
        uint32_t index = first + static_cast<uint32_t>(i);
        samples[i] = {RixRNG::Hash(seed ^ RixRNG::Hash(index + 0x9e3779b9u)), 0, 0, -1.0f, -1.0f};
    }
    return samples;
}

std::vector<SampleSpec> fixedSamples(size_t count, RtFloat2 xi, float choice) {
    return std::vector<SampleSpec>(count, SampleSpec{0u, 0u, 0u, xi.x, xi.y, choice});
}

}  // namespace bxdflab
