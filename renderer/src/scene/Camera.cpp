#include "scene/Camera.h"

#include <cmath>

namespace bxdflab {

Camera::Camera(CameraDesc const& desc, int xres, int yres, float pixelAspect, float shutterOpen,
               float shutterClose)
    : m_cameraToWorld(glm::inverse(desc.worldToCamera)),
      m_worldToCamera(desc.worldToCamera),
      m_perspective(desc.projection != "orthographic"),
      m_tanHalfFov(std::tan(0.5f * desc.fov * kPi / 180.0f)),
      m_xres(xres),
      m_yres(yres),
      m_lensRadius(desc.lensRadius()),
      m_focalDistance(desc.focalDistance),
      m_clipNear(desc.clipNear),
      m_clipFar(desc.clipFar) {
    m_position = transformPoint(m_cameraToWorld, Vec3(0.0f));
    m_depthAlong = Vec3(m_worldToCamera[0][2], m_worldToCamera[1][2], m_worldToCamera[2][2]);
    if (desc.hasScreenWindow) {
        for (int i = 0; i < 4; ++i) m_screen[i] = desc.screenWindow[i];
    } else {
        // The shorter axis spans [-1, 1]; the longer one keeps the frame's aspect ratio, which is the
        // image's unless FrameAspectRatio says otherwise (the image is then stretched to fit, as the
        // RenderMan Interface specifies).
        float aspect = desc.frameAspectRatio > 0.0f ? desc.frameAspectRatio
                                                    : static_cast<float>(xres) * pixelAspect / static_cast<float>(yres);
        float sx = aspect >= 1.0f ? aspect : 1.0f, sy = aspect >= 1.0f ? 1.0f : 1.0f / aspect;
        m_screen[0] = -sx;
        m_screen[1] = sx;
        m_screen[2] = -sy;
        m_screen[3] = sy;
    }
    float screenHeight = m_screen[3] - m_screen[2];
    m_pixelSpread = m_perspective ? 2.0f * std::atan(0.5f * screenHeight * m_tanHalfFov / static_cast<float>(yres)) : 0.0f;

    // Screen x grows with raster x from the left edge; screen y falls with
    // raster y from the top edge. Perspective rays pass through the screen
    // window scaled by tan(fov/2) on the plane z = 1; orthographic rays start on z = 0.
    float const scale = m_perspective ? m_tanHalfFov : 1.0f;
    Vec3 const topLeft(m_screen[0] * scale, m_screen[3] * scale, m_perspective ? 1.0f : 0.0f);
    Vec3 const stepX((m_screen[1] - m_screen[0]) * scale / static_cast<float>(xres), 0.0f, 0.0f);
    Vec3 const stepY(0.0f, -(m_screen[3] - m_screen[2]) * scale / static_cast<float>(yres), 0.0f);
    m_rasterOrigin = m_perspective ? transformVector(m_cameraToWorld, topLeft) : transformPoint(m_cameraToWorld, topLeft);
    m_perRasterX = transformVector(m_cameraToWorld, stepX);
    m_perRasterY = transformVector(m_cameraToWorld, stepY);
    m_orthographicDirection = glm::normalize(transformVector(m_cameraToWorld, Vec3(0.0f, 0.0f, 1.0f)));
    m_lensX = transformVector(m_cameraToWorld, Vec3(m_lensRadius, 0.0f, 0.0f));
    m_lensY = transformVector(m_cameraToWorld, Vec3(0.0f, m_lensRadius, 0.0f));
    // A path that stays put while the shutter is open needs no moving, by the same test a shape's does.
    if (desc.motion && shapeMotion(*desc.motion, shutterOpen, shutterClose)) m_motion = desc.motion;
}

float Camera::moveRay(float time, Vec3& org, Vec3& dir) const {
    if (!m_motion) return 1.0f;
    Mat4 const worldToCamera = m_motion->at(time);
    // Transforms are blended entry by entry, so a half turn between two times passes through a flat one.
    if (!(std::fabs(glm::determinant(worldToCamera)) > 1e-12f)) return 1.0f;
    Mat4 const openToThen = glm::inverse(worldToCamera) * m_worldToCamera;
    org = transformPoint(openToThen, org);
    Vec3 const moved = transformVector(openToThen, dir);
    float const stretch = glm::length(moved);
    dir = moved / stretch;
    return stretch;
}

float Camera::depthAlong(Vec3 const& dir, float t, float time) const {
    if (!m_motion) return glm::dot(m_depthAlong, dir) * t;
    Mat4 const worldToCamera = m_motion->at(time);
    return glm::dot(Vec3(worldToCamera[0][2], worldToCamera[1][2], worldToCamera[2][2]), dir) * t;
}

void Camera::generateRay(float rasterX, float rasterY, Vec3& org, Vec3& dir) const {
    Vec3 const onPlane = m_rasterOrigin + rasterX * m_perRasterX + rasterY * m_perRasterY;
    if (m_perspective) {
        org = m_position;
        dir = glm::normalize(onPlane);
    } else {
        org = onPlane;
        dir = m_orthographicDirection;
    }
}

void Camera::generateRay(float rasterX, float rasterY, RtFloat2 const& lens, Vec3& org, Vec3& dir) const {
    // The pinhole ray's direction has camera-space z 1, so it meets the focal
    // plane at focalDistance times it; every lens point's ray passes there too.
    Vec3 const onFocalPlane = m_focalDistance * (m_rasterOrigin + rasterX * m_perRasterX + rasterY * m_perRasterY);
    // A uniform point on the unit disc, by Shirley and Chiu's concentric map (it keeps strata apart).
    float const a = 2.0f * lens.x - 1.0f, b = 2.0f * lens.y - 1.0f;
    float r = 0.0f, phi = 0.0f;
    if (a * a > b * b) {
        r = a;
        phi = 0.25f * kPi * (b / a);
    } else if (b != 0.0f) {
        r = b;
        phi = 0.5f * kPi - 0.25f * kPi * (a / b);
    }
    Vec3 const onLens = r * std::cos(phi) * m_lensX + r * std::sin(phi) * m_lensY;
    org = m_position + onLens;
    dir = glm::normalize(onFocalPlane - onLens);
}

void Camera::clipRange(Vec3 const& dir, float& tnear, float& tfar) const {
    // Every camera ray starts on the plane z = 0 (at the eye, on the lens, or on the orthographic
    // image plane), so its camera-space depth grows by `along` per unit of t.
    float const along = glm::dot(m_depthAlong, dir);
    if (!(along > 0.0f)) {
        tnear = tfar = 0.0f;  // parallel to the planes: never between them
        return;
    }
    tnear = m_clipNear / along;
    tfar = m_clipFar / along;
}

bool Camera::rasterPosition(Vec3 const& P, float& rasterX, float& rasterY) const {
    Vec3 const c = transformPoint(m_worldToCamera, P);
    if (m_perspective && !(c.z > 0.0f)) return false;
    // The inverse of generateRay: the screen position of the ray through c.
    float const scale = m_perspective ? c.z * m_tanHalfFov : 1.0f;
    float const sx = c.x / scale, sy = c.y / scale;
    rasterX = (sx - m_screen[0]) / (m_screen[1] - m_screen[0]) * static_cast<float>(m_xres);
    rasterY = (m_screen[3] - sy) / (m_screen[3] - m_screen[2]) * static_cast<float>(m_yres);
    return true;
}

bool Camera::project(Vec3 const& P, float& rasterX, float& rasterY, Vec3& toEye, float& distance,
                     float& directionPdf) const {
    if (!m_perspective || !rasterPosition(P, rasterX, rasterY)) return false;
    if (!(rasterX >= 0.0f && rasterX < static_cast<float>(m_xres) && rasterY >= 0.0f &&
          rasterY < static_cast<float>(m_yres)))
        return false;
    Vec3 const c = transformPoint(m_worldToCamera, P);
    Vec3 toward = m_position - P;
    distance = glm::length(toward);
    if (!(distance > 0.0f)) return false;
    toEye = toward / distance;
    float cosTheta = c.z / glm::length(c);
    float imagePlaneArea = (m_screen[1] - m_screen[0]) * (m_screen[3] - m_screen[2]) * m_tanHalfFov * m_tanHalfFov;
    directionPdf = 1.0f / (imagePlaneArea * cosTheta * cosTheta * cosTheta);
    return true;
}

bool Camera::mightSee(Vec3 const& center, float radius) const {
    if (m_motion) return true;
    // In camera space, where the rays are made. A transform that scales makes
    // the sphere an ellipsoid: the Frobenius norm bounds how much it grows.
    Mat3 linear(m_worldToCamera);
    float growth = std::sqrt(glm::dot(linear[0], linear[0]) + glm::dot(linear[1], linear[1]) + glm::dot(linear[2], linear[2]));
    Vec3 c = transformPoint(m_worldToCamera, center);
    // A margin for rounding: only a sphere clearly outside is ruled out.
    float r = 1.01f * radius * growth + 1e-4f * (1.0f + glm::length(c));
    if (c.z < -r) return false;  // behind the camera (every ray goes toward +z)
    float const left = m_screen[0], right = m_screen[1], bottom = m_screen[2], top = m_screen[3];
    if (!m_perspective)  // parallel rays through the screen window
        return c.x + r >= left && c.x - r <= right && c.y + r >= bottom && c.y - r <= top;
    // Four planes through the eye bound the rays' directions (x, y, 1) * tan:
    // each inward normal n; the sphere is outside when dot(n, c) < -r.
    auto inside = [&](Vec3 const& n) { return glm::dot(glm::normalize(n), c) >= -r; };
    return inside(Vec3(1.0f, 0.0f, -left * m_tanHalfFov)) && inside(Vec3(-1.0f, 0.0f, right * m_tanHalfFov)) &&
           inside(Vec3(0.0f, 1.0f, -bottom * m_tanHalfFov)) && inside(Vec3(0.0f, -1.0f, top * m_tanHalfFov));
}

}  // namespace bxdflab
