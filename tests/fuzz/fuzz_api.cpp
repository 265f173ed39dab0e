// libFuzzer harness for sequences of World calls: the bytes are a program of operations — create
// and destroy bodies, shapes (every kind) and joints (every kind), forces, setters, step, ray /
// AABB / point / shape queries, snapshot and restore — interleaved, with finite arguments only.
// A call may refuse its arguments with perpdot::Error; step() must never throw (an exception
// escaping it aborts the harness), and a snapshot must restore into a fresh world and save back to
// the same bytes.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <span>
#include <vector>

#include "perpdot/error.hpp"
#include "perpdot/world.hpp"

namespace {

using namespace perpdot;

// Reads the program; past the end every read is zero.
class Program {
public:
    Program(const uint8_t* data, size_t size) : data_(data), size_(size) {}
    bool done() const { return at_ >= size_; }
    uint8_t byte() { return at_ < size_ ? data_[at_++] : 0; }
    bool flag() { return (byte() & 1) != 0; }
    int index(size_t count) { return count == 0 ? 0 : static_cast<int>(byte() % count); }
    // A finite float: mostly small multiples of 1/8, sometimes raw bits (extremes, denormals).
    float number() {
        const uint8_t kind = byte();
        if (kind < 160) return static_cast<float>(static_cast<int8_t>(byte())) / 8.0f;
        if (kind < 224) return static_cast<float>(static_cast<int16_t>(byte() | (byte() << 8))) / 64.0f;
        uint32_t bits = 0;
        for (int i = 0; i < 4; ++i) bits |= static_cast<uint32_t>(byte()) << (8 * i);
        float f = 0.0f;
        std::memcpy(&f, &bits, sizeof f);
        return std::isfinite(f) ? f : 0.0f;
    }
    Vec2 vec() {
        const float x = number();
        return {x, number()};
    }

private:
    const uint8_t* data_;
    size_t size_;
    size_t at_ = 0;
};

struct ApiRun {
    World world;
    std::vector<BodyId> bodies;
    std::vector<ShapeId> shapes;
    std::vector<JointId> joints;
    Program& in;

    BodyId body() { return bodies.empty() ? BodyId{} : bodies[in.index(bodies.size())]; }
    ShapeId shape() { return shapes.empty() ? ShapeId{} : shapes[in.index(shapes.size())]; }
    JointId joint() { return joints.empty() ? JointId{} : joints[in.index(joints.size())]; }

    void createBody() {
        BodyDef def;
        def.type = static_cast<BodyType>(in.index(3));
        def.position = in.vec();
        def.angle = in.number();
        def.linearVelocity = in.vec();
        def.angularVelocity = in.number();
        def.linearDamping = in.flag() ? in.number() : 0.0f;
        def.angularDamping = in.flag() ? in.number() : 0.0f;
        def.gravityScale = in.flag() ? in.number() : 1.0f;
        def.fixedRotation = in.flag();
        def.bullet = in.flag();
        def.allowSleep = in.flag();
        def.awake = in.flag();
        bodies.push_back(world.createBody(def));
    }

    ShapeDef shapeDef() {
        ShapeDef def;
        def.density = in.flag() ? in.number() : 1.0f;
        def.friction = in.flag() ? in.number() : 0.6f;
        def.restitution = in.flag() ? in.number() : 0.0f;
        def.sensor = in.byte() < 32;
        def.rollingResistance = in.flag() ? in.number() : 0.0f;
        def.tangentSpeed = in.flag() ? in.number() : 0.0f;
        def.enableHitEvents = in.flag();
        def.enablePreSolveEvents = in.flag();
        def.filter.category = static_cast<uint16_t>(1u << in.index(16));
        def.filter.group = static_cast<int16_t>(static_cast<int>(in.index(5)) - 2);
        return def;
    }

    Polygon polygon() {
        if (in.flag()) {
            const float hx = in.number(), hy = in.number();
            const Vec2 center = in.vec();
            return makeBox(hx, hy, center, in.number());
        }
        std::vector<Vec2> points(3 + in.index(7));
        for (Vec2& p : points) p = in.vec();
        const float radius = in.flag() ? in.number() : 0.0f;
        return makePolygon(points, radius);
    }

    void createShape() {
        const BodyId b = body();
        const ShapeDef def = shapeDef();
        switch (in.index(4)) {
            case 0: shapes.push_back(world.createShape(b, def, Circle{in.vec(), in.number()})); break;
            case 1: shapes.push_back(world.createShape(b, def, polygon())); break;
            case 2: shapes.push_back(world.createShape(b, def, Segment{in.vec(), in.vec()})); break;
            default: {
                Chain chain;
                chain.loop = in.flag();
                chain.vertices.resize(2 + in.index(7));
                for (Vec2& v : chain.vertices) v = in.vec();
                shapes.push_back(world.createShape(b, def, chain));
            }
        }
    }

    template <class Def>
    void addJoint(const Def& def) {
        joints.push_back(world.createJoint(def));
    }

    // Braced initialisers evaluate in order, so the reads follow the fields.
    void createJoint() {
        const BodyId a = body(), b = body();
        const bool cc = in.flag();
        switch (in.index(7)) {
            case 0:
                addJoint(RevoluteJointDef{.bodyA = a, .bodyB = b, .localAnchorA = in.vec(), .localAnchorB = in.vec(),
                                          .referenceAngle = in.number(), .enableLimit = in.flag(), .lowerAngle = in.number(),
                                          .upperAngle = in.number(), .enableMotor = in.flag(), .motorSpeed = in.number(),
                                          .maxMotorTorque = in.number(), .collideConnected = cc});
                break;
            case 1:
                addJoint(PrismaticJointDef{.bodyA = a, .bodyB = b, .localAnchorA = in.vec(), .localAnchorB = in.vec(),
                                           .localAxisA = in.vec(), .referenceAngle = in.number(), .enableLimit = in.flag(),
                                           .lower = in.number(), .upper = in.number(), .enableMotor = in.flag(),
                                           .motorSpeed = in.number(), .maxMotorForce = in.number(), .collideConnected = cc});
                break;
            case 2:
                addJoint(DistanceJointDef{.bodyA = a, .bodyB = b, .localAnchorA = in.vec(), .localAnchorB = in.vec(),
                                          .length = in.number(), .minLength = in.number(), .maxLength = in.number(),
                                          .hertz = in.number(), .dampingRatio = in.number(), .collideConnected = cc});
                break;
            case 3:
                addJoint(WeldJointDef{.bodyA = a, .bodyB = b, .localAnchorA = in.vec(), .localAnchorB = in.vec(),
                                      .referenceAngle = in.number(), .hertz = in.number(), .dampingRatio = in.number(),
                                      .collideConnected = cc});
                break;
            case 4:
                addJoint(WheelJointDef{.bodyA = a, .bodyB = b, .localAnchorA = in.vec(), .localAnchorB = in.vec(),
                                       .localAxisA = in.vec(), .hertz = in.number(), .dampingRatio = in.number(),
                                       .enableMotor = in.flag(), .motorSpeed = in.number(), .maxMotorTorque = in.number(),
                                       .collideConnected = cc});
                break;
            case 5:
                addJoint(MotorJointDef{.bodyA = a, .bodyB = b, .linearOffset = in.vec(), .angularOffset = in.number(),
                                       .maxForce = in.number(), .maxTorque = in.number(), .correctionFactor = in.number(),
                                       .collideConnected = cc});
                break;
            default:
                addJoint(MouseJointDef{.bodyA = a, .bodyB = b, .target = in.vec(), .hertz = in.number(),
                                       .dampingRatio = in.number(), .maxForce = in.number(), .collideConnected = cc});
        }
    }

    // Arguments are read into locals first: the order of evaluation of call arguments is
    // unspecified, and gcc and clang must replay the same program.
    void push() {
        const BodyId b = body();
        const int what = in.index(9);
        const Vec2 v = in.vec(), point = in.vec();
        switch (what) {
            case 0: world.applyForce(b, v, point); break;
            case 1: world.applyForceToCenter(b, v); break;
            case 2: world.applyTorque(b, v.x); break;
            case 3: world.applyLinearImpulse(b, v, point); break;
            case 4: world.applyAngularImpulse(b, v.x); break;
            case 5: world.setLinearVelocity(b, v); break;
            case 6: world.setAngularVelocity(b, v.x); break;
            case 7: world.setTransform(b, point, v.x); break;
            default: world.setAwake(b, v.x > 0.0f);
        }
    }

    void set() {
        const int what = in.index(9);
        const ShapeId s = shape();
        const JointId j = joint();
        const BodyId b = body();
        const Vec2 v = in.vec();
        switch (what) {
            case 0: world.setFriction(s, v.x); break;
            case 1: world.setRestitution(s, v.x); break;
            case 2: world.setDensity(s, v.x); break;
            case 3: world.setTangentSpeed(s, v.x); break;
            case 4: world.setGravity(v); break;
            case 5: world.setSubsteps(1 + in.index(8)); break;
            case 6: world.setMotorSpeed(j, v.x); break;
            case 7: world.setMouseTarget(j, v); break;
            default: world.setGravityScale(b, v.x);
        }
    }

    // Queries only read; their results are not checked here beyond not crashing.
    void query() {
        const int what = in.index(7);
        const Vec2 p = in.vec(), q = in.vec();
        const Transform xf{in.vec(), Rot::fromAngle(in.number())};
        switch (what) {
            case 0: (void)world.castRayClosest(p, q); break;
            case 1: (void)world.castRay(p, q); break;
            case 2: (void)world.overlapAABB(AABB{p, q}); break;
            case 3: (void)world.overlapPoint(p); break;
            case 4: (void)world.overlapShape(Circle{p, q.x}, xf); break;
            case 5: (void)world.overlapShape(polygon(), xf); break;
            default: {
                Polygon raw;  // hand-filled: any count, unchecked vertices
                raw.count = static_cast<int>(in.byte()) - 8;
                for (Vec2& v : raw.vertices) v = in.vec();
                raw.radius = p.x;
                (void)world.overlapShape(raw, xf);
            }
        }
        (void)world.contacts();
        (void)world.contactEvents();
        (void)world.sensorEvents();
    }

    // A snapshot restores into a fresh world and saves back to the same bytes; then the world,
    // moved or not (it keeps its identity, and every id it issued stays valid), restores it.
    void snapshotRestore() {
        const std::vector<uint8_t> bytes = world.snapshot();
        World copy;
        copy.restore(bytes);
        if (copy.snapshot() != bytes) std::abort();
        if (in.flag()) {
            World moved = std::move(world);
            world = std::move(moved);
        }
        world.restore(bytes);
    }

    void destroy() {
        switch (in.index(3)) {
            case 0: world.destroyBody(body()); break;
            case 1: world.destroyShape(shape()); break;
            default: world.destroyJoint(joint());
        }
    }

    // One operation; perpdot::Error is a refused call (bad argument, stale id), never a step's.
    void run(uint8_t op) {
        if (op % 8 == 0) {
            world.step(in.flag() ? 1.0f / 60.0f : std::fabs(in.number()));  // must not throw
            return;
        }
        try {
            switch (op % 8) {
                case 1: createBody(); break;
                case 2: createShape(); break;
                case 3: createJoint(); break;
                case 4: push(); break;
                case 5: op & 8 ? set() : destroy(); break;
                case 6: query(); break;
                default: snapshotRestore();
            }
        } catch (const Error&) {
        }
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Program in(data, size);
    ApiRun api{World{}, {}, {}, {}, in};
    for (int ops = 0; ops < 256 && !in.done(); ++ops) api.run(in.byte());
    for (int i = 0; i < 4; ++i) api.world.step(1.0f / 60.0f);
    return 0;
}
