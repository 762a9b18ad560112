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
    Camera(CameraDesc const& desc, int xres, int yres, float pixelAspect);
    /// The world-space ray through raster position (x, y) (pixels, fractional).
    void generateRay(float rasterX, float rasterY, Vec3& org, Vec3& dir) const;
    /// With a lens (hasLens()): the ray from the lens point `lens` (two numbers
    /// in [0, 1)) through the point of the focal plane the pinhole ray meets.
    void generateRay(float rasterX, float rasterY, RtFloat2 const& lens, Vec3& org, Vec3& dir) const;
    /// Clipping: whether near and far planes cut camera rays short, and where a ray in direction
    /// dir (from the camera's origin or lens) crosses them.
    bool clips() const { return m_clipNear > 0.0f || m_clipFar < kInfinity; }
    void clipRange(Vec3 const& dir, float& tnear, float& tfar) const;
    /// Camera-space depth (z) of the point at distance t along a camera ray in direction dir.
    float depthAlong(Vec3 const& dir, float t) const { return glm::dot(m_depthAlong, dir) * t; }
    /// A world-space point, and a world-space normal (unit length), in camera space.
    Vec3 pointToCamera(Vec3 const& P) const { return transformPoint(m_worldToCamera, P); }
    Vec3 normalToCamera(Vec3 const& N) const { return safeNormalize(transformNormal(m_cameraToWorld, N)); }
    /// Whether DepthOfField gave the camera a lens of some size.
    bool hasLens() const { return m_lensRadius > 0.0f; }
    /// Makes the camera a pinhole whatever its DepthOfField said.
    void removeLens() { m_lensRadius = 0.0f; }
    /// False only when no camera ray can reach the sphere (center, radius):
    /// it lies behind the camera or wholly outside the image's frustum.
    bool mightSee(Vec3 const& center, float radius) const;
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
