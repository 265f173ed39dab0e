// The stability figures of stability.hpp, from two frames of samples.
#include "crosscheck/stability.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "perpdot/error.hpp"

namespace perpdot::crosscheck {
namespace {

// The scene's index of the body named `name`, and its index among the non-static bodies (the
// sample index; -1 for a static body). perpdot::Error when there is no such body.
struct Found {
    size_t scene;
    int sample;
};
Found findBody(const Scene& scene, const std::string& name) {
    int moving = 0;
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
        const bool isStatic = scene.bodies[i].type == BodyType::Static;
        if (scene.bodies[i].name == name) return {i, isStatic ? -1 : moving};
        if (!isStatic) ++moving;
    }
    throw Error("scene \"" + scene.name + "\": its stability figure needs a body named \"" + name + "\"");
}

// Sample index of the dynamic body that starts highest; -1: none.
int topBody(const Scene& scene) {
    int top = -1, moving = 0;
    float topY = 0.0f;
    for (const SceneBody& b : scene.bodies) {
        if (b.type == BodyType::Static) continue;
        if (b.type == BodyType::Dynamic && (top < 0 || b.position.y > topY)) top = moving, topY = b.position.y;
        ++moving;
    }
    return top;
}

// The inside of a container, in its body frame: its closed chain loop, or else the rectangle
// around its shapes (the walls of a hollow box).
std::vector<Vec2> insideOutline(const SceneBody& container) {
    for (const SceneShape& s : container.shapes)
        if (s.kind == SceneShape::Kind::Chain && s.loop) return s.vertices;
    constexpr float huge = std::numeric_limits<float>::max();
    Vec2 lower{huge, huge}, upper{-huge, -huge};
    const auto extend = [&](Vec2 p, float r) {
        lower = {std::min(lower.x, p.x - r), std::min(lower.y, p.y - r)};
        upper = {std::max(upper.x, p.x + r), std::max(upper.y, p.y + r)};
    };
    for (const SceneShape& s : container.shapes) {
        switch (s.kind) {
            case SceneShape::Kind::Circle: extend(s.center, s.radius); break;
            case SceneShape::Kind::Box:
                for (const Vec2 corner : {Vec2{-1, -1}, Vec2{1, -1}, Vec2{1, 1}, Vec2{-1, 1}})
                    extend(s.center + rotate(Rot::fromAngle(s.angle), {corner.x * s.halfExtents.x, corner.y * s.halfExtents.y}), 0.0f);
                break;
            case SceneShape::Kind::Polygon:
                for (const Vec2 v : s.vertices) extend(v, s.radius);
                break;
            case SceneShape::Kind::Segment: extend(s.v1, 0.0f), extend(s.v2, 0.0f); break;
            case SceneShape::Kind::Capsule: extend(s.v1, s.radius), extend(s.v2, s.radius); break;
            case SceneShape::Kind::Chain:
                for (const Vec2 v : s.vertices) extend(v, 0.0f);
                break;
        }
    }
    if (lower.x > upper.x) throw Error("body \"" + container.name + "\" has no shapes to contain anything");
    return {lower, {upper.x, lower.y}, upper, {lower.x, upper.y}};
}

// Even-odd rule: a ray from p towards +x crosses the outline an odd number of times iff p is inside.
bool inside(const std::vector<Vec2>& outline, Vec2 p) {
    bool in = false;
    for (size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
        const Vec2 a = outline[i], b = outline[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
    }
    return in;
}

// The lowest centre of the shapes of the static body named "ground", world: the floor everything
// should stay above (a catcher below it, as in `compounds`, is another body).
float groundFloor(const Scene& scene) {
    const SceneBody& ground = scene.bodies[findBody(scene, "ground").scene];
    float floor = std::numeric_limits<float>::max();
    const Transform frame{ground.position, Rot::fromAngle(ground.angle)};
    for (const SceneShape& s : ground.shapes) {
        const bool line = s.kind == SceneShape::Kind::Segment;
        floor = std::min(floor, transformPoint(frame, line ? 0.5f * (s.v1 + s.v2) : s.center).y);
    }
    if (ground.type != BodyType::Static || floor == std::numeric_limits<float>::max())
        throw Error("scene \"" + scene.name + "\": its stability figure needs a static body \"ground\" with shapes");
    return floor;
}

// Σ m v, summed in double: thousands of float terms would otherwise round away the error measured.
struct Momentum {
    double x = 0.0, y = 0.0;
};
Momentum linearMomentum(const std::vector<BodySample>& bodies) {
    Momentum p;
    for (const BodySample& b : bodies) {  // kinematic bodies have mass 0
        p.x += double(b.mass) * b.state.linearVelocity.x;
        p.y += double(b.mass) * b.state.linearVelocity.y;
    }
    return p;
}

}  // namespace

StabilityProbe::StabilityProbe(const Scene& scene) {
    if (scene.name == "bench_tumbler" || scene.name == "spinner" || scene.name == "washer") {
        kind_ = Kind::Escaped;
        const Found container = findBody(scene, "container");
        const SceneBody& body = scene.bodies[container.scene];
        container_ = container.sample;
        containerFrame_ = {body.position, Rot::fromAngle(body.angle)};
        outline_ = insideOutline(body);
    } else if (scene.name == "smash") {
        kind_ = Kind::MomentumError;
    } else if (scene.name == "ragdoll_rain" || scene.name == "junkyard" || scene.name == "compounds") {
        kind_ = Kind::BelowFloor;
        floor_ = groundFloor(scene);
    } else {
        top_ = topBody(scene);
    }
}

const char* StabilityProbe::label() const {
    switch (kind_) {
        case Kind::TopFell: return "top fell";
        case Kind::Escaped: return "escaped";
        case Kind::MomentumError: return "momentum error";
        case Kind::BelowFloor: return "below floor";
    }
    return "";
}

const char* StabilityProbe::unit() const {
    switch (kind_) {
        case Kind::TopFell: return "m";
        case Kind::Escaped:
        case Kind::BelowFloor: return "bodies";
        case Kind::MomentumError: return "of p0";
    }
    return "";
}

float StabilityProbe::measure(const std::vector<BodySample>& first, const std::vector<BodySample>& last) const {
    switch (kind_) {
        case Kind::TopFell:
            return top_ >= 0 ? first[size_t(top_)].state.position.y - last[size_t(top_)].state.position.y : 0.0f;
        case Kind::Escaped: return escaped(last);
        case Kind::MomentumError: {
            const Momentum p0 = linearMomentum(first), p1 = linearMomentum(last);
            // relative to the initial momentum; a scene starting at rest gets the change itself, in N·s
            return float(std::hypot(p1.x - p0.x, p1.y - p0.y) / std::max(std::hypot(p0.x, p0.y), 1.0));
        }
        case Kind::BelowFloor:
            return float(std::count_if(last.begin(), last.end(), [this](const BodySample& b) { return b.center.y < floor_; }));
    }
    return 0.0f;
}

float StabilityProbe::escaped(const std::vector<BodySample>& last) const {
    const Transform frame = container_ < 0 ? containerFrame_
                                           : Transform{last[size_t(container_)].state.position,
                                                       Rot::fromAngle(last[size_t(container_)].state.angle)};
    int count = 0;
    for (size_t i = 0; i < last.size(); ++i)
        if (int(i) != container_ && !inside(outline_, invTransformPoint(frame, last[i].center))) ++count;
    return float(count);
}

}  // namespace perpdot::crosscheck
