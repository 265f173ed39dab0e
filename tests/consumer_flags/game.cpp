// A game's code, compiled by tests/CMakeLists.txt with the project's flags, with -ffast-math
// -ffp-contract=fast (and -mfma where the CPU has it, so contraction is real), and with -O0: it
// places bodies with the public header's inline helpers (Rot::fromAngle, mul, transformPoint,
// rotate, dot, Vec2 operators), steps the world and prints its state_hash. tests/consumer_flags_test.sh
// requires the same line from every build (include/perpdot/math.hpp: a world's bits do not depend
// on the flags of the code that includes the header).
#include <cinttypes>
#include <cstdio>

#include "perpdot/perpdot.hpp"

int main() {
    using namespace perpdot;
    World world;
    const BodyId ground = world.createBody({.type = BodyType::Static});
    world.createShape(ground, {.friction = 0.6f}, makeBox(30.0f, 0.5f));
    // A spiral of boxes: each one's frame is the previous turned by `turn` about a pivot.
    const Rot turn = Rot::fromAngle(0.37f);
    Transform frame{{0.0f, 6.0f}, Rot::fromAngle(0.1f)};
    const Vec2 pivot{0.3f, 6.5f};
    for (int i = 0; i < 40; ++i) {
        frame.q = mul(turn, frame.q);
        frame.p = pivot + rotate(turn, frame.p - pivot) * 1.01f;
        const Vec2 corner = transformPoint(frame, {0.25f, -0.125f});
        const Vec2 velocity = perp(normalize(corner - pivot)) * dot(corner, {0.1f, 0.2f});
        const BodyId box = world.createBody({.type = BodyType::Dynamic, .position = frame.p + Vec2{0.0f, 2.0f},
                                             .angle = frame.q.angle(), .linearVelocity = pointVelocity(velocity, 0.5f, corner - frame.p),
                                             .angularVelocity = 0.2f});
        world.createShape(box, {.density = 1.0f, .friction = 0.6f}, makeBox(0.3f, 0.2f, invRotate(frame.q, {0.01f, 0.0f}), 0.05f));
    }
    for (int step = 0; step < 240; ++step) world.step(1.0f / 60.0f);
    std::printf("state_hash=%016" PRIx64 "\n", stateHash(world));
}
