// The viewer's camera: world metres (y up) <-> screen pixels (y down), and the framing of a
// scene. Header-only so the tests map world points to pixels exactly as the viewer does.
#pragma once

#include <algorithm>
#include <cmath>

#include "perpdot/world.hpp"

namespace perpdot::demo {

struct Camera {
    Vec2 center;                   // world point at the middle of the screen
    float pixelsPerMetre = 30.0f;
    int width = 1280, height = 720;
    bool following = false;        // followCamera: the moving bodies left the view once, now centred

    Vec2 toScreen(Vec2 w) const {
        return {0.5f * width + (w.x - center.x) * pixelsPerMetre, 0.5f * height - (w.y - center.y) * pixelsPerMetre};
    }
    Vec2 toWorld(Vec2 s) const {
        return {center.x + (s.x - 0.5f * width) / pixelsPerMetre, center.y - (s.y - 0.5f * height) / pixelsPerMetre};
    }
    // Zoom by `factor` keeping the world point under screen point `s` fixed.
    void zoomAt(Vec2 s, float factor) {
        const Vec2 anchor = toWorld(s);
        pixelsPerMetre = std::clamp(pixelsPerMetre * factor, 0.5f, 2000.0f);
        center += anchor - toWorld(s);
    }
};

inline AABB unite(const AABB& a, const AABB& b) {
    return {{std::min(a.lower.x, b.lower.x), std::min(a.lower.y, b.lower.y)},
            {std::max(a.upper.x, b.upper.x), std::max(a.upper.y, b.upper.y)}};
}

// The box around every shape of the moving (non-static) bodies; false when there are none.
inline bool movingBounds(const World& world, AABB& bounds) {
    bool any = false;
    for (BodyId body : world.bodies()) {
        if (world.bodyType(body) == BodyType::Static) continue;
        for (ShapeId shape : world.shapes(body)) {
            bounds = any ? unite(bounds, world.aabb(shape)) : world.aabb(shape);
            any = true;
        }
    }
    return any;
}

// Frame the moving bodies with a margin, plus the static geometry near them: beside them, and
// below them down to where they will land (the top 0.5 m of a ground box is enough). A 100 m
// ground must not shrink a 1 m box to a dot. With no moving bodies, frame everything.
inline Camera fitCamera(const World& world, int width, int height) {
    const auto grow = [](const AABB& box, float d) { return AABB{box.lower - Vec2{d, d}, box.upper + Vec2{d, d}}; };
    AABB moving{};
    const bool haveMoving = movingBounds(world, moving);
    const Vec2 size = moving.upper - moving.lower;
    const float extent = std::max(size.x, size.y);
    AABB view = grow(moving, std::max(0.5f, 0.2f * extent));
    const float beside = std::max(2.0f, extent), below = std::max(20.0f, extent);
    bool haveView = haveMoving;
    for (BodyId body : world.bodies()) {
        if (world.bodyType(body) != BodyType::Static) continue;
        for (ShapeId shape : world.shapes(body)) {
            AABB box = world.aabb(shape);
            if (haveMoving) {
                box = {{std::max(box.lower.x, moving.lower.x - beside), std::max(box.lower.y, moving.lower.y - below)},
                       {std::min(box.upper.x, moving.upper.x + beside), std::min(box.upper.y, moving.upper.y + beside)}};
                if (box.lower.x > box.upper.x || box.lower.y > box.upper.y) continue;  // out of reach
                if (box.upper.y < moving.lower.y + 0.1f) box.lower.y = std::max(box.lower.y, box.upper.y - 0.5f);
            }
            view = haveView ? unite(view, grow(box, 0.25f)) : grow(box, 1.0f);
            haveView = true;
        }
    }
    if (!haveView) view = {{-10.0f, -1.0f}, {10.0f, 12.0f}};
    Camera camera;
    camera.width = width;
    camera.height = height;
    camera.center = 0.5f * (view.lower + view.upper);
    const Vec2 viewSize = view.upper - view.lower;
    camera.pixelsPerMetre = std::min(width / std::max(viewSize.x, 1e-3f), height / std::max(viewSize.y, 1e-3f));
    return camera;
}

// Follow the scene at a fixed zoom: once the moving bodies' box first leaves the view, keep it
// centred from then on. A scene whose bodies stay in view keeps its fitted camera exactly.
inline void followCamera(const World& world, Camera& camera) {
    AABB moving{};
    if (!movingBounds(world, moving)) return;
    const Vec2 lower = camera.toWorld({0.0f, float(camera.height)}), upper = camera.toWorld({float(camera.width), 0.0f});
    camera.following = camera.following || moving.lower.x < lower.x || moving.lower.y < lower.y ||
                       moving.upper.x > upper.x || moving.upper.y > upper.y;
    if (camera.following) camera.center = 0.5f * (moving.lower + moving.upper);
}

}  // namespace perpdot::demo
