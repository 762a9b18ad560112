#include "checks/CheckSupport.h"

#include <cmath>
#include <cstdio>

namespace bxdflab::checks {

Frame::Frame(float degrees) {
    Vec3 axis = glm::normalize(Vec3(1.0f, 2.0f, 3.0f));
    float angle = glm::radians(degrees), c = std::cos(angle), s = std::sin(angle);
    Mat3 K(0.0f, axis.z, -axis.y, -axis.z, 0.0f, axis.x, axis.y, -axis.x, 0.0f);  // columns of [axis]x
    m_R = Mat3(1.0f) + s * K + (1.0f - c) * (K * K);
}

ProbePoint Frame::point(Vec3 const& localV) const { return point(localV, defaultTangent()); }

ProbePoint Frame::bentPoint(Vec3 const& localV) const {
    return point(localV, bentGeometricNormal(), defaultTangent());
}

ProbePoint Frame::point(Vec3 const& localV, Vec3 const& localTangent) const {
    return point(localV, Vec3(0.0f, 0.0f, 1.0f), localTangent);
}

ProbePoint Frame::point(Vec3 const& localV, Vec3 const& localNg, Vec3 const& localTangent) const {
    ProbePoint p;
    p.N = toWorld(Vec3(0.0f, 0.0f, 1.0f));
    p.Ng = toWorld(localNg);
    p.dPdu = toWorld(localTangent);
    p.V = toWorld(localV);
    return p;
}

Frame const& frame() {
    static Frame const f;
    return f;
}

Vec3 direction(double thetaDegrees, double phiDegrees) {
    double t = thetaDegrees * M_PI / 180.0, p = phiDegrees * M_PI / 180.0;
    return Vec3(static_cast<float>(std::sin(t) * std::cos(p)), static_cast<float>(std::sin(t) * std::sin(p)),
                static_cast<float>(std::cos(t)));
}

Vec3 bentGeometricNormal() { return direction(20, 250); }

ProbePoint viewFrom(double thetaDegrees, double phiDegrees) {
    ProbePoint point;
    point.V = direction(thetaDegrees, phiDegrees);
    return point;
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", v);
    return text;
}

std::string describeDirection(Vec3 const& w) {
    double length = glm::length(w);
    if (!(length > 0.0) || !std::isfinite(length)) return "(" + number(w.x) + ", " + number(w.y) + ", " + number(w.z) + ")";
    double theta = std::acos(std::max(-1.0, std::min(1.0, w.z / length))) * 180.0 / M_PI;
    double phi = std::atan2(w.y, w.x) * 180.0 / M_PI;
    if (phi < 0) phi += 360.0;
    char text[64];
    std::snprintf(text, sizeof text, "theta %.1f deg, phi %.0f deg", theta, phi);
    return text;
}

std::string describe(RtColorRGB const& c) { return "(" + number(c.r) + ", " + number(c.g) + ", " + number(c.b) + ")"; }

bool close(double a, double b, double relative, double absolute) {
    if (!std::isfinite(a) || !std::isfinite(b)) return a == b;
    return std::fabs(a - b) <= std::max(relative * std::max(std::fabs(a), std::fabs(b)), absolute);
}

namespace {
constexpr double kSteps[] = {8e-3, 4e-3, 2e-3, 1e-3, 5e-4};
constexpr int kStepCount = 5;
}  // namespace

std::vector<RtFloat2> const& jacobianOffsets() {
    static std::vector<RtFloat2> const offsets = [] {
        std::vector<RtFloat2> o = {RtFloat2(0.0f, 0.0f)};
        for (double h : kSteps) {
            float f = static_cast<float>(h);
            o.insert(o.end(), {RtFloat2(f, 0.0f), RtFloat2(-f, 0.0f), RtFloat2(0.0f, f), RtFloat2(0.0f, -f)});
        }
        return o;
    }();
    return offsets;
}

bool jacobianDensity(Vec3 const* w, double& density) {
    glm::dvec3 du[kStepCount], dv[kStepCount];
    double area[kStepCount];
    for (int k = 0; k < kStepCount; ++k) {
        Vec3 const* s = w + 1 + 4 * k;
        for (int j = 0; j < 4; ++j)
            if (!isFinite(s[j]) || !(glm::length(s[j]) > 0.0f)) return false;
        auto unit = [&](int j) { return glm::dvec3(glm::normalize(s[j])); };
        du[k] = (unit(0) - unit(1)) / (2 * kSteps[k]);
        dv[k] = (unit(2) - unit(3)) / (2 * kSteps[k]);
        area[k] = glm::length(glm::cross(du[k], dv[k]));
    }
    double best = 1e30, bestArea = 0.0;
    for (int k = 0; k + 1 < kStepCount; ++k) {
        if (!(area[k + 1] > 0.0)) continue;
        double disagreement = std::fabs(area[k] - area[k + 1]) / area[k + 1];
        if (disagreement < best) {
            best = disagreement;
            bestArea = glm::length(glm::cross((4.0 * du[k + 1] - du[k]) / 3.0, (4.0 * dv[k + 1] - dv[k]) / 3.0));
        }
    }
    if (!(best <= 0.05) || !(bestArea > 0.0)) return false;
    density = 1.0 / bestArea;
    return true;
}

std::string withParams(std::string const& params) {
    return params.empty() ? "with the default parameters" : "with " + params;
}

std::string notAttempted(CheckContext& context) {
    std::string const& params = context.exercise.params;
    Frame const& f = frame();
    ProbePoint point = f.point(direction(30, 20));
    auto evaluated = context.plugin.evaluate(params, {point, point}, {f.toWorld(direction(30, 200)), f.toWorld(direction(10, 90))});
    for (auto const& r : evaluated)
        if (!r.W.IsBlack()) return "";
    for (auto const& g : context.plugin.generate(params, std::vector<ProbePoint>(16, point), stratifiedSamples(16, 1)))
        if (g.valid) return "";
    for (auto const& e : context.plugin.emission(params, {point}))
        if (!e.IsBlack()) return "";
    return "your plugin returns no light and no samples yet: are the TODO bodies still empty?";
}

}  // namespace bxdflab::checks
