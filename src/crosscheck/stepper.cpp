// The two Steppers: perpdot's SceneWorld and Box2D's b2World, sampled into the same BodySample.
#include "crosscheck/stepper.hpp"

#include "crosscheck/box2d_world.hpp"

namespace perpdot::crosscheck {
namespace {

class PerpdotStepper final : public Stepper {
public:
    explicit PerpdotStepper(const Scene& scene) : scene_(buildWorld(scene)) {}

    void step() override { scene_.step(); }

    void sample(std::vector<BodySample>& out) const override {
        out.clear();
        const World& w = scene_.world;
        for (size_t i = 0; i < scene_.bodies.size(); ++i) {
            const BodyType type = scene_.scene.bodies[i].type;
            if (type == BodyType::Static) continue;
            const BodyId id = scene_.bodies[i];
            const bool dynamic = type == BodyType::Dynamic;
            out.push_back({.state = {w.position(id), w.angle(id), w.linearVelocity(id), w.angularVelocity(id)},
                           .center = w.worldCenter(id),
                           .mass = dynamic ? w.mass(id) : 0.0f,
                           .inertia = dynamic ? w.rotationalInertia(id) : 0.0f,
                           .gravityScale = w.gravityScale(id)});
        }
    }

    int contactCount() const override { return scene_.world.contactCount(); }

private:
    SceneWorld scene_;
};

class Box2DStepper final : public Stepper {
public:
    explicit Box2DStepper(const Scene& scene) : scene_(scene) {}

    void step() override { scene_.step(); }

    void sample(std::vector<BodySample>& out) const override {
        out.clear();
        for (size_t i = 0; i < scene_.scene().bodies.size(); ++i) {
            const b2Body* b = scene_.body(int(i));
            if (b->GetType() == b2_staticBody) continue;
            const b2Vec2 p = b->GetPosition(), v = b->GetLinearVelocity(), c = b->GetWorldCenter();
            const b2Vec2 local = b->GetLocalCenter();
            const float m = b->GetMass();
            out.push_back({.state = {{p.x, p.y}, b->GetAngle(), {v.x, v.y}, b->GetAngularVelocity()},
                           .center = {c.x, c.y},
                           .mass = m,
                           // GetInertia() is about the body origin; parallel-axis back to the centre.
                           .inertia = b->GetInertia() - m * b2Dot(local, local),
                           .gravityScale = b->GetGravityScale()});
        }
    }

    int contactCount() const override { return scene_.touchingContactCount(); }

private:
    Box2DScene scene_;
};

}  // namespace

const char* engineName(Engine engine) { return engine == Engine::Perpdot ? "perpdot" : "box2d"; }

std::unique_ptr<Stepper> makeStepper(Engine engine, const Scene& scene) {
    if (engine == Engine::Perpdot) return std::make_unique<PerpdotStepper>(scene);
    return std::make_unique<Box2DStepper>(scene);
}

std::string bodyName(const Scene& scene, size_t index) {
    const std::string& name = scene.bodies[index].name;
    return name.empty() ? "body" + std::to_string(index) : name;
}

std::vector<std::string> movingBodyNames(const Scene& scene) {
    std::vector<std::string> names;
    for (size_t i = 0; i < scene.bodies.size(); ++i) {
        if (scene.bodies[i].type != BodyType::Static) names.push_back(bodyName(scene, i));
    }
    return names;
}

}  // namespace perpdot::crosscheck
