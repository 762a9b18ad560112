// RenderMan's camera: left-handed camera space looking down +z with +y up;
// the field of view spans the shorter image axis; raster (0,0) is the top
// left corner of the image.
#pragma once

#include "RiTypesHelper.h"
#include "core/Math.h"
#include "scene/Scene.h"

namespace bxdflab {

class Camera {
public:
    /// The camera as `desc` places it when the shutter opens at shutterOpen; a camera whose desc.motion
    /// moves it before shutterClose moves while the shutter is open (moves()).
    Camera(CameraDesc const& desc, int xres, int yres, float pixelAspect, float shutterOpen = 0.0f,
           float shutterClose = 0.0f);
    /// The world-space ray through raster position (x, y) (pixels, fractional).
    void generateRay(float rasterX, float rasterY, Vec3& org, Vec3& dir) const;
    /// With a lens (hasLens()): the ray from the lens point `lens` (two numbers
    /// in [0, 1)) through the point of the focal plane the pinhole ray meets.
    void generateRay(float rasterX, float rasterY, RtFloat2 const& lens, Vec3& org, Vec3& dir) const;
    /// Clipping: whether near and far planes cut camera rays short, and where a ray in direction
    /// dir (from the camera's origin or lens) crosses them.
    bool clips() const { return m_clipNear > 0.0f || m_clipFar < kInfinity; }
    void clipRange(Vec3 const& dir, float& tnear, float& tfar) const;
    /// Whether the camera moves while the shutter is open. generateRay() then gives the rays of the
    /// camera as the shutter opens, and moveRay() carries each to the moment it is traced at.
    bool moves() const { return m_motion != nullptr; }
    /// Carries a ray of the camera as the shutter opens to where the camera is at `time`: the same ray
    /// in camera space. Returns how much a unit of distance along the old ray stretches along the new
    /// (1 unless the camera's transform scales), so distances such as clipRange's can follow.
    float moveRay(float time, Vec3& org, Vec3& dir) const;
    /// Makes the camera stand where it is as the shutter opens, whatever its motion.
    void holdStill() { m_motion = nullptr; }
    /// Camera-space depth (z) of the point at distance t along a camera ray in direction dir traced at `time`.
    float depthAlong(Vec3 const& dir, float t, float time) const;
    /// A world-space point, and a world-space normal (unit length), in the camera space of `time`.
    Vec3 pointToCamera(Vec3 const& P, float time) const { return transformPoint(worldToCameraAt(time), P); }
    Vec3 normalToCamera(Vec3 const& N, float time) const {
        return safeNormalize(
            transformNormal(m_motion ? glm::inverse(worldToCameraAt(time)) : m_cameraToWorld, N));
    }
    /// Whether DepthOfField gave the camera a lens of some size.
    bool hasLens() const { return m_lensRadius > 0.0f; }
    /// Makes the camera a pinhole whatever its DepthOfField said.
    void removeLens() { m_lensRadius = 0.0f; }
    /// False only when no camera ray can reach the sphere (center, radius):
    /// it lies behind the camera or wholly outside the image's frustum (never while the camera moves).
    bool mightSee(Vec3 const& center, float radius) const;
    /// Where the world-space point P lands on the image, in raster units (pixels, not limited to the
    /// image), as the shutter opens: false when a perspective camera has it behind the eye.
    bool rasterPosition(Vec3 const& P, float& rasterX, float& rasterY) const;
    /// Where a camera ray through `P` lands, for light subpaths joined to the camera
    /// (perspective cameras only): false when P is behind the camera or outside the image.
    /// Gives the raster position, the unit direction from P to the eye and the distance,
    /// and the density per unit solid angle of a camera ray in that direction (camera
    /// rays are spread uniformly over the image plane at distance 1: 1 / (A cos^3 theta)).
    bool project(Vec3 const& P, float& rasterX, float& rasterY, Vec3& toEye, float& distance,
                 float& directionPdf) const;
    /// The number of pixels.
    int pixelCount() const { return m_xres * m_yres; }
    bool perspective() const { return m_perspective; }
    /// The angle (radians) one pixel subtends at the image centre.
    float pixelSpread() const { return m_pixelSpread; }
    Vec3 position() const { return m_position; }

private:
    /// The world-to-camera transform at `time` (as the shutter opens for a camera that holds still).
    Mat4 worldToCameraAt(float time) const { return m_motion ? m_motion->at(time) : m_worldToCamera; }

    std::shared_ptr<TransformPath const> m_motion;  ///< world-to-camera over time, while the camera moves
    Mat4 m_cameraToWorld;
    Mat4 m_worldToCamera;
    Vec3 m_position;
    bool m_perspective;
    float m_tanHalfFov;
    float m_screen[4];  // left right bottom top
    int m_xres, m_yres;
    float m_pixelSpread;
    // generateRay's plane of rays, in world space: the ray through raster
    // (x, y) starts at m_rasterOrigin + x m_perRasterX + y m_perRasterY
    // (orthographic) or points along m_rasterOrigin + x m_perRasterX + y m_perRasterY
    // (perspective, before normalising). Kept so each camera ray costs two
    // multiply-adds and one normalisation, not a matrix product.
    Vec3 m_rasterOrigin, m_perRasterX, m_perRasterY;
    Vec3 m_orthographicDirection;
    float m_lensRadius, m_focalDistance;  ///< camera space
    float m_clipNear, m_clipFar;          ///< camera space
    Vec3 m_depthAlong;                    ///< camera-space z of a world-space direction: dot(m_depthAlong, dir)
    Vec3 m_lensX, m_lensY;                ///< the lens's axes in world space, of the lens's radius
};

}  // namespace bxdflab
