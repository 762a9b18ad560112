// The benchmark's ray log: every ray a render traces, recorded through the
// tracer's observer, then traced again by Embree alone. The time of that
// replay is what ray tracing itself costs; everything else is overhead.
#pragma once

#include <vector>

#include "accel/RayTracer.h"

namespace bxdflab {

class RayRecording final : public RayTracer::Observer {
public:
    struct Ray {
        Vec3 org, dir;
        float tnear, tfar;
        RayKind kind;
        bool occlusion;
    };

    void traced(Vec3 const& org, Vec3 const& dir, float tnear, float tfar, RayKind kind, bool occlusion) override {
        m_rays.push_back({org, dir, tnear, tfar, kind, occlusion});
    }
    std::vector<Ray> const& rays() const { return m_rays; }
    size_t occlusionRays() const;

    /// Traces every recorded ray with rtcIntersect1 / rtcOccluded1 against the
    /// tracer's own Embree scenes; returns how many hit something.
    size_t replay(RayTracer const& tracer) const;

private:
    std::vector<Ray> m_rays;
};

}  // namespace bxdflab
