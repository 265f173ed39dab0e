// `perpdot stress`: the torture suite's scene files, its probes (they must catch a failure, shown
// on Box2D 2.4.1's known weaknesses) and the command's exit statuses.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "crosscheck/stress.hpp"
#include "perpdot/scene.hpp"

namespace perpdot {
namespace {

using crosscheck::Engine;

TEST(Stress, EveryCaseHasABuiltinSceneAndAMatchingSceneFile) {
    ASSERT_GE(crosscheck::stressCases().size(), 12u);
    for (const crosscheck::StressCase& c : crosscheck::stressCases()) {
        const std::string name = std::string("stress_") + c.name;
        SCOPED_TRACE(name);
        EXPECT_EQ(crosscheck::findStressCase(c.name), &c);
        EXPECT_EQ(crosscheck::findStressCase(name), &c);
        // tests/data/stress holds `perpdot export` of every case: the files reproduce the figures.
        const Scene file = loadScene(std::string(PERPDOT_TEST_DATA) + "/stress/" + name + ".json");
        EXPECT_TRUE(file == findScene(name)) << "re-export it: perpdot export " << name << " tests/data/stress/" << name << ".json";
    }
    EXPECT_EQ(crosscheck::findStressCase("no_such_case"), nullptr);
}

// The probes must be able to fail: Box2D 2.4.1 misses these criteria in known ways (docs/stress.md).
TEST(Stress, ProbesCatchBox2DsKnownFailures) {
    const crosscheck::StressResult rest = crosscheck::runStress(*crosscheck::findStressCase("box_rest"), Engine::Box2D, true);
    EXPECT_FALSE(rest.pass);  // its 1 cm polygon skin holds the box at 0.515 m
    EXPECT_NE(rest.figure.find("0.515"), std::string::npos) << rest.figure;
    const crosscheck::StressResult bounce = crosscheck::runStress(*crosscheck::findStressCase("bounce_e1"), Engine::Box2D, true);
    EXPECT_FALSE(bounce.pass) << bounce.figure;  // gains about 4 % a bounce
    const crosscheck::StressResult chain = crosscheck::runStress(*crosscheck::findStressCase("chain"), Engine::Box2D, true);
    EXPECT_FALSE(chain.pass) << chain.figure;  // the heavy chain comes apart
    const crosscheck::StressResult heavy = crosscheck::runStress(*crosscheck::findStressCase("mass300"), Engine::Box2D, true);
    EXPECT_FALSE(heavy.pass) << heavy.figure;  // the light box is crushed
    const crosscheck::StressResult pile = crosscheck::runStress(*crosscheck::findStressCase("pyramid20"), Engine::Box2D, true);
    EXPECT_FALSE(pile.pass) << pile.figure;  // the pyramid rises 0.3 m on its skins
    EXPECT_NE(pile.figure.find("rose at most 0.2"), std::string::npos) << pile.figure;
    // The loaded bridge comes apart, and its load falls.
    const crosscheck::StressResult bridge = crosscheck::runStress(*crosscheck::findStressCase("bridge1000"), Engine::Box2D, true);
    EXPECT_FALSE(bridge.pass) << bridge.figure;
    EXPECT_EQ(bridge.figure.rfind("worst joint gap ", 0), 0u) << bridge.figure;
    EXPECT_GT(std::stof(bridge.figure.substr(16)), 0.005f) << bridge.figure;
    const size_t at = bridge.figure.find("the load at most ");
    ASSERT_NE(at, std::string::npos) << bridge.figure;
    EXPECT_GT(std::stof(bridge.figure.substr(at + 17)), 1.0f) << bridge.figure;
}

TEST(Stress, BulletsCollideInPerpdotAndBox2D) {
    const crosscheck::StressCase& bullets = *crosscheck::findStressCase("bullets");
    for (Engine engine : {Engine::Perpdot, Engine::Box2D}) {
        const crosscheck::StressResult r = crosscheck::runStress(bullets, engine, false);
        EXPECT_TRUE(r.pass) << crosscheck::engineName(engine) << ": " << r.figure;
        EXPECT_EQ(r.figure.rfind("collided", 0), 0u) << r.figure;
    }
}

struct CliRun {
    int status = -1;
    std::string out, err;
};

CliRun perpdotStress(const std::string& arguments) {
    const std::string base = (std::filesystem::temp_directory_path() / ("perpdot_stress_" + std::to_string(getpid()))).string();
    const std::string command = std::string("'") + PERPDOT_CLI + "' stress " + arguments + " >'" + base + ".out' 2>'" + base + ".err'";
    const int raw = std::system(command.c_str());
    const auto read = [](const std::string& path) {
        std::ifstream in(path);
        std::stringstream text;
        text << in.rdbuf();
        std::filesystem::remove(path);
        return text.str();
    };
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read(base + ".out"), read(base + ".err")};
}

TEST(Stress, CommandExitsZeroOnlyWhenEveryCasePasses) {
    const CliRun pass = perpdotStress("bullets tiles");
    EXPECT_EQ(pass.status, 0) << pass.out << pass.err;
    EXPECT_NE(pass.out.find("perpdot meets 2 of 2 criteria"), std::string::npos) << pass.out;
    // box_rest: perpdot rests on the true surfaces, so it passes and the command exits 0; the
    // Box2D line is reported beside it.
    const CliRun rest = perpdotStress("box_rest");
    EXPECT_EQ(rest.status, 0) << rest.out;
    EXPECT_NE(rest.out.find("box_rest   PASS"), std::string::npos) << rest.out;
    EXPECT_NE(rest.out.find("perpdot meets 1 of 1 criteria"), std::string::npos) << rest.out;
    EXPECT_NE(rest.out.find("box2d:"), std::string::npos) << rest.out;
}

TEST(Stress, CommandRefusesBadUsage) {
    const CliRun unknown = perpdotStress("no_such_case");
    EXPECT_EQ(unknown.status, 2);
    EXPECT_NE(unknown.err.find("no stress case 'no_such_case'"), std::string::npos) << unknown.err;
    EXPECT_EQ(perpdotStress("bullets --steps 3").status, 2);
}

}  // namespace
}  // namespace perpdot
