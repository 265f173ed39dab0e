#include "player_mover.hpp"

namespace perpdot::demo {

void PlayerMover::place(World& world, const MoverDef& def, Vec2 position) {
    if (state_ && world.isValid(state_->body)) world.destroyBody(state_->body);
    def_ = def;
    state_ = world.createMover(def, position);
}

void PlayerMover::forget() {
    state_.reset();
    left_ = right_ = jump_ = false;
}

bool PlayerMover::handleKey(SDL_Keycode key, bool down) {
    switch (key) {
        case SDLK_a: left_ = down; return true;
        case SDLK_d: right_ = down; return true;
        case SDLK_w: jump_ = jump_ || down; return true;
        default: return false;
    }
}

void PlayerMover::move(World& world, float dt) {
    if (!state_ || !world.isValid(state_->body)) return;
    const float walk = (right_ ? walkSpeed : 0.0f) - (left_ ? walkSpeed : 0.0f);
    world.moveMover(def_, *state_, {.walkSpeed = walk, .jump = jump_}, dt);
    jump_ = false;
}

void PlayerMover::autopilot(float dt) {
    if (!state_) return;
    right_ = true;
    jump_ = state_->grounded && state_->lastDisplacement.x < 0.5f * walkSpeed * dt;
}

void PlayerMover::draw(DebugDraw& draw) const {
    if (!state_) return;
    const Vec2 feet = state_->position - Vec2{0.0f, def_.halfHeight + def_.radius};
    draw.drawPoint(feet, 8.0f, state_->grounded ? Color{60, 220, 90, 255} : Color{150, 150, 150, 255});
}

}  // namespace perpdot::demo
