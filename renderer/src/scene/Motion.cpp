#include "scene/Motion.h"

#include <algorithm>
#include <cmath>

namespace bxdflab {

void bracket(std::vector<float> const& times, float time, size_t& earlier, size_t& later, float& fraction) {
    later = static_cast<size_t>(std::upper_bound(times.begin(), times.end(), time) - times.begin());
    earlier = later == 0 ? 0 : later - 1;
    later = std::min(later, times.size() - 1);
    fraction = later == earlier ? 0.0f : (time - times[earlier]) / (times[later] - times[earlier]);
}

Mat4 TransformPath::at(float time) const {
    size_t earlier, later;
    float f;
    bracket(times, time, earlier, later, f);
    return (1.0f - f) * transforms[earlier] + f * transforms[later];
}

std::vector<float> shutterSteps(std::vector<float> const& times, float open, float close) {
    constexpr int kMostSteps = 33;
    float closest = close - open;
    for (size_t i = 1; i < times.size(); ++i)
        if (times[i] > times[i - 1]) closest = std::min(closest, times[i] - times[i - 1]);
    // A small tolerance keeps times that divide the shutter evenly from asking for one step more.
    int const intervals = std::clamp(static_cast<int>(std::ceil((close - open) / closest - 1e-3f)), 1, kMostSteps - 1);
    std::vector<float> steps(static_cast<size_t>(intervals + 1));
    for (int k = 0; k <= intervals; ++k)
        steps[static_cast<size_t>(k)] = open + (close - open) * static_cast<float>(k) / static_cast<float>(intervals);
    return steps;
}

std::shared_ptr<ShapeMotion const> shapeMotion(TransformPath const& path, float open, float close) {
    if (!(close > open)) return nullptr;
    Mat4 const back = glm::inverse(path.at(open));
    auto motion = std::make_shared<ShapeMotion>();
    bool moves = false;
    for (float time : shutterSteps(path.times, open, close)) {
        motion->steps.push_back(path.at(time) * back);
        Mat4 const& step = motion->steps.back();
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) moves = moves || std::fabs(step[i][j] - (i == j ? 1.0f : 0.0f)) > 1e-6f;
    }
    return moves ? motion : nullptr;
}

}  // namespace bxdflab
