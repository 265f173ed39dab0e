// The figures of `perpdot stress`: each case's probe watches every step of one engine's run
// (Stepper::sample: the scene's non-static bodies in scene order) and states what it saw.
#include "crosscheck/stress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <utility>

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

// Bounds on a column's top box: aside from its column, below and above where it started.
struct ColumnBounds {
    float drift = 0.05f, fall = 0.5f, rise = 0.1f;
};

// Stacks and pyramids: the initially highest box must stay in its column, neither falling nor
// rising (a contact rests up to about 1 mm above the true surfaces, docs/stress.md: a 50-box
// column stands about 5 cm taller than placed; more than 10 cm is a stack pushed apart).
class ColumnProbe final : public Probe {
public:
    explicit ColumnProbe(const Scene& scene, ColumnBounds bounds = {}) : bounds_(bounds) {
        int moving = 0;
        for (const SceneBody& b : scene.bodies) {
            if (b.type == BodyType::Static) continue;
            if (top_ < 0 || b.position.y > start_.y) top_ = moving, start_ = b.position;
            ++moving;
        }
    }
    void observe(float time, const Samples& bodies) override {
        end_ = bodies[size_t(top_)].state.position;
        rose_ = std::max(rose_, end_.y - start_.y);
        const float drift = std::fabs(end_.x - start_.x);
        drift_ = std::max(drift_, drift);
        const bool out = drift >= bounds_.drift || start_.y - end_.y >= bounds_.fall || end_.y - start_.y >= bounds_.rise;
        if (brokeAt_ < 0.0f && out) brokeAt_ = time;
    }
    StressResult result() const override {
        std::string figure = format("top drift %.3f m (at most %.3f m), fell %.3f m, rose at most %.4f m", std::fabs(end_.x - start_.x),
                                    drift_, start_.y - end_.y, rose_);
        if (brokeAt_ >= 0.0f) figure += format(" (out from %.2f s)", brokeAt_);
        return {.figure = figure, .pass = brokeAt_ < 0.0f};
    }
private:
    ColumnBounds bounds_;
    int top_ = -1;
    Vec2 start_{}, end_{};
    float rose_ = 0;   // the highest the top box went above where it started
    float drift_ = 0;  // the farthest it went sideways
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

// A unit box placed on the ground: where its centre rests, and the farthest it strays at any step.
class RestProbe final : public Probe {
public:
    void observe(float, const Samples& bodies) override {
        height_ = bodies[0].center.y;
        worst_ = std::max(worst_, std::fabs(height_ - 0.5f));
    }
    StressResult result() const override {
        return {.figure = format("centre at %.4f m, at most %.4f m off", height_, worst_), .pass = worst_ <= 0.002f};
    }

private:
    float height_ = 0, worst_ = 0;
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

// A heavy box on a light one: the most their centres come closer than 1 m, and the most either
// turns, over every step.
class MassRatioProbe final : public Probe {
public:
    explicit MassRatioProbe(float maxSink) : maxSink_(maxSink) {}
    void observe(float, const Samples& bodies) override {
        const BodySample &light = bodies[0], &heavy = bodies[1];
        sink_ = std::max(sink_, 1.0f - (heavy.center.y - light.center.y));
        tilt_ = std::max({tilt_, std::fabs(light.state.angle), std::fabs(heavy.state.angle)});
    }
    StressResult result() const override {
        return {.figure = format("sinks at most %.4f m, tilt at most %.3f rad", sink_, tilt_),
                .pass = sink_ < maxSink_ && tilt_ < 0.01f};
    }

private:
    float maxSink_;
    float sink_ = -std::numeric_limits<float>::infinity(), tilt_ = 0;
};

// The hinges, welds and sliders of a chain or bridge, each judged by what it holds at every step:
// a hinge's anchor gap, a weld's gap and bend, a slider's offset from its axis, its turn and how
// far it is past a limit; each gap within 1 % of a link (`linkLength`), each turn within 0.01 rad.
class JointGapProbe final : public Probe {
public:
    JointGapProbe(const Scene& scene, float linkLength) : link_(linkLength) {
        for (const SceneJoint& j : scene.joints) {
            const bool held = j.type == JointType::Revolute || j.type == JointType::Weld || j.type == JointType::Prismatic;
            if (!held || !j.anchor) continue;
            Held h{j.type, side(scene, j.bodyA, *j.anchor), side(scene, j.bodyB, *j.anchor)};
            h.referenceAngle = h.b.startAngle - h.a.startAngle;
            h.axis = rotate(Rot::fromAngle(-h.a.startAngle), normalize(j.axis));
            if (j.type == JointType::Prismatic && j.enableLimit) h.lower = j.lower, h.upper = j.upper;
            turns_ = turns_ || j.type != JointType::Revolute;
            joints_.push_back(h);
        }
    }
    void observe(float, const Samples& bodies) override {
        for (const Held& h : joints_) {
            const Vec2 d = h.b.world(bodies) - h.a.world(bodies);
            if (h.type != JointType::Prismatic) worst_ = std::max(worst_, length(d));
            if (h.type == JointType::Revolute) continue;
            turn_ = std::max(turn_, std::fabs(h.b.angle(bodies) - h.a.angle(bodies) - h.referenceAngle));
            if (h.type == JointType::Weld) continue;
            const Vec2 axis = rotate(Rot::fromAngle(h.a.angle(bodies)), h.axis);
            const float translation = dot(axis, d);
            worst_ = std::max(worst_, std::fabs(dot(perp(axis), d)));
            past_ = std::max({past_, translation - h.upper, h.lower - translation});
        }
    }
    StressResult result() const override {
        std::string figure = format("worst joint gap %.4f m (%.2f %% of a link)", worst_, 100.0f * worst_ / link_);
        if (turns_) figure += format("; welds and sliders turned at most %.4f rad, sliders at most %.4f m past a limit", turn_, past_);
        return {.figure = figure, .pass = worst_ < 0.01f * link_ && turn_ < 0.01f && past_ < 0.01f * link_};
    }

private:
    struct Side {
        int sample;        // -1: a static body, at `anchor` for ever
        Vec2 anchor;       // body frame (world for a static body)
        float startAngle;  // the body's angle in the scene
        Vec2 world(const Samples& bodies) const {
            if (sample < 0) return anchor;
            const BodyState& s = bodies[size_t(sample)].state;
            return transformPoint({s.position, Rot::fromAngle(s.angle)}, anchor);
        }
        float angle(const Samples& bodies) const { return sample < 0 ? startAngle : bodies[size_t(sample)].state.angle; }
    };
    struct Held {
        JointType type;
        Side a, b;
        float referenceAngle = 0;
        Vec2 axis;  // a slider's, in A's frame
        float lower = -std::numeric_limits<float>::infinity(), upper = std::numeric_limits<float>::infinity();
    };
    static Side side(const Scene& scene, const std::string& name, Vec2 worldAnchor) {
        const auto body = std::find_if(scene.bodies.begin(), scene.bodies.end(), [&](const SceneBody& b) { return b.name == name; });
        const int sample = sampleIndex(scene, name);
        if (sample < 0) return {-1, worldAnchor, body->angle};
        return {sample, invTransformPoint({body->position, Rot::fromAngle(body->angle)}, worldAnchor), body->angle};
    }
    float link_;
    std::vector<Held> joints_;
    bool turns_ = false;
    float worst_ = 0, turn_ = 0, past_ = 0;
};

// A bridge's hinges (JointGapProbe) and its load: the load's centre never more than `maxDrop`
// below where it was placed, so that closed hinges under a load that got away do not pass.
class LoadedBridgeProbe final : public Probe {
public:
    LoadedBridgeProbe(const Scene& scene, float plank, float maxDrop) : gaps_(scene, plank), load_(sampleIndex(scene, "load")), maxDrop_(maxDrop) {
        for (const SceneBody& b : scene.bodies)
            if (b.name == "load") placed_ = b.position.y;
    }
    void observe(float time, const Samples& bodies) override {
        gaps_.observe(time, bodies);
        drop_ = std::max(drop_, placed_ - bodies[size_t(load_)].center.y);
    }
    StressResult result() const override {
        StressResult r = gaps_.result();
        r.figure += format("; the load at most %.2f m below its start", drop_);
        r.pass = r.pass && drop_ < maxDrop_;
        return r;
    }

private:
    JointGapProbe gaps_;
    int load_;
    float maxDrop_, placed_ = 0, drop_ = 0;
};

// A box sliding without friction over a floor: the largest vertical speed it picks up (a bump at
// a seam) and how far its horizontal speed strays from the start's (a catch at a seam slows it).
class SlideProbe final : public Probe {
public:
    void observe(float, const Samples& bodies) override {
        const Vec2 v = bodies[0].state.linearVelocity;
        if (!started_) started_ = true, startVx_ = v.x;
        maxVy_ = std::max(maxVy_, std::fabs(v.y));
        worstVx_ = std::max(worstVx_, std::fabs(v.x - startVx_));
        speed_ = v.x;
    }
    StressResult result() const override {
        return {.figure = format("max |vy| %.4f m/s, vx %.2f m/s at the end, at most %.4f m/s off its start", maxVy_,
                                 speed_, worstVx_),
                .pass = maxVy_ < 0.01f && worstVx_ < 0.01f * std::fabs(startVx_)};
    }

private:
    bool started_ = false;
    float maxVy_ = 0, speed_ = 0, startVx_ = 0, worstVx_ = 0;
};

// Bodies that only collide with each other (zero gravity): momentum kept at every step, kinetic
// energy kept to `energyTolerance` at the end, and, where given, each body's final velocity along
// x within 5 % of `speed` of the expected one (and across x under the same).
class ImpactProbe final : public Probe {
public:
    ImpactProbe(std::vector<float> expectedVx, float speed, float energyTolerance)
        : expected_(std::move(expectedVx)), speed_(speed), energyTolerance_(energyTolerance) {}
    void observe(float, const Samples& bodies) override {
        Vec2 p{};
        float scale = 0.0f;
        for (const BodySample& b : bodies) {
            p = p + b.mass * b.state.linearVelocity;
            scale += b.mass * length(b.state.linearVelocity);
        }
        if (!started_) started_ = true, momentum_ = p, scale_ = scale, energy0_ = energy(bodies);
        momentumError_ = std::max(momentumError_, length(p - momentum_) / scale_);
        energy_ = energy(bodies);
        last_ = bodies;
    }
    StressResult result() const override {
        float worst = 0.0f;
        std::string list;
        for (size_t i = 0; i < expected_.size() && i < last_.size(); ++i) {
            const Vec2 v = last_[i].state.linearVelocity;
            worst = std::max({worst, std::fabs(v.x - expected_[i]), std::fabs(v.y)});
            list += format("%s%.2f", i ? " " : "", v.x);
        }
        const float energyChange = (energy_ - energy0_) / energy0_;
        std::string figure = format("energy %+.1f %%, momentum error %.1e", 100.0f * energyChange, momentumError_);
        if (!expected_.empty()) figure = format("vx %s m/s (worst %.2f off), ", list.c_str(), worst) + figure;
        return {.figure = figure,
                .pass = momentumError_ < 1e-4f && std::fabs(energyChange) <= energyTolerance_ && worst <= 0.05f * speed_};
    }

private:
    static float energy(const Samples& bodies) {
        float e = 0.0f;
        for (const BodySample& b : bodies)
            e += 0.5f * (b.mass * dot(b.state.linearVelocity, b.state.linearVelocity) +
                         b.inertia * b.state.angularVelocity * b.state.angularVelocity);
        return e;
    }
    std::vector<float> expected_;
    float speed_, energyTolerance_;
    bool started_ = false;
    Vec2 momentum_{};
    float scale_ = 1.0f, energy0_ = 1.0f, energy_ = 0.0f, momentumError_ = 0.0f;
    Samples last_;
};

// One coordinate of the first moving body, a box (its angle, or how far it moved along y), which
// must stay within [lower, upper] widened by `slack` at every step; and the ball named "striker"
// must not sink more than `maxSink` into that box: a joint may not hold its pose by letting the
// blow pass through its body (Box2D 2.4.1 holds `weld_hit`'s arm straight while the ball passes
// through it).
class BoundProbe final : public Probe {
public:
    enum class Coordinate { Angle, Y };
    BoundProbe(const Scene& scene, Coordinate coordinate, float lower, float upper, float slack, float maxSink)
        : coordinate_(coordinate), lower_(lower), upper_(upper), slack_(slack), maxSink_(maxSink),
          striker_(sampleIndex(scene, "striker")) {
        for (const SceneBody& b : scene.bodies) {
            if (b.type == BodyType::Static) continue;
            if (halfExtents_.x == 0.0f) halfExtents_ = b.shapes.at(0).halfExtents;  // the first moving body
            if (b.name == "striker") radius_ = b.shapes.at(0).radius;
        }
    }
    void observe(float, const Samples& bodies) override {
        const BodyState& s = bodies[0].state;
        const float value = coordinate_ == Coordinate::Angle ? s.angle : s.position.y;
        if (!started_) started_ = true, origin_ = coordinate_ == Coordinate::Angle ? 0.0f : value;
        low_ = std::min(low_, value - origin_);
        high_ = std::max(high_, value - origin_);
        sink_ = std::max(sink_, sink(s, bodies[static_cast<size_t>(striker_)].state.position));
    }
    StressResult result() const override {
        const char* unit = coordinate_ == Coordinate::Angle ? "rad" : "m";
        return {.figure = format("ranged %.4f to %.4f %s (bounds %.2f to %.2f); the ball at most %.3f m into it", low_, high_,
                                 unit, lower_, upper_, sink_),
                .pass = low_ >= lower_ - slack_ && high_ <= upper_ + slack_ && sink_ <= maxSink_};
    }

private:
    // How deep a circle of radius_ about `centre` reaches into the box of halfExtents_ at `box`.
    float sink(const BodyState& box, Vec2 centre) const {
        const Vec2 d = centre - box.position;
        const float c = std::cos(box.angle), s = std::sin(box.angle);
        const Vec2 local{c * d.x + s * d.y, -s * d.x + c * d.y};  // Rᵀ d
        const Vec2 outside{std::max(std::fabs(local.x) - halfExtents_.x, 0.0f), std::max(std::fabs(local.y) - halfExtents_.y, 0.0f)};
        if (outside.x > 0.0f || outside.y > 0.0f) return radius_ - std::sqrt(outside.x * outside.x + outside.y * outside.y);
        return radius_ + std::min(halfExtents_.x - std::fabs(local.x), halfExtents_.y - std::fabs(local.y));
    }

    Coordinate coordinate_;
    float lower_, upper_, slack_, maxSink_;
    int striker_;
    Vec2 halfExtents_{};
    float radius_ = 0.0f;
    bool started_ = false;
    float origin_ = 0.0f, low_ = std::numeric_limits<float>::infinity(), high_ = -std::numeric_limits<float>::infinity();
    float sink_ = -std::numeric_limits<float>::infinity();
};

// Newton's cradle on pendulum strings under gravity (the stress_cradle_strings scene: the balls
// hung from a static ceiling, which is not sampled, the first `released` pulled aside). They meet the row at
// u = √(2 |g| h), h the released balls' height above the others; once the last ball is struck
// (vx > u/2), each ball's largest speed over the next quarter swing must be the textbook's within
// 5 % of u: u for the last `released`, 0 for the others. The mechanical energy
// Σ m (v²/2 − g·(p − p₀)), p₀ where the balls hang at rest, is kept to 1 % at every step.
class SwingProbe final : public Probe {
public:
    SwingProbe(const Scene& scene, int released) : gravity_(scene.gravity), released_(released) {}
    void observe(float, const Samples& bodies) override {
        if (!started_) {
            started_ = true;
            rest_ = bodies.back().state.position;
            energy0_ = energy(bodies);
            speed_ = std::sqrt(2.0f * length(gravity_) * (bodies.front().state.position.y - bodies.back().state.position.y));
            fastest_.assign(bodies.size(), 0.0f);
        }
        worstEnergy_ = std::max(worstEnergy_, std::fabs(energy(bodies) - energy0_) / std::fabs(energy0_));
        if (struckSteps_ == 0 && bodies.back().state.linearVelocity.x <= 0.5f * speed_) return;
        if (struckSteps_++ >= quarterSwing) return;
        for (size_t i = 0; i < bodies.size(); ++i) fastest_[i] = std::max(fastest_[i], length(bodies[i].state.linearVelocity));
    }
    StressResult result() const override {
        float worst = 0.0f;
        std::string list;
        const int count = static_cast<int>(fastest_.size());
        for (int i = 0; i < count; ++i) {
            const float expected = i >= count - released_ ? speed_ : 0.0f;
            worst = std::max(worst, std::fabs(fastest_[static_cast<size_t>(i)] - expected));
            list += format("%s%.2f", i ? " " : "", fastest_[static_cast<size_t>(i)]);
        }
        const bool struck = struckSteps_ > 0;
        return {.figure = struck ? format("fastest after the strike %s m/s (u = %.2f, worst %.2f off), energy within %.1f %%", list.c_str(),
                                          speed_, worst, 100.0f * worstEnergy_)
                                 : std::string("the last ball was never struck"),
                .pass = struck && worst <= 0.05f * speed_ && worstEnergy_ <= 0.01f};
    }

private:
    static constexpr int quarterSwing = 30;  // steps: a quarter of 2π √(L/g) for the 1 m strings
    float energy(const Samples& bodies) const {
        float e = 0.0f;
        for (const BodySample& b : bodies)
            e += b.mass * (0.5f * dot(b.state.linearVelocity, b.state.linearVelocity) - dot(gravity_, b.state.position - rest_));
        return e;
    }
    Vec2 gravity_, rest_;
    int released_;
    bool started_ = false;
    float energy0_ = 1.0f, speed_ = 0.0f, worstEnergy_ = 0.0f;
    int struckSteps_ = 0;
    std::vector<float> fastest_;
};

struct Entry {
    StressCase stressCase;
    std::unique_ptr<Probe> (*makeProbe)(const Scene& scene);
};

const std::vector<Entry>& entries() {
    static const std::vector<Entry> table = {
        {{"stack30", "top box within 5 cm of its column, under 0.5 m lower and 10 cm higher, all 60 s", 600},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<ColumnProbe>(s); }},
        {{"stack50", "top box within 5 cm of its column, under 0.5 m lower and 10 cm higher, all 30 s", 600},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<ColumnProbe>(s); }},
        {{"pyramid20", "top box within 5 cm of its column, under 0.5 m lower and 10 cm higher, all 60 s", 600},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<ColumnProbe>(s); }},
        {{"bounce_e1", "each of 8 apexes within 2 % of the 3 m drop height", 0},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<BounceProbe>(s, 8); }},
        {{"bounce_e05", "first apex within 2 % of e^2 h = 0.75 m, then at rest (below the threshold)", 0},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<BounceProbe>(s, 1); }},
        {{"box_rest", "centre at 0.500 +- 0.002 m at every step", 0},
         [](const Scene&) -> std::unique_ptr<Probe> { return std::make_unique<RestProbe>(); }},
        {{"bullets", "they collide: never cross, stop closing, momentum kept to 1e-4", 0},
         [](const Scene&) -> std::unique_ptr<Probe> { return std::make_unique<BulletsProbe>(); }},
        {{"mass100", "the heavy box sinks under 5 mm into the light one, tilt under 0.01 rad, at every step", 0},
         [](const Scene&) -> std::unique_ptr<Probe> { return std::make_unique<MassRatioProbe>(0.005f); }},
        {{"mass300", "sinks under 1 cm, tilt under 0.01 rad, at every step", 0},
         [](const Scene&) -> std::unique_ptr<Probe> { return std::make_unique<MassRatioProbe>(0.01f); }},
        {{"mass1000", "stands: sinks under 1 cm, tilt under 0.01 rad, at every step", 0},
         [](const Scene&) -> std::unique_ptr<Probe> { return std::make_unique<MassRatioProbe>(0.01f); }},
        {{"chain", "every joint gap under 1 % of a link (5 mm) at every step", 300},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<JointGapProbe>(s, 0.5f); }},
        {{"tiles", "no bump or catch: |vy| under 0.01 m/s, vx within 1 % of its start, at every step", 0},
         [](const Scene&) -> std::unique_ptr<Probe> { return std::make_unique<SlideProbe>(); }},
        // The frontier cases: textbook outcomes that game engines miss (docs/stress.md). Their
        // criteria were written before perpdot or Box2D ran them.
        {{"pile20", "the 20-row pyramid's top within 5 mm of its placed height and 5 cm of its column, all 60 s", 600},
         [](const Scene& s) -> std::unique_ptr<Probe> {
             return std::make_unique<ColumnProbe>(s, ColumnBounds{.fall = 0.005f, .rise = 0.005f});
         }},
        {{"large_pile", "the large_pyramid scene's top within 5 cm of its placed height and 5 cm of its column, all 10 s", 0},
         [](const Scene& s) -> std::unique_ptr<Probe> {
             return std::make_unique<ColumnProbe>(s, ColumnBounds{.fall = 0.05f, .rise = 0.05f});
         }},
        {{"column100", "the top box within 1 cm of its placed height and 5 cm of its column, all 30 s", 600},
         [](const Scene& s) -> std::unique_ptr<Probe> {
             return std::make_unique<ColumnProbe>(s, ColumnBounds{.fall = 0.01f, .rise = 0.01f});
         }},
        {{"cradle5", "ends 0 0 0 0 2 m/s (within 5 %), energy kept to 1 %, momentum to 1e-4", 0},
         [](const Scene&) -> std::unique_ptr<Probe> { return std::make_unique<ImpactProbe>(std::vector<float>{0, 0, 0, 0, 2}, 2.0f, 0.01f); }},
        {{"cradle7_two", "ends 0 0 0 0 0 2 2 m/s (within 5 %), energy kept to 1 %, momentum to 1e-4", 0},
         [](const Scene&) -> std::unique_ptr<Probe> {
             return std::make_unique<ImpactProbe>(std::vector<float>{0, 0, 0, 0, 0, 2, 2}, 2.0f, 0.01f);
         }},
        {{"cradle_gaps", "ends 0 0 2 2 2 m/s (within 5 %), energy kept to 1 %, momentum to 1e-4", 0},
         [](const Scene&) -> std::unique_ptr<Probe> { return std::make_unique<ImpactProbe>(std::vector<float>{0, 0, 2, 2, 2}, 2.0f, 0.01f); }},
        {{"cradle_strings", "after the strike the last three swing out at u and the others stay (fastest speed each within 5 % of u), energy kept to 1 % at every step", 0},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<SwingProbe>(s, 3); }},
        {{"billiards", "energy kept to 2 %, momentum to 1e-4", 0},
         [](const Scene&) -> std::unique_ptr<Probe> { return std::make_unique<ImpactProbe>(std::vector<float>{}, 5.0f, 0.02f); }},
        {{"hinge_hit", "the arm's angle within its +-0.05 rad limit, overshooting at most 0.01 rad, at every step; the ball never 1 cm into it", 0},
         [](const Scene& s) -> std::unique_ptr<Probe> {
             return std::make_unique<BoundProbe>(s, BoundProbe::Coordinate::Angle, -0.05f, 0.05f, 0.01f, 0.01f);
         }},
        {{"weld_hit", "the welded arm bends at most 0.01 rad at every step; the ball never 1 cm into it", 0},
         [](const Scene& s) -> std::unique_ptr<Probe> {
             return std::make_unique<BoundProbe>(s, BoundProbe::Coordinate::Angle, 0.0f, 0.0f, 0.01f, 0.01f);
         }},
        {{"slider_hit", "the slider within its +-5 cm limit, overshooting at most 1 cm, at every step; the ball never 1 cm into it", 0},
         [](const Scene& s) -> std::unique_ptr<Probe> {
             return std::make_unique<BoundProbe>(s, BoundProbe::Coordinate::Y, -0.05f, 0.05f, 0.01f, 0.01f);
         }},
        {{"chain1000", "every joint gap under 1 % of a link (5 mm) at every step", 300},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<JointGapProbe>(s, 0.5f); }},
        {{"chain10k", "every joint gap under 1 % of a link (5 mm) at every step", 300},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<JointGapProbe>(s, 0.5f); }},
        {{"mixed1000", "every joint within 1 % of a link (5 mm) of its axis, the welds and sliders turned under 0.01 rad, the sliders under 5 mm past their limits, at every step", 300},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<JointGapProbe>(s, 0.5f); }},
        {{"bridge1000", "every joint gap under 1 % of a plank (5 mm) at every step; the load carried, never 1 m below its start", 300},
         [](const Scene& s) -> std::unique_ptr<Probe> { return std::make_unique<LoadedBridgeProbe>(s, 0.5f, 1.0f); }},
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
