// The viewer driven as a user drives it: synthetic SDL key, mouse and wheel events in the dummy
// video driver, frame by frame, asserting what moved — the world, the camera, the mover, the
// panel's toggles and the Box2D overlay.
#ifdef PERPDOT_DEMO

#include <SDL.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>

#include "perpdot/feature_scenes.hpp"
#include "sdl_handles.hpp"
#include "viewer.hpp"

namespace perpdot::demo {
namespace {

constexpr double frameSeconds = 1.0 / 60.0;  // one step of every scene used here

// A dummy-driver window with a software renderer, ImGui, and a Viewer on `scene`.
class ViewerInteraction : public testing::Test {
protected:
    void open(const std::string& scene) {
        setenv("SDL_VIDEODRIVER", "dummy", 1);
        sdl_ = std::make_unique<SdlLibrary>(SDL_INIT_VIDEO | SDL_INIT_TIMER);
        ASSERT_TRUE(sdl_->ok) << SDL_GetError();
        window_.reset(SDL_CreateWindow("perpdot test", 0, 0, 1280, 800, 0));
        ASSERT_TRUE(window_) << SDL_GetError();
        renderer_.reset(SDL_CreateRenderer(window_.get(), -1, SDL_RENDERER_SOFTWARE));
        ASSERT_TRUE(renderer_) << SDL_GetError();
        imgui_ = std::make_unique<ImGuiLayer>(window_.get(), renderer_.get());
        viewer_ = std::make_unique<Viewer>(Options{.scene = scene}, renderer_.get());
        frames(2);  // the panel lays itself out in its first frames
    }
    void TearDown() override {
        viewer_.reset();
        imgui_.reset();
        renderer_.reset();
        window_.reset();
        sdl_.reset();
    }

    void frames(int n) {
        for (int i = 0; i < n; ++i) viewer_->frame(frameSeconds);
    }
    void push(SDL_Event e) { ASSERT_EQ(SDL_PushEvent(&e), 1) << SDL_GetError(); }
    void key(SDL_Keycode sym, bool down = true) {
        SDL_Event e{};
        e.type = down ? SDL_KEYDOWN : SDL_KEYUP;
        e.key.state = down ? SDL_PRESSED : SDL_RELEASED;
        e.key.keysym.sym = sym;
        push(e);
    }
    void tap(SDL_Keycode sym) {
        key(sym, true);
        key(sym, false);
        frames(1);
    }
    void mouseMove(Vec2 to) {
        SDL_Event e{};
        e.type = SDL_MOUSEMOTION;
        e.motion.x = static_cast<int>(std::lround(to.x));
        e.motion.y = static_cast<int>(std::lround(to.y));
        e.motion.xrel = e.motion.x - static_cast<int>(std::lround(mouse_.x));
        e.motion.yrel = e.motion.y - static_cast<int>(std::lround(mouse_.y));
        mouse_ = to;
        push(e);
    }
    void mouseButton(Uint8 button, bool down) {
        SDL_Event e{};
        e.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
        e.button.button = button;
        e.button.state = down ? SDL_PRESSED : SDL_RELEASED;
        e.button.clicks = 1;
        e.button.x = static_cast<int>(std::lround(mouse_.x));
        e.button.y = static_cast<int>(std::lround(mouse_.y));
        push(e);
    }
    // A left click on the panel checkbox labelled `label`, one frame per event as a user's would be.
    void clickCheckbox(const std::string& label) {
        const auto found = viewer_->state().checkboxes.find(label);
        ASSERT_NE(found, viewer_->state().checkboxes.end()) << "no checkbox " << label;
        const auto [min, max] = found->second;
        mouseMove(0.5f * (min + max));
        frames(1);
        mouseButton(SDL_BUTTON_LEFT, true);
        frames(1);
        mouseButton(SDL_BUTTON_LEFT, false);
        frames(1);
    }
    Vec2 screenOf(Vec2 world) const { return viewer_->camera().toScreen(world); }
    const SceneWorld& sim() const { return *viewer_->state().sim; }
    Vec2 bodyPosition(const std::string& name) const {
        for (size_t i = 0; i < sim().scene.bodies.size(); ++i)
            if (sim().scene.bodies[i].name == name) return sim().world.position(sim().bodies[i]);
        ADD_FAILURE() << "no body " << name;
        return {};
    }

    std::unique_ptr<SdlLibrary> sdl_;
    WindowPtr window_;
    RendererPtr renderer_;
    std::unique_ptr<ImGuiLayer> imgui_;
    std::unique_ptr<Viewer> viewer_;
    Vec2 mouse_{640.0f, 400.0f};
};

TEST_F(ViewerInteraction, SpacePausesAndResumesTheSimulation) {
    open("single_box");
    frames(5);
    const int before = sim().stepIndex;
    EXPECT_GT(before, 0);
    tap(SDLK_SPACE);
    const int paused = sim().stepIndex;
    frames(10);
    EXPECT_EQ(sim().stepIndex, paused);
    EXPECT_TRUE(viewer_->state().paused);
    tap(SDLK_SPACE);
    frames(10);
    EXPECT_GE(sim().stepIndex, paused + 10);
}

TEST_F(ViewerInteraction, SStepsExactlyOnceAndPauses) {
    open("single_box");
    tap(SDLK_SPACE);
    const int paused = sim().stepIndex;
    tap(SDLK_s);
    frames(5);
    EXPECT_EQ(sim().stepIndex, paused + 1);
    tap(SDLK_RIGHT);
    EXPECT_EQ(sim().stepIndex, paused + 2);
}

TEST_F(ViewerInteraction, RResetsTheSceneToItsStart) {
    open("projectile");
    const Vec2 start = sim().world.position(sim().bodies.back());
    frames(30);
    EXPECT_GT(length(sim().world.position(sim().bodies.back()) - start), 0.5f);
    tap(SDLK_r);
    EXPECT_LE(sim().stepIndex, 1);  // reset, then at most the frame's one step
    EXPECT_LT(length(sim().world.position(sim().bodies.back()) - start), 0.2f);
}

TEST_F(ViewerInteraction, ZTogglesSlowMotionToAQuarterOfTheSteps) {
    open("single_box");
    tap(SDLK_z);
    EXPECT_FLOAT_EQ(viewer_->state().timeScale, 0.25f);
    const int before = sim().stepIndex;
    frames(40);
    EXPECT_EQ(sim().stepIndex - before, 10);
    tap(SDLK_z);
    EXPECT_FLOAT_EQ(viewer_->state().timeScale, 1.0f);
}

TEST_F(ViewerInteraction, LeftDragPullsTheGrabbedBodyTowardsTheMouse) {
    open("single_box");
    frames(60);  // settled on the ground
    const BodyId box = sim().bodies.back();
    const Vec2 rest = sim().world.position(box);
    mouseMove(screenOf(rest));
    mouseButton(SDL_BUTTON_LEFT, true);
    frames(1);
    mouseMove(screenOf(rest + Vec2{0.0f, 3.0f}));
    frames(90);
    EXPECT_GT(sim().world.position(box).y, rest.y + 1.5f) << "the spring lifts the box towards the cursor";
    mouseButton(SDL_BUTTON_LEFT, false);
    frames(120);
    EXPECT_NEAR(sim().world.position(box).y, rest.y, 0.05f) << "released, it falls back";
}

TEST_F(ViewerInteraction, RightDragPansAndWheelAndKeysZoom) {
    open("single_box");
    const Camera before = viewer_->camera();
    mouseMove({600.0f, 400.0f});
    mouseButton(SDL_BUTTON_RIGHT, true);
    mouseMove({700.0f, 400.0f});  // drag 100 px right: the view moves left
    mouseButton(SDL_BUTTON_RIGHT, false);
    frames(1);
    EXPECT_NEAR(viewer_->camera().center.x, before.center.x - 100.0f / before.pixelsPerMetre, 1e-3f);
    EXPECT_FLOAT_EQ(viewer_->camera().center.y, before.center.y);

    SDL_Event wheel{};
    wheel.type = SDL_MOUSEWHEEL;
    wheel.wheel.y = 1;
    wheel.wheel.preciseY = 1.0f;
    push(wheel);
    frames(1);
    EXPECT_NEAR(viewer_->camera().pixelsPerMetre, before.pixelsPerMetre * 1.15f, 1e-3f);
    tap(SDLK_MINUS);
    EXPECT_NEAR(viewer_->camera().pixelsPerMetre, before.pixelsPerMetre * 1.15f * 0.8f, 1e-3f);
    tap(SDLK_c);
    EXPECT_NEAR(viewer_->camera().pixelsPerMetre, before.pixelsPerMetre, 0.01f * before.pixelsPerMetre) << "C fits the view again";
}

TEST_F(ViewerInteraction, XExplodesAtTheMouseAndPushesBodiesAway) {
    open("single_box");
    frames(60);
    const BodyId box = sim().bodies.back();
    const Vec2 rest = sim().world.position(box);
    mouseMove(screenOf(rest + Vec2{-1.5f, 0.0f}));
    tap(SDLK_SPACE);  // paused: the impulse is all there is
    tap(SDLK_x);
    EXPECT_GT(sim().world.linearVelocity(box).x, 0.5f) << "pushed away from the blast at its left";
}

TEST_F(ViewerInteraction, MoverWalksWithADAndJumpsWithW) {
    open("mover_course");
    ASSERT_TRUE(viewer_->mover().active());
    frames(60);
    ASSERT_TRUE(viewer_->mover().state().grounded);
    const Vec2 start = viewer_->mover().state().position;
    key(SDLK_d);
    frames(30);  // half a second at 4 m/s
    EXPECT_NEAR(viewer_->mover().state().position.x - start.x, 2.0f, 0.15f);
    key(SDLK_d, false);
    frames(5);
    const float stopped = viewer_->mover().state().position.x;
    frames(10);
    EXPECT_FLOAT_EQ(viewer_->mover().state().position.x, stopped) << "released, it stands";
    key(SDLK_a);
    frames(15);
    key(SDLK_a, false);
    EXPECT_LT(viewer_->mover().state().position.x, stopped - 0.8f);
    const float ground = viewer_->mover().state().position.y;
    tap(SDLK_w);
    frames(10);
    EXPECT_FALSE(viewer_->mover().state().grounded);
    EXPECT_GT(viewer_->mover().state().position.y, ground + 0.5f);
    frames(120);
    EXPECT_TRUE(viewer_->mover().state().grounded);
}

TEST_F(ViewerInteraction, MoverPushesTheCourseBoxesAlong) {
    open("mover_course");
    const Vec2 box = bodyPosition("box0");
    key(SDLK_d);
    frames(120);  // 2 s at 4 m/s: it reaches the boxes at x ≈ -12.6 and pushes them to the stairs
    key(SDLK_d, false);
    EXPECT_GT(bodyPosition("box0").x, box.x + 1.0f);
    EXPECT_LT(viewer_->mover().state().position.x, bodyPosition("box0").x) << "it pushes, it does not pass through";
}

TEST_F(ViewerInteraction, MPlacesAMoverAtTheMouseInAnyScene) {
    open("single_box");
    EXPECT_FALSE(viewer_->mover().active());
    mouseMove(screenOf({-3.0f, 3.0f}));
    tap(SDLK_m);
    ASSERT_TRUE(viewer_->mover().active());
    frames(90);
    EXPECT_TRUE(viewer_->mover().state().grounded) << "it fell to the ground";
    EXPECT_NEAR(viewer_->mover().state().position.x, -3.0f, 0.05f);
}

TEST_F(ViewerInteraction, TheMovingPlatformOfTheMoverCourseTurnsBack) {
    open("mover_course");
    float lowest = 1e9f, highest = -1e9f;
    for (int i = 0; i < 600; ++i) {
        frames(1);
        lowest = std::min(lowest, bodyPosition("platform").x);
        highest = std::max(highest, bodyPosition("platform").x);
    }
    EXPECT_NEAR(lowest, 9.0f, 0.05f);
    EXPECT_NEAR(highest, 13.0f, 0.05f);
}

TEST_F(ViewerInteraction, PanelCheckboxesToggleTheDebugLayers) {
    open("single_box");
    EXPECT_FALSE(viewer_->state().draw.aabbs);
    clickCheckbox("AABBs");
    EXPECT_TRUE(viewer_->state().draw.aabbs);
    clickCheckbox("contacts");
    EXPECT_TRUE(viewer_->state().draw.contacts);
    clickCheckbox("AABBs");
    EXPECT_FALSE(viewer_->state().draw.aabbs);
    const int steps = sim().stepIndex;
    EXPECT_GT(steps, 0) << "the clicks were on the panel, not a pause";
}

TEST_F(ViewerInteraction, TheBox2DOverlayFollowsTheSceneWhenTurnedOn) {
    open("projectile");
    clickCheckbox("Box2D overlay (scene as defined)");
    ASSERT_TRUE(viewer_->state().showBox2D);
    frames(60);
    const float error = viewer_->state().box2d.maxPositionError();
    EXPECT_TRUE(std::isfinite(error));
    EXPECT_LT(error, 0.01f) << "free flight agrees with Box2D";
    EXPECT_FALSE(viewer_->state().box2d.worstBody().empty());
}

TEST_F(ViewerInteraction, HShowsHelpAndQQuits) {
    open("single_box");
    tap(SDLK_h);
    EXPECT_TRUE(viewer_->state().showHelp);
    tap(SDLK_h);
    EXPECT_FALSE(viewer_->state().showHelp);
    EXPECT_FALSE(viewer_->quit());
    tap(SDLK_q);
    EXPECT_TRUE(viewer_->quit());
}

}  // namespace
}  // namespace perpdot::demo

#endif  // PERPDOT_DEMO
