#include "sdl_draw.hpp"

#include <algorithm>
#include <cmath>

namespace perpdot::demo {
namespace {

SDL_FPoint toPoint(Vec2 v) { return {v.x, v.y}; }

void setColor(SDL_Renderer* renderer, Color c) { SDL_SetRenderDrawColor(renderer, c.r, c.g, c.b, c.a); }

// Enough segments that a chord deviates from the circle by under about a quarter pixel.
int circleSegments(float radiusPixels) {
    return std::clamp(static_cast<int>(std::ceil(pi / std::acos(std::max(0.0f, 1.0f - 0.25f / std::max(radiusPixels, 0.5f))))),
                      12, 128);
}

}  // namespace

void SdlDraw::circleOutline(Vec2 center, float radius) {
    const Vec2 c = camera_.toScreen(center);
    const float r = radius * camera_.pixelsPerMetre;
    const int n = circleSegments(r);
    outline_.clear();
    for (int i = 0; i < n; ++i) {
        const float a = 2.0f * pi * static_cast<float>(i) / static_cast<float>(n);
        outline_.push_back({c.x + r * std::cos(a), c.y - r * std::sin(a)});
    }
}

void SdlDraw::roundedOutline(std::span<const Vec2> vertices, float radius) {
    outline_.clear();
    const size_t n = vertices.size();
    if (radius <= 0.0f) {
        for (Vec2 v : vertices) outline_.push_back(toPoint(camera_.toScreen(v)));
        return;
    }
    // Each corner of the inner polygon becomes an arc of `radius` between its two edge normals.
    const float r = radius * camera_.pixelsPerMetre;
    const int arcSegments = std::max(2, circleSegments(r) / 4);
    for (size_t i = 0; i < n; ++i) {
        const Vec2 prev = vertices[(i + n - 1) % n], v = vertices[i], next = vertices[(i + 1) % n];
        const Vec2 n0 = -perp(normalize(v - prev));  // outward normal of a CCW polygon's edge
        const Vec2 n1 = -perp(normalize(next - v));
        const float a0 = std::atan2(n0.y, n0.x);
        float a1 = std::atan2(n1.y, n1.x);
        if (a1 < a0) a1 += 2.0f * pi;
        for (int k = 0; k <= arcSegments; ++k) {
            const float a = a0 + (a1 - a0) * static_cast<float>(k) / static_cast<float>(arcSegments);
            outline_.push_back(toPoint(camera_.toScreen(v + radius * Vec2{std::cos(a), std::sin(a)})));
        }
    }
}

void SdlDraw::fillConvex(Color color) {
    vertices_.clear();
    indices_.clear();
    const SDL_Color c{color.r, color.g, color.b, color.a};
    for (const SDL_FPoint& p : outline_) vertices_.push_back({p, c, {0.0f, 0.0f}});
    for (int i = 1; i + 1 < static_cast<int>(outline_.size()); ++i) {
        indices_.insert(indices_.end(), {0, i, i + 1});
    }
    if (!indices_.empty()) {
        SDL_RenderGeometry(renderer_, nullptr, vertices_.data(), static_cast<int>(vertices_.size()), indices_.data(),
                           static_cast<int>(indices_.size()));
    }
}

void SdlDraw::strokeClosed(Color color) {
    if (outline_.empty()) return;
    outline_.push_back(outline_.front());
    setColor(renderer_, color);
    SDL_RenderDrawLinesF(renderer_, outline_.data(), static_cast<int>(outline_.size()));
    outline_.pop_back();
}

void SdlDraw::drawPolygon(std::span<const Vec2> vertices, Color color) {
    roundedOutline(vertices, 0.0f);
    strokeClosed(color);
}

void SdlDraw::drawSolidPolygon(std::span<const Vec2> vertices, float radius, Color color) {
    roundedOutline(vertices, radius);
    fillConvex(fillColor(color));
    strokeClosed(color);
}

void SdlDraw::drawCircle(Vec2 center, float radius, Color color) {
    circleOutline(center, radius);
    strokeClosed(color);
}

void SdlDraw::drawSolidCircle(Vec2 center, float radius, Rot rotation, Color color) {
    circleOutline(center, radius);
    fillConvex(fillColor(color));
    strokeClosed(color);
    drawSegment(center, center + radius * rotate(rotation, {1.0f, 0.0f}), color);
}

void SdlDraw::drawSegment(Vec2 a, Vec2 b, Color color) {
    const Vec2 sa = camera_.toScreen(a), sb = camera_.toScreen(b);
    setColor(renderer_, color);
    SDL_RenderDrawLineF(renderer_, sa.x, sa.y, sb.x, sb.y);
}

void SdlDraw::drawPoint(Vec2 p, float sizePixels, Color color) {
    const Vec2 s = camera_.toScreen(p);
    const SDL_FRect rect{s.x - 0.5f * sizePixels, s.y - 0.5f * sizePixels, sizePixels, sizePixels};
    setColor(renderer_, color);
    SDL_RenderFillRectF(renderer_, &rect);
}

void drawWorld(SDL_Renderer* renderer, const World& world, const Camera& camera, const DebugDrawOptions& options) {
    setColor(renderer, backgroundColor);
    SDL_RenderClear(renderer);
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_BLEND);
    SdlDraw draw(renderer, camera);
    debugDraw(world, draw, options);
}

}  // namespace perpdot::demo
