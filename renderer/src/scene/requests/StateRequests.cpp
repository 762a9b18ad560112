// The graphics state: attribute and transform blocks, transforms, named
// coordinate systems, motion blocks and the attributes of what follows.
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <sstream>

#include "scene/Camera.h"
#include "scene/SceneBuilder.h"

namespace bxdflab {
namespace {

/// The names in a "subset" or "membership" string (or strings): separated by spaces or commas.
std::vector<std::string> groupNames(Param const& param) {
    std::vector<std::string> names;
    for (std::string const& text : param.strings) {
        std::string name;
        for (char c : text + " ") {
            if (c != ' ' && c != ',') {
                name += c;
            } else if (!name.empty()) {
                names.push_back(name);
                name.clear();
            }
        }
    }
    return names;
}

}  // namespace

void SceneBuilder::beginBlock(RequestReader& in, Block block) {
    in.finish();
    m_attributes.push_back(state());
    m_blocks.push_back(block);
}

bool SceneBuilder::endBlock(RequestReader& in, Block block) {
    in.finish();
    bool const attribute = block == Block::Attribute;
    std::string const end = attribute ? "AttributeEnd" : "TransformEnd";
    if (closesSkippedBegin(block, in.where(), end)) return false;
    if (m_blocks.empty())
        in.fail(in.where(), end + " without a matching " + (attribute ? "AttributeBegin" : "TransformBegin"));
    if (m_blocks.back() != block)
        in.fail(in.where(), end + (attribute ? " closes a TransformBegin block (expected TransformEnd)"
                                             : " closes an AttributeBegin block (expected AttributeEnd)"));
    m_blocks.pop_back();
    return true;
}

void SceneBuilder::attributeBegin(RequestReader& in) { beginBlock(in, Block::Attribute); }

// Level of detail. A model given in several representations sets its bound with Detail and gives
// each representation after a DetailRange; what the bound covers on the image picks the one drawn.

void SceneBuilder::detail(RequestReader& in) {
    std::vector<float> const bound = in.numbers(6, "bound (xmin xmax ymin ymax zmin zmax)");
    in.finish();
    if (!(bound[0] <= bound[1] && bound[2] <= bound[3] && bound[4] <= bound[5]))
        in.fail(in.where(), "the bound must give each axis's least value before its greatest");
    if (!m_inWorld) {
        warnOnce("detail outside world", in.where(),
                 "Detail before WorldBegin has no model to measure; ignored");
        return;
    }
    state().detail = rasterArea(bound) * m_scene.relativeDetail;
}

float SceneBuilder::rasterArea(std::vector<float> const& bound) {
    Camera const camera(m_scene.camera, m_scene.xres, m_scene.yres, m_scene.pixelAspect);
    float xmin = kInfinity, xmax = -kInfinity, ymin = kInfinity, ymax = -kInfinity;
    for (int corner = 0; corner < 8; ++corner) {
        Vec3 const p(bound[corner & 1], bound[2 + ((corner >> 1) & 1)], bound[4 + ((corner >> 2) & 1)]);
        float x = 0.0f, y = 0.0f;
        if (!camera.rasterPosition(transformPoint(state().transform, p), x, y)) return kInfinity;
        xmin = std::min(xmin, x);
        xmax = std::max(xmax, x);
        ymin = std::min(ymin, y);
        ymax = std::max(ymax, y);
    }
    return (xmax - xmin) * (ymax - ymin);
}

void SceneBuilder::detailRange(RequestReader& in) {
    std::vector<float> const range = in.numbers(4, "minvisible lowertransition uppertransition maxvisible");
    in.finish();
    if (!(range[0] <= range[1] && range[1] <= range[2] && range[2] <= range[3]))
        in.fail(in.where(), "minvisible, lowertransition, uppertransition and maxvisible must not decrease");
    float detail = state().detail;
    if (detail < 0.0f) {
        warnOnce("detail range without detail", in.where(),
                 "DetailRange with no Detail bound before it: the detail is taken as the greatest, so the "
                 "representation for the closest view is drawn");
        detail = kInfinity;
    }
    // A representation fades in between minvisible and lowertransition and out between uppertransition
    // and maxvisible, where the next takes over. Drawing each where it is at least half faded in draws
    // exactly one of a model's representations at any detail, with no blend of two. (1e38, as files write
    // infinity, stays above any detail.)
    detail = std::min(detail, 1e37f);
    state().outsideDetailRange =
        !(detail >= 0.5f * (range[0] + range[1]) && detail < 0.5f * (range[2] + range[3]));
}

void SceneBuilder::attributeEnd(RequestReader& in) {
    if (!endBlock(in, Block::Attribute)) return;
    warnIfUnshaped(m_attributes.back().areaLight, m_attributes[m_attributes.size() - 2].areaLight);
    m_attributes.pop_back();
}

void SceneBuilder::warnIfUnshaped(std::shared_ptr<AreaLightDesc> const& closing,
                                  std::shared_ptr<AreaLightDesc> const& outer) {
    // An area light is the shapes that follow it in its block; with none it lights nothing.
    if (!closing || closing == outer || closing->shaped || !building()) return;
    std::string const request = closing->shader == "PxrMeshLight" ? "Light" : "AreaLightSource";
    warnOnce("area light without a shape", closing->where,
             request + " \"" + closing->shader + "\" \"" + closing->handle +
                 "\": no shape follows it in its attribute block, so it lights nothing (give it a Sphere, a Disk or "
                 "a Geometry \"rectlight\", \"spherelight\", \"disklight\" or \"distantlight\")");
}

void SceneBuilder::transformBegin(RequestReader& in) { beginBlock(in, Block::Transform); }

void SceneBuilder::transformEnd(RequestReader& in) {
    if (!endBlock(in, Block::Transform)) return;
    // Only the transform is restored; attributes set inside the block persist.
    Attributes inner = m_attributes.back();
    m_attributes.pop_back();
    inner.transform = state().transform;
    inner.motion = state().motion;
    state() = inner;
}

void SceneBuilder::identity(RequestReader& in) {
    in.finish();
    // Inside the world, identity is world space; before it, the camera's.
    setTransform(in, Mat4(1.0f));
}

// RIB matrices are row-major for row vectors (p' = p M); read as column-major
// they are exactly the column-vector matrix GLM uses.
void SceneBuilder::transform(RequestReader& in) {
    std::vector<float> m = in.numbers(16, "a 4x4 matrix");
    in.finish();
    setTransform(in, glm::make_mat4(m.data()));
}

void SceneBuilder::concatTransform(RequestReader& in) {
    std::vector<float> m = in.numbers(16, "a 4x4 matrix");
    in.finish();
    concatenate(in, glm::make_mat4(m.data()));
}

namespace {
/// Each number is a valid float, yet products of large ones overflow; say where it happened.
void checkFinite(RequestReader& in, Mat4 const& transform) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(transform[i][j]))
                in.fail(in.where(), "the current transform is no longer finite (the numbers overflow a float)");
}
}  // namespace

void SceneBuilder::setTransform(RequestReader& in, Mat4 const& transform) {
    if (m_motion && m_motion->current >= 0) {
        m_motion->moves.push_back({transform, true});
        return;
    }
    checkFinite(in, transform);
    state().transform = transform;
    state().motion = nullptr;
}

void SceneBuilder::concatenate(RequestReader& in, Mat4 const& change) {
    if (m_motion && m_motion->current >= 0) {
        m_motion->moves.push_back({change, false});
        return;
    }
    checkFinite(in, state().transform * change);
    state().transform = state().transform * change;
    if (!state().motion) return;
    auto moved = std::make_shared<TransformPath>(*state().motion);
    for (Mat4& transform : moved->transforms) transform = transform * change;
    state().motion = moved;
}

void SceneBuilder::translate(RequestReader& in) {
    std::vector<float> v = in.numbers(3, "dx dy dz");
    in.finish();
    concatenate(in, glm::translate(Mat4(1.0f), Vec3(v[0], v[1], v[2])));
}

void SceneBuilder::rotate(RequestReader& in) {
    std::vector<float> v = in.numbers(4, "angle dx dy dz");
    in.finish();
    Vec3 axis(v[1], v[2], v[3]);
    // No turn, whatever the axis (exporters write "Rotate 0 0 0 0"); still a step of any motion block.
    if (v[0] == 0.0f) return concatenate(in, Mat4(1.0f));
    if (glm::length(axis) == 0.0f)
        in.fail(in.where(), "rotation axis is the zero vector (only a rotation by 0 may have no axis)");
    concatenate(in, glm::rotate(Mat4(1.0f), glm::radians(v[0]), glm::normalize(axis)));
}

void SceneBuilder::scale(RequestReader& in) {
    std::vector<float> v = in.numbers(3, "sx sy sz");
    in.finish();
    if (v[0] == 0.0f || v[1] == 0.0f || v[2] == 0.0f)
        m_diagnostics.warn(in.where(), "Scale by zero collapses everything that follows");
    concatenate(in, glm::scale(Mat4(1.0f), Vec3(v[0], v[1], v[2])));
}

// Skew shears space along d2 so that d1 turns by `angle` towards it: a point moves along d2 by
// s times its distance along `across`, the direction of d1's part square to d2. If d1 makes the
// angle a0 with `across` (towards d2), it turns to a0 + angle when s = tan(a0 + angle) - tan(a0),
// which needs |a0 + angle| < 90 degrees: d1 cannot be turned onto the line of d2.
void SceneBuilder::skew(RequestReader& in) {
    std::vector<float> v = in.numbers(7, "angle dx1 dy1 dz1 dx2 dy2 dz2");
    in.finish();
    Vec3 const d1(v[1], v[2], v[3]), d2(v[4], v[5], v[6]);
    if (glm::length(d1) == 0.0f || glm::length(d2) == 0.0f) in.fail(in.where(), "an axis is the zero vector");
    Vec3 const along = glm::normalize(d2);
    Vec3 const d1Across = d1 - glm::dot(d1, along) * along;
    if (glm::length(d1Across) <= 1e-6f * glm::length(d1))
        in.fail(in.where(), "the two axes are parallel, so no angle between them can change");
    Vec3 const across = glm::normalize(d1Across);
    double const from = glm::degrees(std::atan2(double(glm::dot(d1, along)), double(glm::dot(d1, across))));
    double const to = from + v[0];
    if (std::abs(to) >= 90.0) {
        std::ostringstream message;
        message << "the axes are " << 90.0 - from << " degrees apart, so the angle must lie between "
                << -(90.0 + from) << " and " << 90.0 - from << " (not " << v[0]
                << "): the first axis cannot be turned onto the line of the second";
        in.fail(in.where(), message.str());
    }
    float const s = float(std::tan(glm::radians(to)) - std::tan(glm::radians(from)));
    Mat4 shear(1.0f);
    for (int column = 0; column < 3; ++column)
        for (int row = 0; row < 3; ++row) shear[column][row] += s * along[row] * across[column];
    concatenate(in, shear);
}

// A bounding box for the shapes that follow: a hint for a renderer that dices them, which a ray
// tracer, bounding every shape itself, does not need.
void SceneBuilder::bound(RequestReader& in) {
    in.numbers(6, "bound (xmin xmax ymin ymax zmin zmax)");
    in.finish();
}

void SceneBuilder::coordinateSystem(RequestReader& in) {
    std::string name = in.string("coordinate system name");
    in.finish();
    m_namedSpaces[name] = state().transform;
    m_scene.coordinateSystems[name] = state().transform;
}

void SceneBuilder::scopedCoordinateSystem(RequestReader& in) {
    std::string name = in.string("coordinate system name");
    in.finish();
    state().scopedSpaces[name] = state().transform;
    m_scene.coordinateSystems[name] = state().transform;
}

void SceneBuilder::coordSysTransform(RequestReader& in) {
    std::string name = in.string("coordinate system name");
    in.finish();
    auto scoped = state().scopedSpaces.find(name);
    if (scoped != state().scopedSpaces.end()) {
        setTransform(in, scoped->second);
        return;
    }
    auto found = m_namedSpaces.find(name);
    if (found == m_namedSpaces.end()) {
        warnOnce("coordsys " + name, in.where(), "CoordSysTransform: no coordinate system \"" + name + "\"; ignored");
        return;
    }
    setTransform(in, found->second);
}

void SceneBuilder::motionBegin(RequestReader& in) {
    std::vector<float> times = in.numberArray("time samples");
    in.finish();
    if (m_motion) in.fail(in.where(), "MotionBegin inside a motion block");
    if (times.empty()) in.fail(in.where(), "a motion block needs at least one time");
    for (size_t i = 0; i < times.size(); ++i) {
        if (!std::isfinite(times[i])) in.fail(in.where(), "a motion block's times must be finite numbers");
        if (i > 0 && !(times[i] > times[i - 1])) in.fail(in.where(), "a motion block's times must increase");
    }
    m_motion = MotionBlock{};
    m_motion->times = std::move(times);
    m_motion->where = in.where();
}

void SceneBuilder::motionEnd(RequestReader& in) {
    in.finish();
    if (!m_motion) in.fail(in.where(), "MotionEnd without a matching MotionBegin");
    MotionBlock block = std::move(*m_motion);
    m_motion.reset();
    if (block.read == 0) return;
    if (block.read != static_cast<int>(block.times.size()))
        m_diagnostics.warn(in.where(), "the motion block at " + block.where.str() + " has " +
                                           std::to_string(block.times.size()) + " times but " +
                                           std::to_string(block.read) + " requests (one a time is expected): it " +
                                           "holds still, as its first request places it");
    if (!block.moves.empty()) finishMotionTransform(block, in);
    if (block.madeShapes()) finishMotionShapes(block, in.where());
}

void SceneBuilder::finishMotionTransform(MotionBlock& block, RequestReader& in) {
    auto path = std::make_shared<TransformPath>();
    Attributes const& now = state();
    bool const complete = block.read == static_cast<int>(block.times.size()) && block.moves.size() == block.times.size();
    size_t const count = complete && block.changes ? block.moves.size() : 1;
    for (size_t k = 0; k < count; ++k) {
        float const time = block.times[k];
        MotionBlock::Move const& move = block.moves[k];
        Mat4 const before = now.motion ? now.motion->at(time) : now.transform;
        path->times.push_back(time);
        path->transforms.push_back(move.absolute ? move.matrix : before * move.matrix);
    }
    for (Mat4 const& transform : path->transforms) checkFinite(in, transform);
    state().transform = path->at(m_scene.shutterOpen);
    state().motion = count > 1 ? path : nullptr;
}

void SceneBuilder::finishMotionShapes(MotionBlock& block, SourceLocation const& where) {
    std::vector<MotionBlock::Made>& first = block.shapes.front();
    // Deformation: the same shapes at every time, only their points changing. (A block that writes
    // the same request at every time changes nothing.)
    bool deforms = block.changes && block.read == static_cast<int>(block.times.size()) &&
                   block.shapes.size() == block.times.size();
    bool pointsMove = false;
    for (size_t k = 1; deforms && k < block.shapes.size(); ++k) {
        deforms = block.shapes[k].size() == first.size();
        for (size_t j = 0; deforms && j < first.size(); ++j) {
            Shape const& shape = *first[j].shape;
            deforms = shape.points() && shape.samePointsAs(*block.shapes[k][j].shape);
            pointsMove = pointsMove || (deforms && *shape.points() != *block.shapes[k][j].shape->points());
        }
    }
    float const open = m_scene.shutterOpen, close = m_scene.shutterClose;
    if (deforms && pointsMove) {
        std::vector<float> const steps = close > open ? shutterSteps(block.times, open, close) : std::vector<float>{open};
        // A moving transform moves the points too: its motion is folded into theirs.
        std::shared_ptr<ShapeMotion const> const moving =
            state().motion ? shapeMotion(*state().motion, open, close) : nullptr;
        for (size_t j = 0; j < first.size(); ++j) {
            auto deformation = std::make_shared<PointSteps>();
            for (size_t step = 0; step < steps.size(); ++step) {
                // The points at this step, along straight lines between the block's times.
                size_t earlier, later;
                float f;
                bracket(block.times, steps[step], earlier, later, f);
                std::vector<Vec3> const& from = *block.shapes[earlier][j].shape->points();
                std::vector<Vec3> const& to = *block.shapes[later][j].shape->points();
                Mat4 const move = moving ? moving->at(static_cast<float>(step) / static_cast<float>(steps.size() - 1))
                                         : Mat4(1.0f);
                std::vector<Vec3> at(from.size());
                for (size_t i = 0; i < at.size(); ++i) at[i] = transformPoint(move, (1.0f - f) * from[i] + f * to[i]);
                deformation->steps.push_back(std::move(at));
            }
            first[j].shape->deform(std::move(deformation));
        }
    } else if (block.changes && !deforms && close > open) {
        std::string const kind = first.empty() ? "shape" : first.front().shape->kind();
        warnOnce("deformation " + kind, where,
                 "the motion block at " + block.where.str() + " changes a " + kind +
                     " from time to time; only polygons, patches and subdivision meshes whose points alone change "
                     "are blurred, so it holds still as its first time gives it");
    }
    for (MotionBlock::Made& made : first) addShape(std::move(made.shape), made.where, std::move(made.constants));
}

void SceneBuilder::attribute(RequestReader& in) {
    std::string category = in.string("attribute name");
    ParamList params = in.params();
    if (category == "visibility") {
        Visibility& vis = state().visibility;
        vis.camera = params.getInt("camera", vis.camera) != 0;
        vis.indirect = params.getInt("indirect", vis.indirect) != 0;
        // RenderMan's older form: "string transmission" "opaque" | "transparent" | "Os" | "shader",
        // also written without its type (the standard name is an int today).
        if (Param const* t = params.find("transmission")) {
            if (!t->strings.empty()) {
                t->used = true;
                vis.transmission = t->strings[0] != "transparent";
            } else {
                vis.transmission = params.getInt("transmission", vis.transmission) != 0;
            }
        }
        // RenderMan 11 to 13: "trace" is visibility to traced (reflected and refracted) rays, our indirect rays.
        if (params.has("trace")) vis.indirect = params.getInt("trace", 1) != 0;
        // Older files name the indirect rays by kind; any kind seeing the object makes it visible to indirect rays.
        bool olderKinds = params.has("diffuse") || params.has("specular");
        if (olderKinds) vis.indirect = params.getInt("diffuse", 0) != 0 || params.getInt("specular", 0) != 0;
    } else if (category == "trace") {
        // RenderMan's per-object bounce limits (PxrPathTracer honours them). Its other
        // "trace" attributes (bias, displacements, holdout, ...) are reported as skipped below.
        traceDepthLimit(params, "maxdiffusedepth", state().traceDepth.maxDiffuse);
        traceDepthLimit(params, "maxspeculardepth", state().traceDepth.maxSpecular);
    } else if (category == "Ri") {
        riAttributes(params);
    } else if (category == "light" && params.has("shadows")) {
        Param const* shadows = params.take("shadows");
        if (!shadows->strings.empty()) state().classicLightShadows = shadows->strings[0] == "on";
        else if (!shadows->floats.empty()) state().classicLightShadows = shadows->floats[0] != 0.0f;
        for (auto const& p : params.all())  // BMRT's "nsamples": shadows are sampled as the integrator samples
            if (p.name() == "nsamples") p.used = true;
    } else if (category == "render" && params.has("casts_shadows")) {
        // BMRT's shadow casting: "none" hides the object from shadow rays (a sky
        // sphere around the scene, say); "opaque", "Os" and "shade" cast shadows,
        // here all opaque ones.
        Param const* casts = params.take("casts_shadows");
        if (!casts->strings.empty()) state().visibility.transmission = casts->strings[0] != "none";
    } else if (category == "user") {
        // Values conditions read ("$user:shader_bindingstrength"); they last to the block's end.
        for (Param const& p : params.all()) {
            p.used = true;
            if (std::optional<std::string> value = p.firstValueText()) state().user[p.name()] = *value;
        }
    } else if (category == "lighting") {
        // Light linking, RenderMan 22 on: "subset" lists the lights (handles or "grouping" groups) that light
        // the shapes that follow (none: all of them), "excludesubset" those that do not.
        if (Param const* subset = params.take("subset")) state().lightingSubset = groupNames(*subset);
        if (Param const* exclude = params.take("excludesubset")) state().lightingExclude = groupNames(*exclude);
        state().lightMute = params.getInt("mute", state().lightMute) != 0;
    } else if (category == "grouping") {
        if (Param const* membership = params.take("membership")) state().membership = groupNames(*membership);
    } else if (category == "trimcurve") {
        if (Param const* sense = params.take("sense")) {
            std::string const which = sense->strings.empty() ? "" : sense->strings[0];
            if (which == "inside" || which == "outside")
                state().trimKeepsOutside = which == "outside";
            else
                m_diagnostics.warn(sense->location, "Attribute \"trimcurve\" \"sense\" is \"inside\" or \"outside\", not \"" +
                                                        which + "\"; left as it was");
        }
    } else if (category == "identifier") {
        if (Param const* name = params.take("name")) state().name = name->strings.empty() ? state().name : name->strings[0];
        for (auto const& p : params.all()) p.used = true;  // shadinggroup, id: labels only
    } else {
        warnOnce("attribute " + category, in.where(), "Attribute \"" + category + "\" is not used by this renderer; skipped");
        return;
    }
    for (auto const& p : params.all())
        if (!p.used)
            warnOnce("attribute " + category + " " + p.name(), p.location,
                     "Attribute \"" + category + "\" \"" + p.name() + "\" is not used by this renderer; skipped");
}

void SceneBuilder::traceDepthLimit(ParamList const& params, std::string const& name, int& limit) {
    Param const* p = params.find(name);
    if (!p) return;
    int const value = params.getInt(name, limit);
    if (value >= 0)
        limit = value;
    else
        warnOnce("trace " + name + " negative", p->location,
                 "Attribute \"trace\" \"" + name + "\" " + std::to_string(value) +
                     " is below 0, which limits nothing; the limit in effect (" + std::to_string(limit) +
                     ") stays");
}

void SceneBuilder::color(RequestReader& in) {
    state().color = in.color("red green blue");
    in.finish();
    state().colorSet = true;
}

void SceneBuilder::opacity(RequestReader& in) {
    Vec3 const c = in.color("red green blue");
    in.finish();
    state().opacity = c;
    // Classic surface shaders show through (ClassicSurface's presence); a Bxdf ignores Opacity, as in RenderMan.
    if (c.x != c.y || c.y != c.z)
        warnOnce("opacity", in.where(),
                 "Opacity with unequal colours is rendered as their mean: a classic surface shows what lies behind "
                 "it in grey, not tinted");
}

void SceneBuilder::reverseOrientation(RequestReader& in) {
    in.finish();
    state().reverseOrientation = !state().reverseOrientation;
}

void SceneBuilder::orientation(RequestReader& in) {
    std::string value = in.string("orientation");
    in.finish();
    if (!setOrientation(value))
        in.fail(in.where(), "orientation must be \"outside\", \"inside\", \"lh\" or \"rh\", not \"" + value + "\"");
}

bool SceneBuilder::setOrientation(std::string const& value) {
    if (value == "outside" || value == "lh")
        state().reverseOrientation = false;
    else if (value == "inside" || value == "rh")
        state().reverseOrientation = true;
    else
        return false;
    return true;
}

void SceneBuilder::sides(RequestReader& in) {
    // Sides 1: the camera sees only the outside of what follows (the back is
    // culled, as RenderMan culls it); every other ray sees both sides, and
    // each side is shaded as seen. A mesh light emits from one face or both.
    float sides = in.number("number of sides");
    in.finish();
    if (sides != 1.0f && sides != 2.0f) in.fail(in.where(), "Sides must be 1 or 2");
    state().twoSided = sides == 2.0f;
}

void SceneBuilder::matte(RequestReader& in) {
    // Matte 1 makes what follows a holdout: it hides what lies behind it and shows nothing itself.
    float const on = in.number("onoff");
    in.finish();
    if (on != 0.0f && on != 1.0f) in.fail(in.where(), "onoff must be 0 or 1");
    if (on == 1.0f)
        warnOnce("matte", in.where(),
                 "Matte 1 (a holdout, which hides what lies behind it and shows nothing itself) is not supported: "
                 "what follows is drawn as an ordinary surface");
}

void SceneBuilder::geometricRepresentation(RequestReader& in) {
    // "primitive" draws surfaces as they are; "points" and "lines" (a wireframe) are previews.
    std::string const type = in.string("representation type");
    in.finish();
    if (type != "primitive")
        warnOnce("geometric representation " + type, in.where(),
                 "GeometricRepresentation \"" + type +
                     "\" is not supported: what follows is drawn as its surfaces "
                     "(\"primitive\")");
}

void SceneBuilder::solidBegin(RequestReader& in) {
    // Solid modelling: "primitive" marks one closed surface and "union" joins solids, which drawing every
    // surface shows from outside; "intersection" and "difference" would cut surfaces away.
    std::string const operation = in.string("\"primitive\", \"union\", \"intersection\" or \"difference\"");
    in.finish();
    if (operation != "primitive" && operation != "union" && operation != "intersection" &&
        operation != "difference")
        in.fail(in.where(), "unknown operation \"" + operation +
                                "\" (\"primitive\", \"union\", \"intersection\" or \"difference\")");
    if (operation == "intersection" || operation == "difference")
        warnOnce("solid " + operation, in.where(),
                 "SolidBegin \"" + operation + "\" is not supported: its solids are drawn whole, as a union");
    ++m_solidDepth;
}

void SceneBuilder::solidEnd(RequestReader& in) {
    in.finish();
    if (m_solidDepth == 0) in.fail(in.where(), "no SolidBegin to match");
    --m_solidDepth;
}

// Named resources (RenderMan 16 and later): an "attributes" resource saves the graphics state under a
// name and restores it, or the part of it a "subset" names, later. ResourceBegin/ResourceEnd bound
// where names saved inside them hold.

void SceneBuilder::resourceBegin(RequestReader& in) {
    in.finish();
    m_resourceScopes.push_back(m_savedAttributes);
}

void SceneBuilder::resourceEnd(RequestReader& in) {
    in.finish();
    if (m_resourceScopes.empty()) in.fail(in.where(), "no ResourceBegin to match");
    m_savedAttributes = std::move(m_resourceScopes.back());
    m_resourceScopes.pop_back();
}

void SceneBuilder::resource(RequestReader& in) {
    std::string const name = in.string("resource name");
    std::string const type = in.string("resource type");
    ParamList params = in.params();
    if (type != "attributes") {
        for (auto const& p : params.all()) p.used = true;  // the resource's own parameters
        warnOnce("resource " + type, in.where(),
                 "Resource of type \"" + type +
                     "\" is not a resource this renderer keeps (it keeps \"attributes\"); skipped");
        return;
    }
    std::string const operation = params.getString("operation", "");
    std::string subset = params.getString("subset", "all");
    params.warnUnused(m_diagnostics, "Resource \"attributes\"");
    if (operation == "save") {
        m_savedAttributes[name] = state();
        return;
    }
    if (operation != "restore") in.fail(in.where(), "\"string operation\" must be \"save\" or \"restore\"");
    auto const saved = m_savedAttributes.find(name);
    if (saved == m_savedAttributes.end()) {
        warnOnce("resource not saved", in.where(),
                 "Resource \"" + name + "\": no attributes were saved under this name here; nothing restored");
        return;
    }
    if (subset != "all" && subset != "shading" && subset != "transform") {
        warnOnce("resource subset " + subset, in.where(),
                 "Resource \"" + name + "\": subset \"" + subset +
                     "\" is not one this renderer knows (\"all\", \"shading\", \"transform\"); all is restored");
        subset = "all";
    }
    Attributes restored = saved->second;
    if (subset == "shading") {  // everything but where things are
        restored.transform = state().transform;
        restored.motion = state().motion;
    } else if (subset == "transform") {  // where things are, and nothing else
        Attributes current = state();
        current.transform = restored.transform;
        current.motion = restored.motion;
        restored = std::move(current);
    }
    state() = std::move(restored);
}

void SceneBuilder::riAttributes(ParamList const& params) {
    // RenderMan 21 and later write the state requests as one Attribute "Ri",
    // each request a parameter of its own name.
    if (Param const* p = params.take("Orientation"))
        if (!setOrientation(params.getString("Orientation", "")))
            throw RibError(p->location, "Attribute \"Ri\" \"Orientation\" must be \"outside\", \"inside\", \"lh\" or \"rh\"");
    if (Param const* p = params.take("Sides")) {
        float const sides = params.getFloat("Sides", 2.0f);
        if (sides != 1.0f && sides != 2.0f) throw RibError(p->location, "Attribute \"Ri\" \"Sides\" must be 1 or 2");
        state().twoSided = sides == 2.0f;
    }
    if (params.has("Color")) {
        state().color = params.getColor("Color", state().color);
        state().colorSet = true;
    }
    // Dicing controls, meaningless to a ray tracer that does not dice.
    params.ignore("ShadingRate");
    params.ignore("ShadingInterpolation");
    if (Param const* matte = params.take("Matte"); matte && params.getInt("Matte", 0) != 0)
        warnOnce("attribute Ri Matte", matte->location,
                 "Attribute \"Ri\" \"Matte\" [1] (a holdout) is not modelled: the object renders as any other");
}

void SceneBuilder::basis(RequestReader& in) {
    SplineBasis bases[2];
    for (int k = 0; k < 2; ++k) {
        const char* what = k == 0 ? "u basis" : "v basis";
        if (in.nextIsString()) {
            std::string name = in.string(what);
            if (!SplineBasis::named(name, bases[k]))
                in.fail(in.where(), "unknown basis \"" + name + "\" (bezier, b-spline, catmull-rom, hermite, power)");
        } else {
            std::vector<float> m = in.numbers(16, what);
            for (int i = 0; i < 16; ++i) bases[k].matrix[i / 4][i % 4] = m[static_cast<size_t>(i)];
        }
        int step = in.integer(k == 0 ? "u step" : "v step");
        if (step < 1) in.fail(in.where(), "basis steps must be whole numbers of at least 1");
        bases[k].step = step;
    }
    in.finish();
    state().uBasis = bases[0];
    state().vBasis = bases[1];
}

void SceneBuilder::textureCoordinates(RequestReader& in) {
    std::vector<float> v = in.numbers(8, "s1 t1 s2 t2 s3 t3 s4 t4");
    in.finish();
    std::copy(v.begin(), v.end(), state().textureCoordinates.begin());
    state().textureCoordinatesSet = true;
}

}  // namespace bxdflab
