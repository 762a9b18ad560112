// Shapes: intersections, partial quadrics, and the differential geometry
// handed to plugins (normals, u, v, dPdu, dPdv), checked against finite
// differences and closed forms.
#include <catch2/catch.hpp>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <vector>

#include "accel/RayTracer.h"
#include "scene/shapes/MeshBuilders.h"
#include "scene/shapes/Quadrics.h"
#include "support/RenderHelpers.h"

using namespace bxdflab;

namespace {

Scene sceneWith(std::string const& rib) {
    Diagnostics diagnostics(false);
    return test::parseRib("WorldBegin\n" + rib + "\nWorldEnd\n", diagnostics);
}

HitRecord trace(RayTracer const& tracer, Vec3 org, Vec3 dir) {
    RayCounts counts;
    return tracer.intersect(org, glm::normalize(dir), 0.0f, kInfinity, 0.0f, RayKind::Camera, counts);
}

/// Numbers in [0, 1) from a small linear congruential generator: the tests
/// need spread, not quality, and the same numbers everywhere.
class Uniform {
public:
    explicit Uniform(uint32_t seed) : m_state(seed) {}
    float operator()() {
        m_state = m_state * 1664525u + 1013904223u;
        return static_cast<float>(m_state >> 8) / 16777216.0f;
    }

private:
    uint32_t m_state;
};

/// A hit on quadric q at parameters (u, v), as a ray would leave it: its
/// point (org + t dir) on the surface, t = 0 here.
HitRecord hitAt(Quadric const& q, float u, float v) {
    HitRecord hit;
    hit.org = transformPoint(q.objectToWorld(), q.surfaceLocal(u, v).P);
    hit.dir = Vec3(0, 0, 1);
    hit.u = u;
    hit.v = v;
    return hit;
}

/// dPdu and dPdv must be the derivatives of P(u, v): compare with central
/// differences of the quadric's own parameterisation.
void checkDerivatives(Quadric const& q, float u, float v) {
    const float h = 1e-3f;
    auto P = [&](float uu, float vv) { return transformPoint(q.objectToWorld(), q.surfaceLocal(uu, vv).P); };
    HitRecord hit = hitAt(q, u, v);
    SurfaceTangents t = q.tangents(hit);
    Vec3 du = (P(u + h, v) - P(u - h, v)) / (2 * h);
    Vec3 dv = (P(u, v + h) - P(u, v - h)) / (2 * h);
    for (int k = 0; k < 3; ++k) {
        CHECK(t.dPdu[k] == Approx(du[k]).margin(2e-3));
        CHECK(t.dPdv[k] == Approx(dv[k]).margin(2e-3));
    }
    // RenderMan's convention: the outward normal is dPdu x dPdv.
    SurfaceBasics b = q.basics(hit);
    Vec3 cross = glm::cross(t.dPdu, t.dPdv);
    if (glm::length(cross) > 1e-4f) CHECK(glm::dot(glm::normalize(cross), b.Ng) == Approx(1.0f).margin(1e-4));
}

}  // namespace

TEST_CASE("sphere: hit distance, outward normal and RI parameterisation", "[geometry]") {
    Scene scene = sceneWith("Translate 0 0 5\nSphere 2 -2 2 360");
    RayTracer tracer(scene);
    HitRecord hit = trace(tracer, Vec3(0), Vec3(0, 0, 1));
    REQUIRE(hit.hit());
    CHECK(hit.t == Approx(3.0f).epsilon(1e-6));
    SurfaceBasics b = scene.shapes[0]->basics(hit);
    CHECK(b.P.z == Approx(3.0f).epsilon(1e-6));
    CHECK(b.Ng.z == Approx(-1.0f).epsilon(1e-6));  // outward, toward the camera
    CHECK(scene.shapes[0]->parameters(hit).v == Approx(0.0f).margin(1e-4));  // z = zmin: v = 0 (v grows with z)
    auto const& sphere = dynamic_cast<Quadric const&>(*scene.shapes[0]);
    for (float u : {0.1f, 0.5f, 0.9f})
        for (float v : {0.2f, 0.5f, 0.8f}) checkDerivatives(sphere, u, v);
}

TEST_CASE("partial sphere: zmin, zmax and thetamax cut the surface", "[geometry]") {
    // A hemisphere (z >= 0) swept only over phi in [0, 90] degrees.
    Scene scene = sceneWith("Sphere 1 0 1 90");
    RayTracer tracer(scene);
    // Into the kept quadrant (x, y, z > 0) from outside: hits the outside.
    HitRecord kept = trace(tracer, Vec3(3, 3, 3), Vec3(-1, -1, -1));
    REQUIRE(kept.hit());
    CHECK(kept.t == Approx(std::sqrt(27.0f) - 1.0f).epsilon(1e-5));
    // The quadrant phi in [90, 180] is cut away: the ray passes straight through.
    HitRecord cutAway = trace(tracer, Vec3(-3, 0.5f, 0.5f), Vec3(1, 0, 0));
    REQUIRE(cutAway.hit());  // misses the removed front, hits the kept back from inside
    CHECK(scene.shapes[0]->basics(cutAway).P.x > 0.0f);
    // Below zmin there is nothing: a ray from below passes through to the dome.
    HitRecord fromBelow = trace(tracer, Vec3(0.3f, 0.3f, -3), Vec3(0, 0, 1));
    REQUIRE(fromBelow.hit());
    CHECK(scene.shapes[0]->basics(fromBelow).P.z > 0.0f);  // the inside of the dome, not the missing bottom
    CHECK_FALSE(trace(tracer, Vec3(-0.3f, -0.3f, -3), Vec3(0, 0, 1)).hit());  // outside the 90-degree sweep
}

TEST_CASE("sphere poles: dPdu vanishes but the normal stays defined", "[geometry]") {
    Scene scene = sceneWith("Sphere 1 -1 1 360");
    auto const& sphere = dynamic_cast<Quadric const&>(*scene.shapes[0]);
    HitRecord top = hitAt(sphere, 0.3f, 1.0f);
    SurfaceTangents t = sphere.tangents(top);
    CHECK(glm::length(t.dPdu) == Approx(0.0f).margin(1e-5));
    SurfaceBasics b = sphere.basics(top);
    CHECK(b.Ng.z == Approx(1.0f).epsilon(1e-5));
    CHECK(isFinite(b.N));
}

TEST_CASE("cylinder and disk: hits, normals and derivatives", "[geometry]") {
    Scene scene = sceneWith("Cylinder 1 -1 1 360\nTranslate 0 0 3\nDisk 0.5 2 270");
    RayTracer tracer(scene);
    HitRecord side = trace(tracer, Vec3(5, 0, 0.5f), Vec3(-1, 0, 0));
    REQUIRE(side.hit());
    CHECK(side.geomID == 0u);
    CHECK(side.t == Approx(4.0f).epsilon(1e-6));
    CHECK(scene.shapes[0]->basics(side).Ng.x == Approx(1.0f).epsilon(1e-6));
    CHECK(scene.shapes[0]->parameters(side).v == Approx(0.75f).epsilon(1e-5));

    HitRecord cap = trace(tracer, Vec3(1, 0.2f, 10), Vec3(0, 0, -1));
    REQUIRE(cap.hit());
    CHECK(cap.geomID == 1u);
    CHECK(cap.t == Approx(10.0f - 3.5f).epsilon(1e-6));
    SurfaceBasics disk = scene.shapes[1]->basics(cap);
    CHECK(disk.Ng.z == Approx(1.0f).epsilon(1e-6));
    CHECK(scene.shapes[1]->parameters(cap).v == Approx(1.0f - std::sqrt(1.04f) / 2.0f).epsilon(1e-4));
    // thetamax 270: the quadrant x > 0, y < 0 is missing.
    CHECK_FALSE(trace(tracer, Vec3(1, -0.5f, 10), Vec3(0, 0, -1)).hit());
    checkDerivatives(dynamic_cast<Quadric const&>(*scene.shapes[0]), 0.3f, 0.6f);
    checkDerivatives(dynamic_cast<Quadric const&>(*scene.shapes[1]), 0.3f, 0.6f);
}

TEST_CASE("polygons: concave faces are triangulated without covering the notch", "[geometry]") {
    // An L shape in the z = 2 plane: the square [0,2]^2 minus [1,2]x[1,2].
    Scene scene = sceneWith("Polygon \"P\" [0 0 2  2 0 2  2 1 2  1 1 2  1 2 2  0 2 2]");
    RayTracer tracer(scene);
    CHECK(trace(tracer, Vec3(0.5f, 0.5f, 0), Vec3(0, 0, 1)).hit());
    CHECK(trace(tracer, Vec3(1.5f, 0.5f, 0), Vec3(0, 0, 1)).hit());
    CHECK(trace(tracer, Vec3(0.5f, 1.5f, 0), Vec3(0, 0, 1)).hit());
    CHECK_FALSE(trace(tracer, Vec3(1.5f, 1.5f, 0), Vec3(0, 0, 1)).hit());
    HitRecord hit = trace(tracer, Vec3(0.5f, 0.5f, 0), Vec3(0, 0, 1));
    CHECK(std::fabs(scene.shapes[0]->basics(hit).Ng.z) == Approx(1.0f));
}

TEST_CASE("PointsPolygons: vertex normals and st are interpolated", "[geometry]") {
    Scene scene = sceneWith(
        "PointsPolygons [4] [0 1 2 3] \"P\" [0 0 1  1 0 1  1 1 1  0 1 1]"
        " \"N\" [0 0 -1  0 0 -1  0 0 -1  0 0 -1] \"st\" [0 0  1 0  1 1  0 1]");
    RayTracer tracer(scene);
    HitRecord hit = trace(tracer, Vec3(0.25f, 0.75f, 0), Vec3(0, 0, 1));
    REQUIRE(hit.hit());
    SurfaceBasics b = scene.shapes[0]->basics(hit);
    SurfaceParameters at = scene.shapes[0]->parameters(hit);
    CHECK(at.s == Approx(0.25f).epsilon(1e-5));
    CHECK(at.t == Approx(0.75f).epsilon(1e-5));
    CHECK(b.N.z == Approx(-1.0f));
    CHECK(b.Ng.z == Approx(-1.0f));  // follows the authored normals
    SurfaceTangents t = scene.shapes[0]->tangents(hit);
    CHECK(t.dPdu.x == Approx(1.0f).epsilon(1e-5));  // ds along +x
    CHECK(t.dPdv.y == Approx(1.0f).epsilon(1e-5));
}

TEST_CASE("bilinear patch and teapot tessellate with exact derivatives", "[geometry]") {
    Mat4 identity(1.0f);
    MeshData patch = buildBilinearPatch({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 1), Vec3(1, 1, 0)}, identity, false);
    CHECK(patch.triangleCount() >= 2u * 10u * 10u);  // twisted: sampled finely
    // Sampling follows the bend: a corner lifted by 2% of the patch's size gets a few quads a side
    // (a height field of hundreds of such patches stays light), a flat patch one quad.
    MeshData gentle = buildBilinearPatch({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0.02f)}, identity, false);
    CHECK(gentle.triangleCount() >= 2u * 2u * 2u);
    CHECK(gentle.triangleCount() <= 2u * 3u * 3u);
    MeshData flat = buildBilinearPatch({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)}, identity, false);
    CHECK(flat.triangleCount() == 2u);
    MeshData teapot = buildTeapot(identity, false);
    CHECK(teapot.triangleCount() == 32u * 12u * 12u * 2u);
    for (size_t i = 0; i < teapot.N.size(); ++i) REQUIRE(glm::length(teapot.N[i]) == Approx(1.0f).epsilon(1e-3));
    // The Newell teapot spans about 6.4 units along x (spout to handle) and 3.15 high.
    Vec3 lo(kInfinity), hi(-kInfinity);
    for (Vec3 const& p : teapot.P) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    CHECK(hi.z == Approx(3.15f).epsilon(1e-3));
    CHECK(lo.z == Approx(0.0f).margin(1e-4));
    CHECK(hi.x - lo.x == Approx(6.43f).epsilon(0.01));
}

TEST_CASE("cone, paraboloid and hyperboloid: RI derivatives and outward normals", "[geometry]") {
    Scene scene = sceneWith("Cone 2 1 300\nParaboloid 1 0.2 2 360\nHyperboloid 1 0 0.5 0.5 1 -0.5 270\n"
                            "Hyperboloid 0.2 0 1  1 0.3 1  300");
    for (size_t k = 0; k < scene.shapes.size(); ++k) {
        CAPTURE(scene.shapes[k]->kind());
        auto const& q = dynamic_cast<Quadric const&>(*scene.shapes[k]);
        for (float u : {0.2f, 0.7f})
            for (float v : {0.25f, 0.6f}) checkDerivatives(q, u, v);
    }
    // Seen from the side, the cone's normal faces the viewer (dPdu x dPdv points out).
    Scene cone = sceneWith("Cone 2 1 360");
    RayTracer tracer(cone);
    HitRecord side = trace(tracer, Vec3(5, 0.01f, 0.5f), Vec3(-1, 0, 0));
    REQUIRE(side.hit());
    CHECK(side.t == Approx(5.0f - 0.75f).epsilon(1e-4));
    CHECK(cone.shapes[0]->basics(side).Ng.x > 0.0f);
}

TEST_CASE("a hyperboloid with both points at one height is a flat ring", "[geometry]") {
    // From the axis out to radius 1: the surface of Disk 0 1 360, with the same u. Its v runs
    // out from the axis where the disk's runs in from the rim, so dPdu x dPdv points down.
    Scene flat = sceneWith("Hyperboloid 0 0 0  1 0 0  360");
    Scene disk = sceneWith("Disk 0 1 360");
    REQUIRE(flat.shapes.size() == 1u);
    RayTracer flatTracer(flat), diskTracer(disk);
    int hits = 0;
    for (float x = -1.2f; x <= 1.2f; x += 0.15f)
        for (float y = -1.2f; y <= 1.2f; y += 0.15f) {
            Vec3 const org(x, y, 3.0f), dir(0.1f, -0.05f, -1.0f);
            HitRecord a = trace(flatTracer, org, dir), b = trace(diskTracer, org, dir);
            REQUIRE(a.hit() == b.hit());
            if (!a.hit()) continue;
            ++hits;
            CHECK(a.t == Approx(b.t).epsilon(1e-5));
            SurfaceBasics sa = flat.shapes[0]->basics(a), sb = disk.shapes[0]->basics(b);
            CHECK(sa.Ng.z == Approx(-sb.Ng.z));
            SurfaceParameters pa = flat.shapes[0]->parameters(a), pb = disk.shapes[0]->parameters(b);
            CHECK(pa.u == Approx(pb.u).margin(1e-4));
            CHECK(pa.v == Approx(1.0f - pb.v).margin(1e-4));
        }
    CHECK(hits > 100);
    // A ring from 0.5 to 1, a quarter of it: only those points.
    Scene ring = sceneWith("Hyperboloid 0.5 0 2  1 0 2  90");
    RayTracer ringTracer(ring);
    auto hitsAt = [&](float x, float y) { return trace(ringTracer, Vec3(x, y, 5.0f), Vec3(0, 0, -1)).hit(); };
    CHECK(hitsAt(0.5f, 0.5f));
    CHECK_FALSE(hitsAt(0.3f, 0.3f));   // inside the hole
    CHECK_FALSE(hitsAt(-0.5f, 0.5f));  // outside the quarter
    CHECK_FALSE(hitsAt(0.9f, 0.9f));   // beyond the rim
    HitRecord at = trace(ringTracer, Vec3(0.75f * std::cos(0.5f), 0.75f * std::sin(0.5f), 5.0f), Vec3(0, 0, -1));
    REQUIRE(at.hit());
    CHECK(at.t == Approx(3.0f));
    SurfaceBasics const atRing = ring.shapes[0]->basics(at);
    SurfaceParameters const ringParameters = ring.shapes[0]->parameters(at);
    CHECK(ringParameters.u == Approx(0.5f / (0.5f * kPi)).epsilon(1e-4));
    CHECK(ringParameters.v == Approx(0.5f).epsilon(1e-4));
    CHECK(atRing.Ng.z == Approx(-1.0f));  // dPdu x dPdv, as for the ring above
}

TEST_CASE("shadow rays traced as a stream answer as one at a time", "[geometry]") {
    // Quadrics (Embree user geometry) and polygons (its triangles), rays of
    // every length: some blocked, some short of what they point at.
    Scene scene = sceneWith("Sphere 1 -1 0.5 270\nTranslate 0 0 3\nCylinder 0.5 -1 1 360\n"
                            "Polygon \"P\" [-4 -4 -2  4 -4 -2  4 4 -2  -4 4 -2]");
    RayTracer tracer(scene);
    std::vector<Vec3> org, dir;
    std::vector<float> reach;
    Uniform uniform(12345u);
    for (int k = 0; k < 600; ++k) {
        org.emplace_back(8.0f * uniform() - 4.0f, 8.0f * uniform() - 4.0f, 6.0f * uniform() - 1.5f);
        dir.push_back(glm::normalize(Vec3(uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f)));
        reach.push_back(k % 7 == 0 ? kInfinity : 6.0f * uniform());
    }
    RayCounts counts;
    std::vector<char> blocked(org.size());
    std::unique_ptr<bool[]> streamed(new bool[org.size()]);
    tracer.occludedStream(org.data(), dir.data(), reach.data(), nullptr, static_cast<int>(org.size()), streamed.get(),
                          counts);
    int blockedCount = 0;
    for (size_t k = 0; k < org.size(); ++k) {
        bool single = tracer.occluded(org[k], dir[k], 0.0f, reach[k], 0.0f, counts);
        CHECK(streamed[k] == single);
        blockedCount += single;
    }
    CHECK(counts.shadow == 2 * org.size());
    // Both answers occur, or the comparison would say little.
    CHECK(blockedCount > 60);
    CHECK(blockedCount < 540);
}

TEST_CASE("a shadow ray's answer for a sphere is the nearest-hit answer, for whole and cut spheres", "[geometry]") {
    // hitsLocal skips (u, v) for a whole sphere; it must still agree with intersectLocal
    // on every ray: starting outside, inside, on the surface, grazing, short of it.
    Mat4 const place = glm::translate(Mat4(1.0f), Vec3(0.3f, -0.2f, 0.1f));
    Sphere const whole(1.0f, -1.0f, 1.0f, 360.0f, place, false);
    Sphere const cut(1.0f, -0.5f, 0.8f, 300.0f, place, false);
    Uniform uniform(777u);
    int hits = 0;
    for (int k = 0; k < 4000; ++k) {
        DVec3 org(3.0 * uniform() - 1.5, 3.0 * uniform() - 1.5, 3.0 * uniform() - 1.5);
        if (k % 10 == 0) org = glm::normalize(org);  // on the surface
        DVec3 dir = glm::normalize(DVec3(uniform() - 0.5, uniform() - 0.5, uniform() - 0.5));
        double tnear = k % 3 == 0 ? 1e-4 : 0.0, tfar = k % 5 == 0 ? 0.5 : 1e30;
        for (Sphere const* s : {&whole, &cut}) {
            bool const nearest = s->intersectLocal(org, dir, tnear, tfar).has_value();
            CHECK(s->hitsLocal(org, dir, tnear, tfar) == nearest);
            hits += nearest;
        }
    }
    CHECK(hits > 1000);  // both answers occur (1799 of 8000)
    CHECK(hits < 7000);
}

TEST_CASE("a whole sphere can be Embree's own sphere primitive: only when it is one, and with the same hits", "[geometry]") {
    auto placed = [](std::string const& rib) {
        Scene scene = sceneWith(rib);
        return dynamic_cast<Quadric const&>(*scene.shapes[0]).placedSphere();
    };
    std::optional<Vec4> ball = placed("Translate 1 2 3\nRotate 30 1 1 0\nScale 1.5 1.5 1.5\nSphere 2 -2 2 360");
    REQUIRE(ball.has_value());
    CHECK(ball->x == Approx(1.0f));
    CHECK(ball->z == Approx(3.0f));
    CHECK(ball->w == Approx(3.0f));                                      // radius 2, scaled 1.5
    CHECK(placed("Scale -1 1 1\nSphere 1 -1 1 360").has_value());        // a mirror is still a ball
    CHECK_FALSE(placed("Sphere 1 -0.5 1 360").has_value());              // cut below
    CHECK_FALSE(placed("Sphere 1 -1 1 300").has_value());                // swept short
    CHECK_FALSE(placed("Scale 1 1 1.01\nSphere 1 -1 1 360").has_value());  // an ellipsoid
    CHECK_FALSE(placed("ConcatTransform [1 0 0 0  0.2 1 0 0  0 0 1 0  0 0 0 1]\nSphere 1 -1 1 360").has_value());  // sheared
    CHECK_FALSE(placed("Cylinder 1 -1 1 360").has_value());

    // Both ways of intersecting find the same surface: distance, point,
    // normal and (u, v), which the primitive's hits do not carry and the
    // sphere works out from the hit point (checked here against the angles).
    Scene scene = sceneWith("Translate 0.3 -0.2 5\nRotate 40 0.2 1 0.5\nScale 0.8 0.8 0.8\nSphere 1 -1 1 360");
    RayTracer exact(scene, WholeSpheres::Exact), embree(scene, WholeSpheres::EmbreePrimitive);
    auto const& sphere = dynamic_cast<Quadric const&>(*scene.shapes[0]);
    Uniform uniform(99u);
    int hits = 0;
    for (int k = 0; k < 3000; ++k) {
        Vec3 org = k % 2 ? Vec3(0.0f) : Vec3(0.3f, -0.2f, 5.0f) + 0.5f * Vec3(uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f);
        Vec3 target = Vec3(0.3f, -0.2f, 5.0f) + 2.0f * Vec3(uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f);
        Vec3 dir = glm::normalize(target - org);
        HitRecord a = trace(exact, org, dir), b = trace(embree, org, dir);
        float miss = glm::length(glm::cross(Vec3(0.3f, -0.2f, 5.0f) - org, dir)) - 0.8f;  // distance past the silhouette
        if (std::abs(miss) < 1e-4f) continue;                                             // grazing: either answer
        REQUIRE(a.hit() == b.hit());
        if (!a.hit()) continue;
        ++hits;
        CHECK(b.t == Approx(a.t).epsilon(1e-5).margin(1e-5));
        SurfaceBasics sa = sphere.basics(a), sb = sphere.basics(b);
        CHECK(glm::length(sa.P - sb.P) < 1e-4f);
        CHECK(glm::dot(sa.Ng, sb.Ng) > 1.0f - 1e-6f);
        Vec3 local = transformPoint(sphere.worldToObject(), sa.P);  // on the unit sphere about the origin
        float phi = std::atan2(local.y, local.x);
        float u = (phi < 0.0f ? phi + 2.0f * kPi : phi) / (2.0f * kPi);
        float v = 1.0f - std::acos(std::clamp(local.z, -1.0f, 1.0f)) / kPi;
        for (SurfaceParameters const& s : {sphere.parameters(a), sphere.parameters(b)}) {
            CHECK(std::min(std::abs(s.u - u), 1.0f - std::abs(s.u - u)) < 1e-4f);  // (u wraps at the seam)
            CHECK(s.v == Approx(v).margin(1e-4));
        }
    }
    CHECK(hits > 1000);  // inside and outside, near and far
}
