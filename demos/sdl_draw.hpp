// perpdot::DebugDraw over an SDL_Renderer and a Camera: the one drawer shared by the window and
// the headless PNG frames. Fills use SDL_RenderGeometry (SDL 2.0.18+), outlines use lines.
#pragma once

#include <SDL.h>

#include <vector>

#include "camera.hpp"
#include "perpdot/debug_draw.hpp"

namespace perpdot::demo {

inline constexpr Color backgroundColor{24, 26, 32};

// Shapes are filled opaquely with their colour mixed half-way into the background, so a pixel
// inside a shape has a known colour (the tests check it) and the outline stands out.
constexpr Color fillColor(Color c) {
    const auto mix = [](uint8_t fg, uint8_t bg) { return static_cast<uint8_t>((fg + bg) / 2); };
    return {mix(c.r, backgroundColor.r), mix(c.g, backgroundColor.g), mix(c.b, backgroundColor.b), 255};
}

class SdlDraw final : public DebugDraw {
public:
    SdlDraw(SDL_Renderer* renderer, const Camera& camera) : renderer_(renderer), camera_(camera) {}

    void drawPolygon(std::span<const Vec2> vertices, Color color) override;
    void drawSolidPolygon(std::span<const Vec2> vertices, float radius, Color color) override;
    void drawCircle(Vec2 center, float radius, Color color) override;
    void drawSolidCircle(Vec2 center, float radius, Rot rotation, Color color) override;
    void drawSegment(Vec2 a, Vec2 b, Color color) override;
    void drawPoint(Vec2 p, float sizePixels, Color color) override;

private:
    // Screen-space outline of a circle, or of a polygon rounded by `radius` (arcs at the corners).
    void circleOutline(Vec2 center, float radius);
    void roundedOutline(std::span<const Vec2> vertices, float radius);
    void fillConvex(Color color);    // fan-triangulate outline_
    void strokeClosed(Color color);  // closed line loop through outline_

    SDL_Renderer* renderer_;
    Camera camera_;
    std::vector<SDL_FPoint> outline_;
    std::vector<SDL_Vertex> vertices_;
    std::vector<int> indices_;
};

// Clear to the background and draw the world: the frame used by both the window and the PNGs.
void drawWorld(SDL_Renderer* renderer, const World& world, const Camera& camera, const DebugDrawOptions& options);

}  // namespace perpdot::demo
