// The two Steppers: perpdot's SceneWorld and Box2D's b2World, sampled into the same BodySample.
// Each is also the SceneEditor of the scene's script, so both engines spawn, destroy and drive the
// same bodies before the same steps.
#include "crosscheck/stepper.hpp"

#include <string>
#include <utility>

#include "crosscheck/box2d_world.hpp"
#include "perpdot/error.hpp"
#include "scene/build_world.hpp"

namespace perpdot::crosscheck {
namespace {

// The bodies of each spawn() so far, by group; a destroyed group is left empty.
template <class Body>
class Groups {
public:
    SceneEditor::Group add(std::vector<Body> bodies) {
        if (bodies.empty()) throw Error("scene script: spawn() needs a fragment with at least one body");
        groups_.push_back(std::move(bodies));
        return SceneEditor::Group(groups_.size() - 1);
    }
    // The group's bodies, which the caller destroys; Error for a group never spawned or destroyed already.
    std::vector<Body> take(SceneEditor::Group group) {
        if (group < 0 || size_t(group) >= groups_.size() || groups_[size_t(group)].empty())
            throw Error("scene script: group " + std::to_string(group) + " was never spawned or is destroyed already");
        return std::exchange(groups_[size_t(group)], {});
    }
    const std::vector<std::vector<Body>>& all() const { return groups_; }

private:
    std::vector<std::vector<Body>> groups_;
};

// A script's body index, checked against the scene's body count.
size_t sceneBodyIndex(int sceneBody, size_t bodyCount) {
    if (sceneBody < 0 || size_t(sceneBody) >= bodyCount)
        throw Error("scene script: setVelocity() of body " + std::to_string(sceneBody) + ", but the scene has " +
                    std::to_string(bodyCount) + " bodies");
    return size_t(sceneBody);
}

BodySample samplePerpdot(const World& w, BodyId id) {
    const bool dynamic = w.bodyType(id) == BodyType::Dynamic;
    return {.state = {w.position(id), w.angle(id), w.linearVelocity(id), w.angularVelocity(id)},
            .center = w.worldCenter(id),
            .mass = dynamic ? w.mass(id) : 0.0f,
            .inertia = dynamic ? w.rotationalInertia(id) : 0.0f,
            .gravityScale = w.gravityScale(id)};
}

BodySample sampleBox2D(const b2Body* b) {
    const b2Vec2 p = b->GetPosition(), v = b->GetLinearVelocity(), c = b->GetWorldCenter();
    const b2Vec2 local = b->GetLocalCenter();
    const float m = b->GetMass();
    return {.state = {{p.x, p.y}, b->GetAngle(), {v.x, v.y}, b->GetAngularVelocity()},
            .center = {c.x, c.y},
            .mass = m,
            // GetInertia() is about the body origin; parallel-axis back to the centre.
            .inertia = b->GetInertia() - m * b2Dot(local, local),
            .gravityScale = b->GetGravityScale()};
}

class PerpdotStepper final : public Stepper, private SceneEditor {
public:
    PerpdotStepper(const Scene& scene, std::unique_ptr<SceneScript> script, int workerCount)
        : scene_(buildWorld(scene, workerCount)), script_(std::move(script)) {}

    void step() override {
        if (script_) script_->beforeStep(scene_.stepIndex, *this);
        scene_.step();
    }

    void sample(std::vector<BodySample>& out) const override {
        out.clear();
        for (size_t i = 0; i < scene_.bodies.size(); ++i)
            if (scene_.scene.bodies[i].type != BodyType::Static) out.push_back(samplePerpdot(scene_.world, scene_.bodies[i]));
    }

    void sampleAll(std::vector<BodySample>& out) const override {
        sample(out);
        for (const std::vector<BodyId>& group : spawned_.all())
            for (const BodyId id : group)
                if (scene_.world.bodyType(id) != BodyType::Static) out.push_back(samplePerpdot(scene_.world, id));
    }

    int contactCount() const override { return scene_.world.contactCount(); }

private:
    Group spawn(const Scene& fragment) override { return spawned_.add(addToWorld(scene_.world, fragment).bodies); }
    void destroy(Group group) override {
        for (const BodyId body : spawned_.take(group)) scene_.world.destroyBody(body);
    }
    void setVelocity(int sceneBody, Vec2 linearVelocity, float angularVelocity) override {
        const BodyId body = scene_.bodies[sceneBodyIndex(sceneBody, scene_.bodies.size())];
        scene_.world.setLinearVelocity(body, linearVelocity);
        scene_.world.setAngularVelocity(body, angularVelocity);
    }

    SceneWorld scene_;
    std::unique_ptr<SceneScript> script_;
    Groups<BodyId> spawned_;
};

class Box2DStepper final : public Stepper, private SceneEditor {
public:
    Box2DStepper(const Scene& scene, std::unique_ptr<SceneScript> script) : scene_(scene), script_(std::move(script)) {}

    void step() override {
        if (script_) script_->beforeStep(scene_.stepIndex(), *this);
        scene_.step();
    }

    void sample(std::vector<BodySample>& out) const override {
        out.clear();
        for (size_t i = 0; i < scene_.scene().bodies.size(); ++i) {
            const b2Body* b = scene_.body(int(i));
            if (b->GetType() != b2_staticBody) out.push_back(sampleBox2D(b));
        }
    }

    void sampleAll(std::vector<BodySample>& out) const override {
        sample(out);
        for (const std::vector<b2Body*>& group : spawned_.all())
            for (const b2Body* b : group)
                if (b->GetType() != b2_staticBody) out.push_back(sampleBox2D(b));
    }

    int contactCount() const override { return scene_.touchingContactCount(); }

private:
    Group spawn(const Scene& fragment) override { return spawned_.add(scene_.add(fragment)); }
    void destroy(Group group) override {
        for (b2Body* body : spawned_.take(group)) scene_.destroy(body);
    }
    void setVelocity(int sceneBody, Vec2 linearVelocity, float angularVelocity) override {
        b2Body* body = scene_.body(int(sceneBodyIndex(sceneBody, scene_.scene().bodies.size())));
        body->SetLinearVelocity({linearVelocity.x, linearVelocity.y});
        body->SetAngularVelocity(angularVelocity);
    }

    Box2DScene scene_;
    std::unique_ptr<SceneScript> script_;
    Groups<b2Body*> spawned_;
};

}  // namespace

const char* engineName(Engine engine) { return engine == Engine::Perpdot ? "perpdot" : "box2d"; }

std::unique_ptr<Stepper> makeStepper(Engine engine, const Scene& scene) {
    return makeStepper(engine, scene, makeSceneScript(scene.name));
}

std::unique_ptr<Stepper> makeStepper(Engine engine, const Scene& scene, std::unique_ptr<SceneScript> script,
                                     int workerCount) {
    if (engine == Engine::Perpdot) return std::make_unique<PerpdotStepper>(scene, std::move(script), workerCount);
    return std::make_unique<Box2DStepper>(scene, std::move(script));
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
