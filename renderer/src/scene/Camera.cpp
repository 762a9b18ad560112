#include "scene/Camera.h"

#include <cmath>

namespace bxdflab {

Camera::Camera(CameraDesc const& desc, int xres, int yres, float pixelAspect)
    : m_cameraToWorld(glm::inverse(desc.worldToCamera)),
      m_perspective(desc.projection != "orthographic"),
      m_tanHalfFov(std::tan(0.5f * desc.fov * kPi / 180.0f)),
      m_xres(xres),
      m_yres(yres) {
    m_position = transformPoint(m_cameraToWorld, Vec3(0.0f));
    if (desc.hasScreenWindow) {
        for (int i = 0; i < 4; ++i) m_screen[i] = desc.screenWindow[i];
    } else {
        // The shorter axis spans [-1, 1]; the longer one keeps the aspect ratio.
        float aspect = static_cast<float>(xres) * pixelAspect / static_cast<float>(yres);
        float sx = aspect >= 1.0f ? aspect : 1.0f, sy = aspect >= 1.0f ? 1.0f : 1.0f / aspect;
        m_screen[0] = -sx;
        m_screen[1] = sx;
        m_screen[2] = -sy;
        m_screen[3] = sy;
    }
    float screenHeight = m_screen[3] - m_screen[2];
    m_pixelSpread = m_perspective ? 2.0f * std::atan(0.5f * screenHeight * m_tanHalfFov / static_cast<float>(yres)) : 0.0f;
}

void Camera::generateRay(float rasterX, float rasterY, Vec3& org, Vec3& dir) const {
    float sx = m_screen[0] + (m_screen[1] - m_screen[0]) * rasterX / static_cast<float>(m_xres);
    float sy = m_screen[3] - (m_screen[3] - m_screen[2]) * rasterY / static_cast<float>(m_yres);
    if (m_perspective) {
        org = m_position;
        dir = glm::normalize(transformVector(m_cameraToWorld, Vec3(sx * m_tanHalfFov, sy * m_tanHalfFov, 1.0f)));
    } else {
        org = transformPoint(m_cameraToWorld, Vec3(sx, sy, 0.0f));
        dir = glm::normalize(transformVector(m_cameraToWorld, Vec3(0.0f, 0.0f, 1.0f)));
    }
}

}  // namespace bxdflab
