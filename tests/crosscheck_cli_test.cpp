// `perpdot crosscheck | record | compare | bench` as a user runs them: exit codes 0 / 1 / 2,
// the record -> compare round trip, tampered and malformed golden files, and the report files.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

const std::string gates = std::string(PERPDOT_TEST_DATA) + "/../crosscheck/";

struct Result {
    int status;
    std::string output;  // stdout and stderr
};

// Runs the perpdot binary (with `environment`, e.g. "PATH=/x", prepended through env(1)).
Result perpdot(const std::string& arguments, const std::string& environment = "") {
    const std::string prefix = environment.empty() ? "" : "/usr/bin/env " + environment + " ";
    const std::string command = prefix + PERPDOT_CLI + " " + arguments + " 2>&1";
    std::FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return {-1, "popen failed"};
    std::string output;
    char buffer[4096];
    while (size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, n);
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::path(testing::TempDir()) / ("perpdot_crosscheck_cli_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(CrosscheckCli, WithinToleranceExitsZero) {
    const Result r = perpdot("crosscheck " + gates + "projectile.json --tolerance 1e-4");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("verdict: within tolerance"), std::string::npos) << r.output;
}

TEST(CrosscheckCli, DivergenceExitsOne) {
    // Two different contact solvers never agree to a nanometre on a settling stack.
    const Result r = perpdot("crosscheck " + gates + "stack.json --tolerance 1e-9 --angle-tolerance 1e-9");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("verdict: DIVERGED at step"), std::string::npos) << r.output;
}

TEST(CrosscheckCli, Box2DSkinComparesRestHeightsLikeForLike) {
    // A box at rest: perpdot on its true surface is 0.014 m below b2World's box on its skin, beyond
    // 1 cm; with --box2d-skin both rest on Box2D's skin and agree.
    const Result own = perpdot("crosscheck stress_box_rest");
    EXPECT_EQ(own.status, 1) << own.output;
    const Result skinned = perpdot("crosscheck stress_box_rest --box2d-skin");
    EXPECT_EQ(skinned.status, 0) << skinned.output;
    EXPECT_EQ(perpdot("crosscheck stress_box_rest --box2d-skin 1").status, 2);  // a switch takes no value
}

TEST(CrosscheckCli, BadInputExitsTwo) {
    EXPECT_EQ(perpdot("crosscheck no_such_scene_anywhere").status, 2);
    EXPECT_EQ(perpdot("crosscheck " + gates + "projectile.json --tolerance -1").status, 2);
    EXPECT_EQ(perpdot("crosscheck " + gates + "projectile.json --steps many").status, 2);
    EXPECT_EQ(perpdot("crosscheck " + gates + "projectile.json --no-such-flag 1").status, 2);
    EXPECT_EQ(perpdot("crosscheck").status, 2);
    EXPECT_EQ(perpdot("record " + gates + "projectile.json").status, 2);  // --out missing
    EXPECT_EQ(perpdot("record " + gates + "projectile.json --out x.csv --engine bullet").status, 2);
    EXPECT_EQ(perpdot("bench no_such_scene_anywhere").status, 2);
}

TEST(CrosscheckCli, ReportWritesJsonCsvAndPlots) {
    const fs::path dir = scratch("report");
    const Result r = perpdot("crosscheck " + gates + "bounce.json --steps 120 --report " + dir.string());
    ASSERT_LE(r.status, 1) << r.output;

    const auto report = nlohmann::json::parse(readFile(dir / "report.json"));
    EXPECT_EQ(report["scene"], "bounce");
    EXPECT_EQ(report["steps"], 120);
    ASSERT_EQ(report["bodies"].size(), 1u);
    EXPECT_EQ(report["bodies"][0]["name"], "ball");
    EXPECT_EQ(report["bodies"][0]["position_error_series"].size(), 121u);
    EXPECT_EQ(report["engines"]["box2d"]["kinetic_energy"].size(), 121u);
    EXPECT_EQ(report["verdict"], r.status == 0 ? "within tolerance" : "diverged");

    std::ifstream csv(dir / "trajectories.csv");
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line, "step,time,body,x,y,angle,vx,vy,omega,engine");
    int perpdotRows = 0, box2dRows = 0;
    while (std::getline(csv, line)) {
        perpdotRows += line.ends_with(",perpdot");
        box2dRows += line.ends_with(",box2d");
    }
    EXPECT_EQ(perpdotRows, 121);
    EXPECT_EQ(box2dRows, 121);

    if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) {
        for (const char* png : {"position_error.png", "energy.png"}) {
            const std::string bytes = readFile(dir / png);
            EXPECT_TRUE(bytes.starts_with("\x89PNG")) << png << "\n" << readFile(dir / "gnuplot.log");
        }
    } else {
        EXPECT_NE(r.output.find("gnuplot is not installed"), std::string::npos) << r.output;
    }
}

TEST(CrosscheckCli, ReportWithoutGnuplotSaysSoAndWritesTheRest) {
    const fs::path dir = scratch("no_gnuplot");
    const Result r = perpdot("crosscheck " + gates + "projectile.json --steps 10 --report " + dir.string(), "PATH=/nonexistent");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("gnuplot is not installed"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(dir / "report.json"));
    EXPECT_TRUE(fs::exists(dir / "trajectories.csv"));
    EXPECT_FALSE(fs::exists(dir / "energy.png"));
}

TEST(CrosscheckCli, RecordThenCompareRoundTrip) {
    const fs::path dir = scratch("golden");
    const std::string golden = (dir / "actions.csv").string();
    const Result rec = perpdot("record " + gates + "actions.json --steps 200 --out " + golden);
    ASSERT_EQ(rec.status, 0) << rec.output;
    const Result cmp = perpdot("compare " + gates + "actions.json --against " + golden);
    EXPECT_EQ(cmp.status, 0) << cmp.output;
    EXPECT_NE(cmp.output.find("within tolerance"), std::string::npos) << cmp.output;
}

TEST(CrosscheckCli, Box2DGoldenOfFreeFlightPassesCompare) {
    const fs::path dir = scratch("box2d_golden");
    const std::string golden = (dir / "projectile.csv").string();
    ASSERT_EQ(perpdot("record " + gates + "projectile.json --engine box2d --out " + golden).status, 0);
    const Result cmp = perpdot("compare " + gates + "projectile.json --against " + golden + " --tolerance 1e-4");
    EXPECT_EQ(cmp.status, 0) << cmp.output;
}

TEST(CrosscheckCli, TamperedGoldenFileFails) {
    const fs::path dir = scratch("tampered");
    const fs::path golden = dir / "actions.csv";
    ASSERT_EQ(perpdot("record " + gates + "actions.json --steps 100 --out " + golden.string()).status, 0);
    // Move the plate 1 mm in x at step 50: a well-formed file that no longer matches.
    std::string text = readFile(golden);
    const size_t row = text.find("\n50,");
    ASSERT_NE(row, std::string::npos);
    const size_t x = text.find(",plate,", row) + 7;
    const size_t comma = text.find(',', x);
    const float moved = std::stof(text.substr(x, comma - x)) + 1e-3f;
    text.replace(x, comma - x, std::to_string(moved));
    std::ofstream(golden) << text;

    const Result cmp = perpdot("compare " + gates + "actions.json --against " + golden.string());
    EXPECT_EQ(cmp.status, 1) << cmp.output;
    EXPECT_NE(cmp.output.find("DIVERGED at step 50"), std::string::npos) << cmp.output;
}

TEST(CrosscheckCli, MalformedOrForeignGoldenFileExitsTwo) {
    const fs::path dir = scratch("malformed");
    const fs::path golden = dir / "actions.csv";
    ASSERT_EQ(perpdot("record " + gates + "actions.json --steps 20 --out " + golden.string()).status, 0);
    std::string text = readFile(golden);
    std::ofstream(dir / "truncated.csv") << text.substr(0, text.size() - 20);  // last row cut short
    std::ofstream(dir / "garbage.csv") << "this is not a trajectory\n";

    Result r = perpdot("compare " + gates + "actions.json --against " + (dir / "truncated.csv").string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("truncated.csv: line"), std::string::npos) << r.output;
    r = perpdot("compare " + gates + "actions.json --against " + (dir / "garbage.csv").string());
    EXPECT_EQ(r.status, 2) << r.output;
    r = perpdot("compare " + gates + "projectile.json --against " + golden.string());  // another scene's bodies
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("does not belong to scene"), std::string::npos) << r.output;
    r = perpdot("compare " + gates + "actions.json --against " + (dir / "missing.csv").string());
    EXPECT_EQ(r.status, 2) << r.output;
}

TEST(CrosscheckCli, BenchPrintsBothEngines) {
    const Result r = perpdot("bench " + gates + "stack.json --steps 30 --repeat 2");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("stack"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("x "), std::string::npos) << r.output;  // the ratio column, e.g. 0.80x
}

TEST(CrosscheckCli, BenchTimesOneEngineAloneWhenAsked) {
    Result r = perpdot("bench " + gates + "stack.json --steps 10 --repeat 1 --engine perpdot");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output.find("x "), std::string::npos) << r.output;  // no ratio without Box2D
    EXPECT_NE(r.output.find("top fell: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(" / - m"), std::string::npos) << r.output;  // Box2D's stability not measured
    r = perpdot("bench " + gates + "stack.json --steps 10 --repeat 1 --engine bullet");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("--engine: expected perpdot or box2d"), std::string::npos) << r.output;
}

TEST(CrosscheckCli, BenchPrintsEachScenesStabilityFigure) {
    const Result r = perpdot("bench smash --steps 5 --repeat 1");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("stability p / b2"), std::string::npos) << r.output;  // the column's header
    EXPECT_NE(r.output.find("momentum error: "), std::string::npos) << r.output;  // smash's figure, both engines
    EXPECT_NE(r.output.find(" of p0"), std::string::npos) << r.output;
}

}  // namespace
