// RenderMan's camera: left-handed camera space looking down +z with +y up;
// the field of view spans the shorter image axis; raster (0,0) is the top
// left corner of the image.
#pragma once

#include "core/Math.h"
#include "scene/Scene.h"

namespace bxdflab {

class Camera {
public:
    Camera(CameraDesc const& desc, int xres, int yres, float pixelAspect);
    /// The world-space ray through raster position (x, y) (pixels, fractional).
    void generateRay(float rasterX, float rasterY, Vec3& org, Vec3& dir) const;
    /// False only when no camera ray can reach the sphere (center, radius):
    /// it lies behind the camera or wholly outside the image's frustum.
    bool mightSee(Vec3 const& center, float radius) const;
    /// The angle (radians) one pixel subtends at the image centre.
    float pixelSpread() const { return m_pixelSpread; }
    Vec3 position() const { return m_position; }

private:
    Mat4 m_cameraToWorld;
    Mat4 m_worldToCamera;
    Vec3 m_position;
    bool m_perspective;
    float m_tanHalfFov;
    float m_screen[4];  // left right bottom top
    int m_xres, m_yres;
    float m_pixelSpread;
};

}  // namespace bxdflab
