// The `perpdot` command, run as a process: list, run (summary line and trajectory CSV), export,
// and exit status 2 with a message on stderr for bad usage or bad input.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "perpdot/scene.hpp"
#include "perpdot/state_hash.hpp"

namespace perpdot {
namespace {

std::string tempPath(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("perpdot_cli_" + std::to_string(getpid()) + "_" + name)).string();
}

std::string readFile(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

struct Result {
    int status = -1;
    std::string out, err;
};

// Runs `perpdot <arguments>` through the shell, capturing stdout, stderr and the exit status.
Result perpdot(const std::string& arguments) {
    const std::string out = tempPath("stdout"), err = tempPath("stderr");
    const std::string command = std::string("'") + PERPDOT_CLI + "' " + arguments + " >'" + out + "' 2>'" + err + "'";
    const int raw = std::system(command.c_str());
    Result r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, readFile(out), readFile(err)};
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return r;
}

std::vector<std::vector<std::string>> readCsv(const std::string& path) {
    std::vector<std::vector<std::string>> rows;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> fields;
        std::stringstream fieldStream(line);
        for (std::string field; std::getline(fieldStream, field, ',');) fields.push_back(field);
        rows.push_back(fields);
    }
    return rows;
}

TEST(Cli, ListShowsEveryBuiltinScene) {
    const Result r = perpdot("list");
    ASSERT_EQ(r.status, 0) << r.err;
    for (const BuiltinScene& scene : builtinScenes())
        EXPECT_TRUE(r.out.starts_with(scene.name + " ") || r.out.find("\n" + scene.name + " ") != std::string::npos)
            << scene.name;
}

TEST(Cli, RunPrintsOneSummaryLineAndWritesTheTrajectory) {
    const std::string csv = tempPath("single_box.csv");
    const Result r = perpdot("run single_box --steps 10 --csv '" + csv + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    // scene=single_box steps=10 bodies=2 ms_per_step=<x.xxx> state_hash=<16 hex digits>
    const std::string prefix = "scene=single_box steps=10 bodies=2 ms_per_step=";
    ASSERT_TRUE(r.out.starts_with(prefix) && r.out.ends_with("\n")) << r.out;
    const std::string rest = r.out.substr(prefix.size());
    const size_t dot = rest.find('.'), space = rest.find(' ');
    ASSERT_TRUE(dot != std::string::npos && dot > 0 && space == dot + 4) << r.out;
    EXPECT_TRUE(std::all_of(rest.begin(), rest.begin() + space, [](char c) { return std::isdigit(c) || c == '.'; }));
    const std::string hashField = rest.substr(space + 1, rest.size() - space - 2);
    ASSERT_TRUE(hashField.starts_with("state_hash=")) << r.out;
    const std::string printedHash = hashField.substr(11);
    EXPECT_EQ(printedHash.size(), 16u);

    // The same run in the library gives the same hash.
    SceneWorld built = buildWorld(findScene("single_box"));
    for (int i = 0; i < 10; ++i) built.step();
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016" PRIx64, stateHash(built.world));
    EXPECT_EQ(printedHash, hash);

    const auto rows = readCsv(csv);
    ASSERT_EQ(rows.size(), 1u + 11u * 1u);  // header + (steps/every + 1) rows × one dynamic body (ground is static)
    EXPECT_EQ(rows[0], (std::vector<std::string>{"step", "time", "body", "x", "y", "angle", "vx", "vy", "omega"}));
    const SceneBody& box = built.scene.bodies[1];
    EXPECT_EQ(rows[1][0], "0");
    EXPECT_EQ(rows[1][2], box.name);
    EXPECT_EQ(std::stof(rows[1][3]), box.position.x);
    EXPECT_EQ(std::stof(rows[1][4]), box.position.y);
    EXPECT_EQ(std::stof(rows[1][5]), box.angle);
    EXPECT_EQ(rows.back()[0], "10");
    // %.9g round-trips: the last row is the library's final state exactly.
    EXPECT_EQ(std::stof(rows.back()[4]), built.world.position(built.bodies[1]).y);
    EXPECT_EQ(std::stof(rows.back()[7]), built.world.linearVelocity(built.bodies[1]).y);
    EXPECT_FLOAT_EQ(std::stof(rows.back()[1]), 10 * built.scene.timestep);
    std::filesystem::remove(csv);
}

TEST(Cli, EveryKRecordsEveryKthStep) {
    const std::string csv = tempPath("balls.csv");
    const Result r = perpdot("run bouncing_balls --steps 10 --every 3 --csv '" + csv + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rows = readCsv(csv);
    const size_t balls = 5;
    ASSERT_EQ(rows.size(), 1u + (10u / 3u + 1u) * balls);
    for (size_t i = 0; i + 1 < rows.size(); ++i) EXPECT_EQ(std::stoi(rows[i + 1][0]), 3 * int(i / balls));
    std::filesystem::remove(csv);
}

TEST(Cli, RunsAndExportsSceneFiles) {
    const std::string file = tempPath("spinning_box_copy.json");
    const Result exported = perpdot("export spinning_box '" + file + "'");
    ASSERT_EQ(exported.status, 0) << exported.err;
    EXPECT_TRUE(loadScene(file) == findScene("spinning_box"));
    const Result r = perpdot("run '" + file + "' --steps 3");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(r.out.starts_with("scene=spinning_box steps=3 bodies=1 ")) << r.out;
    std::filesystem::remove(file);
}

TEST(Cli, BadInputExitsWithStatus2AndSaysWhy) {
    const std::string badFile = std::string(PERPDOT_TEST_DATA) + "/bad_polygon.json";
    const struct {
        std::string arguments, stderrMentions;
    } cases[] = {
        {"run '" + badFile + "'", "bodies[1].shapes[0].vertices"},
        {"run '" + badFile + "'", badFile},
        {"run no_such_scene", "no_such_scene"},
        {"frobnicate", "unknown command 'frobnicate'"},
        {"run single_box --steps 12abc", "--steps"},
        {"run single_box --steps -1", "--steps"},
        {"run single_box --steps", "--steps needs a value"},
        {"run single_box --every 0", "--every"},
        {"run single_box --fast", "unknown option --fast"},
        {"run", "no scene given"},
        {"run single_box pyramid", "more than one scene"},
        {"list extra", "list takes no arguments"},
        {"export single_box", "expected a scene and an output file"},
        {"export single_box /nonexistent-dir/x.json", "/nonexistent-dir/x.json"},
        {"run single_box --steps 1 --csv /nonexistent-dir/x.csv", "/nonexistent-dir/x.csv"},
    };
    for (const auto& c : cases) {
        const Result r = perpdot(c.arguments);
        EXPECT_EQ(r.status, 2) << c.arguments;
        EXPECT_NE(r.err.find(c.stderrMentions), std::string::npos) << c.arguments << "\n  stderr: " << r.err;
        EXPECT_EQ(r.out.find("scene="), std::string::npos) << c.arguments;
    }
}

std::string hashOf(const Result& r) {
    const size_t at = r.out.find("state_hash=");
    return at == std::string::npos ? "(none: " + r.out + r.err + ")" : r.out.substr(at + 11, 16);
}

// --save-at K FILE then --load FILE continues the run bit for bit, scripted actions included
// (off_center_push pushes for its first steps: the save falls inside the push).
TEST(Cli, SaveAtThenLoadContinuesTheRunBitForBit) {
    for (const char* scene : {"off_center_push", "pyramid", "ragdoll"}) {
        const std::string file = tempPath(std::string(scene) + ".snapshot");
        const Result straight = perpdot(std::string("run ") + scene + " --steps 240");
        const Result saving = perpdot(std::string("run ") + scene + " --steps 240 --save-at 20 '" + file + "'");
        const Result loaded = perpdot(std::string("run ") + scene + " --steps 240 --load '" + file + "'");
        ASSERT_EQ(straight.status, 0) << straight.err;
        ASSERT_EQ(saving.status, 0) << saving.err;
        ASSERT_EQ(loaded.status, 0) << loaded.err;
        EXPECT_EQ(hashOf(saving), hashOf(straight)) << scene;
        EXPECT_EQ(hashOf(loaded), hashOf(straight)) << scene;
        // A snapshot cut short is refused with the file's name, exit status 2.
        std::filesystem::resize_file(file, std::filesystem::file_size(file) - 7);
        const Result truncated = perpdot(std::string("run ") + scene + " --steps 240 --load '" + file + "'");
        EXPECT_EQ(truncated.status, 2);
        EXPECT_NE(truncated.err.find(file + ": snapshot: "), std::string::npos) << truncated.err;
        std::filesystem::remove(file);
    }
    const std::string file = tempPath("other.snapshot");
    ASSERT_EQ(perpdot("run single_box --steps 5 --save-at 5 '" + file + "'").status, 0);
    const Result wrongScene = perpdot("run pyramid --load '" + file + "'");
    EXPECT_EQ(wrongScene.status, 2);
    EXPECT_NE(wrongScene.err.find("not of scene"), std::string::npos) << wrongScene.err;
    EXPECT_EQ(perpdot("run single_box --steps 5 --save-at 6 '" + file + "'").status, 2);
    EXPECT_EQ(perpdot("run single_box --save-at 5").status, 2);
    EXPECT_EQ(perpdot("run single_box --load /nonexistent-dir/x.snapshot").status, 2);
    std::filesystem::remove(file);
}

}  // namespace
}  // namespace perpdot
