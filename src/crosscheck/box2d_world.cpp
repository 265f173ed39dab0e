// Scene -> b2World. Each scene field maps onto the b2*Def field of the same meaning; the few
// places where Box2D 2.4 has no equivalent say so where they are handled.
#include "crosscheck/box2d_world.hpp"

#include <algorithm>
#include <unordered_map>

#include "collide/b2_convert.hpp"
#include "collide/capsule_b2.hpp"
#include "collide/chain_b2.hpp"
#include "collide/polygon_b2.hpp"
#include "crosscheck/stepper.hpp"
#include "perpdot/error.hpp"
#include "perpdot/shapes.hpp"

namespace perpdot::crosscheck {
namespace {

using collide::toB2;

b2BodyType toB2(BodyType type) {
    switch (type) {
    case BodyType::Static: return b2_staticBody;
    case BodyType::Kinematic: return b2_kinematicBody;
    case BodyType::Dynamic: return b2_dynamicBody;
    }
    return b2_staticBody;
}

b2BodyDef bodyDef(const SceneBody& b) {
    b2BodyDef def;
    def.type = toB2(b.type);
    def.position = toB2(b.position);
    def.angle = b.angle;
    def.linearVelocity = toB2(b.linearVelocity);  // of the centre of mass in both engines
    def.angularVelocity = b.angularVelocity;
    def.linearDamping = b.linearDamping;
    def.angularDamping = b.angularDamping;
    def.gravityScale = b.gravityScale;
    def.fixedRotation = b.fixedRotation;
    def.bullet = b.bullet;
    def.allowSleep = b.allowSleep;
    def.awake = b.awake;
    def.enabled = b.enabled;
    return def;
}

b2FixtureDef fixtureDef(const SceneShape& s, const b2Shape* shape) {
    b2FixtureDef def;
    def.shape = shape;
    def.density = s.density;
    def.friction = s.friction;        // mixed sqrt(μA μB) by both engines
    def.restitution = s.restitution;  // mixed max(eA, eB) by both engines
    def.restitutionThreshold = 1.0f;  // m/s, perpdot's WorldDef::restitutionThreshold
    def.isSensor = s.sensor;
    def.filter.categoryBits = s.filter.category;
    def.filter.maskBits = s.filter.mask;
    def.filter.groupIndex = s.filter.group;
    if (!s.enabled) {  // Box2D 2.4 cannot disable a fixture: one that collides with nothing keeps its mass, as perpdot's does
        def.filter.categoryBits = 0;
        def.filter.maskBits = 0;
        def.filter.groupIndex = 0;  // a shared positive group would collide whatever the mask
    }
    return def;
}

// The chain in Box2D's order (solid on the left) with perpdot's ghost vertices: those given, or the
// end segments continued straight on, so a shape sliding off an end meets no phantom corner.
void createChain(b2ChainShape& chain, const SceneShape& s) {
    const collide::ChainPath path = collide::box2dChainPath(Chain{s.vertices, s.loop, s.solid, s.prevVertex, s.nextVertex});
    std::vector<b2Vec2> v;
    for (Vec2 p : path.vertices) v.push_back(toB2(p));
    if (s.loop) {
        chain.CreateLoop(v.data(), int32(v.size()));
        return;
    }
    chain.CreateChain(v.data(), int32(v.size()), toB2(path.prev), toB2(path.next));
}

void createFixture(b2Body* body, const SceneShape& s) {
    switch (s.kind) {
    case SceneShape::Kind::Circle: {
        b2CircleShape circle;
        circle.m_p = toB2(s.center);
        circle.m_radius = s.radius;
        const b2FixtureDef def = fixtureDef(s, &circle);
        body->CreateFixture(&def);
        return;
    }
    case SceneShape::Kind::Box: {
        b2PolygonShape box;
        box.SetAsBox(s.halfExtents.x, s.halfExtents.y, toB2(s.center), s.angle);
        const b2FixtureDef def = fixtureDef(s, &box);
        body->CreateFixture(&def);
        return;
    }
    case SceneShape::Kind::Polygon: {
        // perpdot's validated polygon as it is, as the collide adapter hands it to Box2D:
        // b2PolygonShape::Set re-runs its own hull and asserts on thin polygons perpdot accepts.
        // Box2D 2.4 has no rounded polygons: the rounding joins the skin radius for collision,
        // and the mass (which Box2D computes from the core polygon only) is set by roundedMass().
        const b2PolygonShape shape = collide::polygonToB2(makePolygon(s.vertices, s.radius));
        const b2FixtureDef def = fixtureDef(s, &shape);
        body->CreateFixture(&def);
        return;
    }
    case SceneShape::Kind::Segment: {
        b2EdgeShape edge;
        edge.SetTwoSided(toB2(s.v1), toB2(s.v2));
        const b2FixtureDef def = fixtureDef(s, &edge);
        body->CreateFixture(&def);
        return;
    }
    case SceneShape::Kind::Capsule: {
        // Box2D 2.4 has no capsule; its exact equivalent is a 2-vertex b2PolygonShape whose
        // m_radius is the capsule radius (b2Distance, b2TimeOfImpact and the polygon manifolds take
        // it). b2PolygonShape::ComputeMass cannot (zero core area), so the fixture carries no
        // density and roundedMass() gives the body perpdot's capsule mass.
        const b2PolygonShape shape = collide::capsuleToB2(Capsule{s.v1, s.v2, s.radius});
        b2FixtureDef def = fixtureDef(s, &shape);
        def.density = 0.0f;
        body->CreateFixture(&def);
        return;
    }
    case SceneShape::Kind::Chain: {
        b2ChainShape chain;
        createChain(chain, s);
        const b2FixtureDef def = fixtureDef(s, &chain);
        body->CreateFixture(&def);
        return;
    }
    }
}

// Rounded polygons and capsules: Box2D 2.4 leaves the rounding out of the mass, perpdot includes it. Give the
// Box2D body perpdot's mass properties (area integrals of the rounded shapes) so the comparison
// measures the dynamics, not the mass model. Only bodies with a rounded polygon or a capsule are touched.
void roundedMass(b2Body* body, const SceneBody& b) {
    const bool rounded = std::any_of(b.shapes.begin(), b.shapes.end(), [](const SceneShape& s) {
        return ((s.kind == SceneShape::Kind::Polygon && s.radius > 0.0f) || s.kind == SceneShape::Kind::Capsule) && !s.sensor;
    });
    if (!rounded || b.type != BodyType::Dynamic) return;
    std::vector<MassData> parts;
    for (const SceneShape& s : b.shapes) {
        if (s.sensor || s.density <= 0.0f) continue;
        switch (s.kind) {
        case SceneShape::Kind::Circle: parts.push_back(computeMass(Circle{s.center, s.radius}, s.density)); break;
        case SceneShape::Kind::Box:
            parts.push_back(computeMass(makeBox(s.halfExtents.x, s.halfExtents.y, s.center, s.angle), s.density));
            break;
        case SceneShape::Kind::Polygon: parts.push_back(computeMass(makePolygon(s.vertices, s.radius), s.density)); break;
        case SceneShape::Kind::Capsule: parts.push_back(computeMass(Capsule{s.v1, s.v2, s.radius}, s.density)); break;
        case SceneShape::Kind::Segment:
        case SceneShape::Kind::Chain: break;
        }
    }
    const MassData m = combineMass(parts);
    b2MassData data;
    data.mass = m.mass;
    data.center = toB2(m.center);
    data.I = m.rotationalInertia + m.mass * dot(m.center, m.center);  // Box2D wants it about the origin
    body->SetMassData(&data);
}

class NameIndex {
public:
    explicit NameIndex(const Scene& scene) {
        for (size_t i = 0; i < scene.bodies.size(); ++i) index_[bodyName(scene, i)] = i;
    }
    size_t operator()(const std::string& name, const std::string& where) const {
        const auto it = index_.find(name);
        if (it == index_.end()) throw Error(where + ": no body named '" + name + "'");
        return it->second;
    }

private:
    std::unordered_map<std::string, size_t> index_;
};

// Anchors as scene-format.md defines them: a world `anchor` (B's may be given apart as
// `anchor_b`), otherwise local anchors, otherwise the bodies' origins.
struct Anchors {
    b2Vec2 localA, localB;
};
Anchors anchors(const SceneJoint& j, const b2Body* a, const b2Body* b) {
    if (j.anchor) {
        const Vec2 worldB = j.anchorB.value_or(*j.anchor);
        return {a->GetLocalPoint(toB2(*j.anchor)), b->GetLocalPoint(toB2(worldB))};
    }
    return {toB2(j.localAnchorA.value_or(Vec2{})), toB2(j.localAnchorB.value_or(Vec2{}))};
}

b2Vec2 localAxis(const b2Body* a, Vec2 worldAxis) { return a->GetLocalVector(toB2(normalize(worldAxis))); }

// `built`: the fragment's joints created so far (a gear names two of them; the reader checked
// that they are earlier revolute or prismatic joints).
b2Joint* createJoint(b2World& world, const SceneJoint& j, b2Body* a, b2Body* b, const std::vector<b2Joint*>& built) {
    const Anchors anchor = anchors(j, a, b);
    const float referenceAngle = b->GetAngle() - a->GetAngle();
    switch (j.type) {
    case JointType::Revolute: {
        b2RevoluteJointDef def;
        def.bodyA = a, def.bodyB = b, def.collideConnected = j.collideConnected;
        def.localAnchorA = anchor.localA, def.localAnchorB = anchor.localB;
        def.referenceAngle = referenceAngle;
        def.enableLimit = j.enableLimit, def.lowerAngle = j.lowerAngle, def.upperAngle = j.upperAngle;
        def.enableMotor = j.enableMotor, def.motorSpeed = j.motorSpeed, def.maxMotorTorque = j.maxMotorTorque;
        return world.CreateJoint(&def);
    }
    case JointType::Prismatic: {
        b2PrismaticJointDef def;
        def.bodyA = a, def.bodyB = b, def.collideConnected = j.collideConnected;
        def.localAnchorA = anchor.localA, def.localAnchorB = anchor.localB;
        def.localAxisA = localAxis(a, j.axis);
        def.referenceAngle = referenceAngle;
        def.enableLimit = j.enableLimit, def.lowerTranslation = j.lower, def.upperTranslation = j.upper;
        def.enableMotor = j.enableMotor, def.motorSpeed = j.motorSpeed, def.maxMotorForce = j.maxMotorForce;
        return world.CreateJoint(&def);
    }
    case JointType::Distance: {
        b2DistanceJointDef def;
        def.bodyA = a, def.bodyB = b, def.collideConnected = j.collideConnected;
        def.localAnchorA = anchor.localA, def.localAnchorB = anchor.localB;
        const float current = (b->GetWorldPoint(anchor.localB) - a->GetWorldPoint(anchor.localA)).Length();
        def.length = j.length.value_or(current);
        if (j.hertz > 0.0f) {
            def.minLength = j.minLength, def.maxLength = j.maxLength;
            b2LinearStiffness(def.stiffness, def.damping, j.hertz, j.dampingRatio, a, b);
        } else {
            // Box2D 2.4 corrects the length's drift only when min = max: that is the rigid rod.
            def.minLength = def.maxLength = def.length;
        }
        return world.CreateJoint(&def);
    }
    case JointType::Weld: {
        b2WeldJointDef def;
        def.bodyA = a, def.bodyB = b, def.collideConnected = j.collideConnected;
        def.localAnchorA = anchor.localA, def.localAnchorB = anchor.localB;
        def.referenceAngle = referenceAngle;
        if (j.hertz > 0.0f) b2AngularStiffness(def.stiffness, def.damping, j.hertz, j.dampingRatio, a, b);
        return world.CreateJoint(&def);
    }
    case JointType::Wheel: {
        b2WheelJointDef def;
        def.bodyA = a, def.bodyB = b, def.collideConnected = j.collideConnected;
        def.localAnchorA = anchor.localA, def.localAnchorB = anchor.localB;
        def.localAxisA = localAxis(a, j.axis);
        def.enableMotor = j.enableMotor, def.motorSpeed = j.motorSpeed, def.maxMotorTorque = j.maxMotorTorque;
        if (j.hertz > 0.0f) {
            b2LinearStiffness(def.stiffness, def.damping, j.hertz, j.dampingRatio, a, b);
        } else {
            // 0 hertz means rigid in the scene format; Box2D's wheel without a spring slides freely,
            // so pin the suspension with a zero-width limit instead.
            def.enableLimit = true, def.lowerTranslation = def.upperTranslation = 0.0f;
        }
        return world.CreateJoint(&def);
    }
    case JointType::Motor: {
        b2MotorJointDef def;
        def.bodyA = a, def.bodyB = b, def.collideConnected = j.collideConnected;
        def.linearOffset = toB2(j.linearOffset);
        def.angularOffset = j.angularOffset;
        def.maxForce = j.maxForce, def.maxTorque = j.maxTorque;
        return world.CreateJoint(&def);
    }
    case JointType::Friction: {
        b2FrictionJointDef def;
        def.bodyA = a, def.bodyB = b, def.collideConnected = j.collideConnected;
        def.localAnchorA = anchor.localA, def.localAnchorB = anchor.localB;
        def.maxForce = j.maxForce, def.maxTorque = j.maxTorque;
        return world.CreateJoint(&def);
    }
    case JointType::Gear: {
        if (j.jointA < 0 || j.jointB < 0 || j.jointA >= static_cast<int>(built.size()) ||
            j.jointB >= static_cast<int>(built.size()))
            throw Error("joints: a gear must name two earlier joints");
        b2GearJointDef def;
        def.bodyA = a, def.bodyB = b, def.collideConnected = j.collideConnected;
        def.joint1 = built[j.jointA], def.joint2 = built[j.jointB];
        def.ratio = j.ratio;
        return world.CreateJoint(&def);
    }
    case JointType::Pulley: {
        b2PulleyJointDef def;
        def.bodyA = a, def.bodyB = b, def.collideConnected = j.collideConnected;
        def.groundAnchorA = toB2(j.groundAnchorA), def.groundAnchorB = toB2(j.groundAnchorB);
        def.localAnchorA = anchor.localA, def.localAnchorB = anchor.localB;
        def.lengthA = j.lengthA.value_or((a->GetWorldPoint(anchor.localA) - def.groundAnchorA).Length());
        def.lengthB = j.lengthB.value_or((b->GetWorldPoint(anchor.localB) - def.groundAnchorB).Length());
        def.ratio = j.ratio;
        return world.CreateJoint(&def);
    }
    default: break;  // mouse joints, and types the format does not have
    }
    throw Error("joints: mouse joints are interactive and not part of the scene format, nor are joints of a type it does not have");
}

// b2ChainShape asserts (aborts) unless every edge, a loop's closing one included (its fixture's
// clone checks it), is longer than Box2D's linear slop; perpdot accepts edges of exactly the slop
// and a loop's short closing edge. Refused here with the shape's path instead.
void checkChainsForBox2D(const Scene& fragment) {
    for (size_t i = 0; i < fragment.bodies.size(); ++i)
        for (size_t k = 0; k < fragment.bodies[i].shapes.size(); ++k) {
            const SceneShape& s = fragment.bodies[i].shapes[k];
            if (s.kind != SceneShape::Kind::Chain) continue;
            const size_t n = s.vertices.size(), edges = s.loop ? n : n - 1;
            for (size_t e = 0; e < edges; ++e) {
                const size_t next = (e + 1) % n;
                if (b2DistanceSquared(toB2(s.vertices[e]), toB2(s.vertices[next])) > b2_linearSlop * b2_linearSlop) continue;
                throw Error("bodies[" + std::to_string(i) + "].shapes[" + std::to_string(k) + "]: Box2D 2.4 cannot build this chain: vertices " +
                            std::to_string(e) + " and " + std::to_string(next) +
                            " are not more than its linear slop (0.005 m) apart (perpdot runs it; only the cross-check refuses it)");
            }
        }
}

}  // namespace

Box2DScene::Box2DScene(const Scene& scene)
    : scene_(scene), world_(std::make_unique<b2World>(toB2(scene.gravity))) {
    // Box2D asserts on definitions perpdot refuses with an Error (a gear on a weld joint, a joint
    // between a body and itself, ...): let perpdot's checks speak first.
    (void)buildWorld(scene_);
    world_->SetAllowSleeping(scene.enableSleep);
    bodies_ = add(scene_);
    const NameIndex index(scene_);
    for (size_t i = 0; i < scene_.actions.size(); ++i) {
        const std::string where = "actions[" + std::to_string(i) + "]";
        if (scene_.actions[i].kind == SceneAction::Kind::Explosion)
            throw Error(where + ": Box2D 2.4 has no explosion (World::explode): the cross-check cannot compare this scene");
        actionBodies_.push_back(bodies_[index(scene_.actions[i].body, where + ".body")]);
    }
}

std::vector<b2Body*> Box2DScene::add(const Scene& fragment) {
    checkChainsForBox2D(fragment);
    std::vector<b2Body*> bodies;
    for (const SceneBody& b : fragment.bodies) {
        const b2BodyDef def = bodyDef(b);
        b2Body* body = world_->CreateBody(&def);
        for (const SceneShape& s : b.shapes) createFixture(body, s);
        roundedMass(body, b);
        bodies.push_back(body);
    }
    const NameIndex index(fragment);
    std::vector<b2Joint*> joints;
    for (size_t i = 0; i < fragment.joints.size(); ++i) {
        const SceneJoint& j = fragment.joints[i];
        const std::string where = "joints[" + std::to_string(i) + "]";
        if (j.breakForce || j.breakTorque)
            throw Error(where + ": Box2D 2.4 has no breakable joints (break_force, break_torque): the cross-check cannot compare this scene");
        b2Body* a = bodies[index(j.bodyA, where + ".body_a")];
        b2Body* b = bodies[index(j.bodyB, where + ".body_b")];
        joints.push_back(createJoint(*world_, j, a, b, joints));
    }
    return bodies;
}

void Box2DScene::destroy(b2Body* body) { world_->DestroyBody(body); }

void Box2DScene::applyActions(int step) {
    for (size_t i = 0; i < scene_.actions.size(); ++i) {
        const SceneAction& action = scene_.actions[i];
        if (step < action.firstStep || step > action.lastStep) continue;  // as SceneWorld::applyActions
        b2Body* body = actionBodies_[i];
        const b2Vec2 point = action.point ? toB2(*action.point) : body->GetWorldCenter();
        switch (action.kind) {
        case SceneAction::Kind::Force: body->ApplyForce(toB2(action.value), point, true); break;
        case SceneAction::Kind::Impulse: body->ApplyLinearImpulse(toB2(action.value), point, true); break;
        case SceneAction::Kind::Torque: body->ApplyTorque(action.scalar, true); break;
        case SceneAction::Kind::AngularImpulse: body->ApplyAngularImpulse(action.scalar, true); break;
        case SceneAction::Kind::Explosion: break;  // refused by the constructor
        }
    }
}

void Box2DScene::step() {
    if (!scene_.actions.empty()) applyActions(stepIndex_);
    world_->Step(scene_.timestep, scene_.solver.velocityIterations, scene_.solver.positionIterations);
    ++stepIndex_;
}

int Box2DScene::touchingContactCount() const {
    int count = 0;
    for (const b2Contact* c = world_->GetContactList(); c; c = c->GetNext()) {
        if (c->IsTouching() && !c->GetFixtureA()->IsSensor() && !c->GetFixtureB()->IsSensor()) ++count;
    }
    return count;
}

}  // namespace perpdot::crosscheck
