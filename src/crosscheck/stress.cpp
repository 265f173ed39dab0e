// The figures of `perpdot stress`: each case's probe watches every step of one engine's run
// (Stepper::sample: the scene's non-static bodies in scene order) and states what it saw.
#include "crosscheck/stress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "crosscheck/stepper.hpp"
#include "perpdot/error.hpp"

namespace perpdot::crosscheck {
namespace {

using Samples = std::vector<BodySample>;

// printf into a std::string.
template <class... Args>
std::string format(const char* pattern, Args... args) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, args...);
    return text;
}

class Probe {
public:
    virtual ~Probe() = default;
    // After each step; `time` in seconds since the start.
    virtual void observe(float time, const Samples& bodies) = 0;
    virtual StressResult result() const = 0;
};

// Index among the non-static bodies (the sample index) of the scene body named `name`.
int sampleIndex(const Scene& scene, const std::string& name) {
    int moving = 0;
    for (const SceneBody& b : scene.bodies) {
        if (b.name == name) return b.type == BodyType::Static ? -1 : moving;
        if (b.type != BodyType::Static) ++moving;
    }
    throw Error("stress scene \"" + scene.name + "\" has no body \"" + name + "\"");
}

// Stacks and pyramids: the initially highest box must stay in its column and not fall.
class ColumnProbe final : public Probe {
public:
    explicit ColumnProbe(const Scene& scene) {
        int moving = 0;
        for (const SceneBody& b : scene.bodies) {
            if (b.type == BodyType::Static) continue;
            if (top_ < 0 || b.position.y > start_.y) top_ = moving, start_ = b.position;
            ++moving;
        }
    }
    void observe(float time, const Samples& bodies) override {
        end_ = bodies[size_t(top_)].state.position;
        if (brokeAt_ < 0.0f && (std::fabs(end_.x - start_.x) >= maxDrift || start_.y - end_.y >= maxFall)) brokeAt_ = time;
    }
    StressResult result() const override {
        std::string figure = format("top drift %.3f m, fell %.3f m", std::fabs(end_.x - start_.x), start_.y - end_.y);
        if (brokeAt_ >= 0.0f) figure += format(" (out from %.2f s)", brokeAt_);
        return {.figure = figure, .pass = brokeAt_ < 0.0f};
    }
    static constexpr float maxDrift = 0.05f, maxFall = 0.5f;

private:
    int top_ = -1;
    Vec2 start_{}, end_{};
    float brokeAt_ = -1.0f;  // first time the top box was out of bounds
};

// A ball dropped from h on a ground of its restitution e: the heights of its bottom at the apexes.
class BounceProbe final : public Probe {
public:
    BounceProbe(const Scene& scene, int apexesJudged) : judged_(apexesJudged) {
        const SceneBody& ball = scene.bodies[1];
        radius_ = ball.shapes[0].radius;
        restitution_ = ball.shapes[0].restitution;
        drop_ = ball.position.y - radius_;  // the ground's top is y = 0
    }
    void observe(float, const Samples& bodies) override {
        const BodyState& s = bodies[0].state;
        if (previousVy_ > 0.0f && s.linearVelocity.y <= 0.0f) apexes_.push_back(std::max(previousY_, s.position.y) - radius_);
        previousVy_ = s.linearVelocity.y;
        previousY_ = s.position.y;
        last_ = s;
    }
    StressResult result() const override {
        // Each apex is e² times the one before: e^(2k) h after k bounces.
        std::string list;
        float worst = 0.0f;
        int judged = 0;
        for (size_t k = 0; k < apexes_.size() && judged < judged_; ++k, ++judged) {
            const float expected = drop_ * std::pow(restitution_, 2.0f * float(k + 1));
            const float error = (apexes_[k] - expected) / expected;
            if (std::fabs(error) > std::fabs(worst)) worst = error;
            if (k < 8) list += format("%s%.2f", k ? " " : "", apexes_[k]);
        }
        if (list.empty()) list = "none";
        std::string figure = format("apexes %s m, worst %+.1f %%", list.c_str(), 100.0f * worst);
        bool pass = judged == judged_ && std::fabs(worst) <= 0.02f;
        if (restitution_ < 1.0f) {  // below the restitution threshold the ball must come to rest
            const bool atRest = std::fabs(last_.linearVelocity.y) < 0.01f && last_.position.y - radius_ < 0.01f;
            figure += atRest ? ", then at rest" : ", still bouncing";
            pass = pass && atRest;
        }
        return {.figure = figure, .pass = pass};
    }

private:
    int judged_;
    float radius_ = 0, restitution_ = 0, drop_ = 0;
    float previousVy_ = 0, previousY_ = 0;
    BodyState last_{};
    std::vector<float> apexes_;
};

// A unit box placed on the ground: where its centre rests.
class RestProbe final : public Probe {
public:
    void observe(float, const Samples& bodies) override { height_ = bodies[0].center.y; }
    StressResult result() const override {
        return {.figure = format("centre at %.4f m", height_), .pass = std::fabs(height_ - 0.5f) <= 0.002f};
    }

private:
    float height_ = 0;
};

// Two bullets closing head-on along x: they must meet (velocities change), keep their momentum,
// and the right one must stay right of the left one.
class BulletsProbe final : public Probe {
public:
    void observe(float, const Samples& bodies) override {
        const BodySample &left = bodies[0], &right = bodies[1];
        if (!started_) {
            started_ = true;
            speed_ = left.state.linearVelocity.x - right.state.linearVelocity.x;
            momentum_ = left.mass * left.state.linearVelocity.x + right.mass * right.state.linearVelocity.x;
            scale_ = left.mass * std::fabs(left.state.linearVelocity.x) + right.mass * std::fabs(right.state.linearVelocity.x);
        }
        crossed_ = crossed_ || right.center.x <= left.center.x;
        closing_ = left.state.linearVelocity.x - right.state.linearVelocity.x;
        const float p = left.mass * left.state.linearVelocity.x + right.mass * right.state.linearVelocity.x;
        momentumError_ = std::max(momentumError_, std::fabs(p - momentum_) / scale_);
    }
    StressResult result() const override {
        const bool met = closing_ < 0.99f * speed_;
        std::string figure = crossed_ ? "passed through" : met ? "collided" : "never met";
        figure += format(", closing at %.1f m/s at the end (%.0f after step 1), momentum error %.1e", closing_, speed_,
                         momentumError_);
        return {.figure = figure, .pass = !crossed_ && met && closing_ <= 0.01f * speed_ && momentumError_ < 1e-4f};
    }

private:
    bool started_ = false, crossed_ = false;
    float speed_ = 0, closing_ = 0, momentum_ = 0, scale_ = 1, momentumError_ = 0;
};

// A heavy box on a light one: how much closer than 1 m their centres end, and how far either turned.
class MassRatioProbe final : public Probe {
public:
    explicit MassRatioProbe(float maxSink) : maxSink_(maxSink) {}
    void observe(float, const Samples& bodies) override {
        const BodySample &light = bodies[0], &heavy = bodies[1];
        sink_ = 1.0f - (heavy.center.y - light.center.y);
        tilt_ = std::max(std::fabs(light.state.angle), std::fabs(heavy.state.angle));
    }
    StressResult result() const override {
        return {.figure = format("sinks %.4f m, tilt %.3f rad", sink_, tilt_), .pass = sink_ < maxSink_ && tilt_ < 0.01f};
    }

private:
    float maxSink_;
    float sink_ = 0, tilt_ = 0;
};

// Revolute joints: the worst distance, over all steps, between a joint's anchor on body A and on body B.
class JointGapProbe final : public Probe {
public:
    JointGapProbe(const Scene& scene, float linkLength) : link_(linkLength) {
        for (const SceneJoint& j : scene.joints) {
            if (j.type != JointType::Revolute || !j.anchor) continue;
            joints_.push_back({side(scene, j.bodyA, *j.anchor), side(scene, j.bodyB, *j.anchor)});
        }
    }
    void observe(float, const Samples& bodies) override {
        for (const auto& [a, b] : joints_) worst_ = std::max(worst_, distance(a.world(bodies), b.world(bodies)));
    }
    StressResult result() const override {
        return {.figure = format("worst joint gap %.4f m (%.2f %% of a link)", worst_, 100.0f * worst_ / link_),
                .pass = worst_ < 0.01f * link_};
    }

private:
    struct Side {
        int sample;   // -1: a static body, at `anchor` for ever
        Vec2 anchor;  // body frame (world for a static body)
        Vec2 world(const Samples& bodies) const {
            if (sample < 0) return anchor;
            const BodyState& s = bodies[size_t(sample)].state;
            return transformPoint({s.position, Rot::fromAngle(s.angle)}, anchor);
        }
    };
    static Side side(const Scene& scene, const std::string& name, Vec2 worldAnchor) {
        const int sample = sampleIndex(scene, name);
        if (sample < 0) return {-1, worldAnchor};
        const auto body = std::find_if(scene.bodies.begin(), scene.bodies.end(), [&](const SceneBody& b) { return b.name == name; });
        return {sample, invTransformPoint({body->position, Rot::fromAngle(body->angle)}, worldAnchor)};
    }
    float link_;
    std::vector<std::pair<Side, Side>> joints_;
    float worst_ = 0;
};

// A box sliding over a floor: the largest vertical speed it picks up (a bump at a seam).
class SlideProbe final : public Probe {
public:
    void observe(float, const Samples& bodies) override {
        maxVy_ = std::max(maxVy_, std::fabs(bodies[0].state.linearVelocity.y));
        speed_ = bodies[0].state.linearVelocity.x;
    }
    StressResult result() const override {
        return {.figure = format("max |vy| %.4f m/s, vx %.2f m/s at the end", maxVy_, speed_), .pass = maxVy_ < 0.01f};
    }

private:
    float maxVy_ = 0, speed_ = 0;
};

struct Entry {
    StressCase stressCase;
    std::unique_ptr<Probe> (*makeProbe)(const Scene& scene);
};

const std::vector<Entry>& entries() {
    static const std::vector<Entry> table = {
        {{"stack30", "top box within 5 cm of its column and under 0.5 m lower, all 60 s", 600},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<ColumnProbe>(s); }},
        {{"stack50", "top box within 5 cm of its column and under 0.5 m lower, all 30 s", 600},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<ColumnProbe>(s); }},
        {{"pyramid20", "top box within 5 cm of its column and under 0.5 m lower, all 60 s", 600},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<ColumnProbe>(s); }},
        {{"bounce_e1", "each of 8 apexes within 2 % of the 3 m drop height", 0},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<BounceProbe>(s, 8); }},
        {{"bounce_e05", "first apex within 2 % of e^2 h = 0.75 m, then at rest (below the threshold)", 0},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<BounceProbe>(s, 1); }},
        {{"box_rest", "centre at 0.500 +- 0.002 m", 0},
         [](const Scene&) -> std::unique_ptr<Probe> { return std::make_unique<RestProbe>(); }},
        {{"bullets", "they collide: never cross, stop closing, momentum kept to 1e-4", 0},
         [](const Scene&) -> std::unique_ptr<Probe> { return std::make_unique<BulletsProbe>(); }},
        {{"mass100", "the heavy box sinks under 5 mm into the light one, tilt under 0.01 rad", 0},
         [](const Scene&) -> std::unique_ptr<Probe> { return std::make_unique<MassRatioProbe>(0.005f); }},
        {{"mass300", "sinks under 1 cm, tilt under 0.01 rad", 0},
         [](const Scene&) -> std::unique_ptr<Probe> { return std::make_unique<MassRatioProbe>(0.01f); }},
        {{"mass1000", "stands: sinks under 1 cm, tilt under 0.01 rad", 0},
         [](const Scene&) -> std::unique_ptr<Probe> { return std::make_unique<MassRatioProbe>(0.01f); }},
        {{"chain", "every joint gap under 1 % of a link (5 mm) at every step", 300},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<JointGapProbe>(s, 0.5f); }},
        {{"tiles", "no bump: max |vy| under 0.01 m/s", 0},
         [](const Scene&) -> std::unique_ptr<Probe> { return std::make_unique<SlideProbe>(); }},
    };
    return table;
}

}  // namespace

const std::vector<StressCase>& stressCases() {
    static const std::vector<StressCase> cases = [] {
        std::vector<StressCase> all;
        for (const Entry& e : entries()) all.push_back(e.stressCase);
        return all;
    }();
    return cases;
}

const StressCase* findStressCase(const std::string& name) {
    for (const StressCase& c : stressCases())
        if (name == c.name || name == std::string("stress_") + c.name) return &c;
    return nullptr;
}

StressResult runStress(const StressCase& stressCase, Engine engine, bool shortRun) {
    const auto entry = std::find_if(entries().begin(), entries().end(),
                                    [&](const Entry& e) { return std::string(e.stressCase.name) == stressCase.name; });
    if (entry == entries().end()) throw Error(std::string("no stress case \"") + stressCase.name + "\"");
    const Scene scene = findScene(std::string("stress_") + stressCase.name);
    const int steps = shortRun && stressCase.shortSteps > 0 ? stressCase.shortSteps : scene.steps;
    const std::unique_ptr<Probe> probe = entry->makeProbe(scene);
    const std::unique_ptr<Stepper> stepper = makeStepper(engine, scene);
    Samples bodies;
    for (int i = 0; i < steps; ++i) {
        stepper->step();
        stepper->sample(bodies);
        probe->observe(float(i + 1) * scene.timestep, bodies);
    }
    StressResult result = probe->result();
    result.steps = steps;
    return result;
}

}  // namespace perpdot::crosscheck
