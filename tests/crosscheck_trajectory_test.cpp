// Trajectory CSV round trip and the frame-by-frame comparison on hand-made trajectories.
#include <gtest/gtest.h>

#include <sstream>

#include "perpdot/crosscheck.hpp"
#include "perpdot/error.hpp"

namespace perpdot::crosscheck {
namespace {

// Two bodies; body "b" moves along x at 1 m per frame, "a" rotates 0.1 rad per frame.
Trajectory straightLines(int frames) {
    Trajectory t;
    t.timestep = 1.0f / 60.0f;
    t.bodies = {"a", "b"};
    for (int f = 0; f < frames; ++f) {
        t.states.push_back({{0.0f, 1.0f}, 0.1f * float(f), {0.0f, 0.0f}, 6.0f});
        t.states.push_back({{float(f), 0.0f}, 0.0f, {60.0f, 0.0f}, 0.0f});
    }
    return t;
}

Options tolerance(float metres, float radians) {
    Options o;
    o.tolerance = metres;
    o.angleTolerance = radians;
    return o;
}

TEST(TrajectoryCsv, RoundTripIsExact) {
    Trajectory t = straightLines(5);
    t.states[3].position = {1.0f / 3.0f, -123456.789f};  // needs all 9 significant digits
    t.states[7].angularVelocity = 1e-30f;
    std::stringstream csv;
    writeCsv(csv, t);
    const Trajectory back = readCsv(csv);
    EXPECT_EQ(back.bodies, t.bodies);
    EXPECT_EQ(back.states, t.states);
    EXPECT_NEAR(back.timestep, t.timestep, 1e-9f);
}

TEST(TrajectoryCsv, HeaderAndEngineColumn) {
    std::stringstream csv;
    writeCsv(csv, straightLines(2), "box2d");
    std::string header, row;
    std::getline(csv, header);
    std::getline(csv, row);
    EXPECT_EQ(header, "step,time,body,x,y,angle,vx,vy,omega,engine");
    EXPECT_EQ(row, "0,0,a,0,1,0,0,0,6,box2d");
}

void expectMalformed(const std::string& text, const std::string& message) {
    std::istringstream in(text);
    try {
        readCsv(in);
        ADD_FAILURE() << "accepted: " << text;
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
}

TEST(TrajectoryCsv, MalformedFilesNameTheProblem) {
    const std::string header = "step,time,body,x,y,angle,vx,vy,omega\n";
    expectMalformed("", "empty file");
    expectMalformed("x,y\n", "line 1: expected the header");
    expectMalformed(header + "0,0,a,1,2,3,4,5\n", "line 2: expected 9 fields");
    expectMalformed(header + "0,0,a,1,2,oops,4,5,6\n", "line 2: column angle");
    expectMalformed(header + "0,0,a,1,2,3,4,5,6\n2,0.1,a,1,2,3,4,5,6\n", "line 3: expected step 1");
    expectMalformed(header + "0,0,a,1,2,3,4,5,6\n0,0,b,1,2,3,4,5,6\n1,0.1,b,1,2,3,4,5,6\n", "line 4: expected body 'a'");
    expectMalformed(header + "0,0,a,1,2,3,4,5,6\n1,0.1,a,1,2,3,4,5,6\n2,0.3,a,1,2,3,4,5,6\n", "line 3: time");
}

TEST(Compare, IdenticalTrajectoriesHaveZeroError) {
    const auto metrics = compare(straightLines(10), straightLines(10), tolerance(0.0f, 0.0f));
    ASSERT_EQ(metrics.size(), 2u);
    for (const BodyMetrics& m : metrics) {
        EXPECT_EQ(m.position.max, 0.0f);
        EXPECT_EQ(m.divergenceStep, -1);
        EXPECT_EQ(m.positionError.size(), 10u);
    }
    EXPECT_EQ(firstDiverged(metrics), -1);
}

TEST(Compare, ErrorsMaxRmsAndDivergenceStep) {
    const Trajectory reference = straightLines(10);
    Trajectory measured = reference;
    // b drifts by 3-4-5 triangles growing 0.5 m per frame from frame 4; a's angle lags 0.2 rad from frame 7.
    for (int f = 4; f < 10; ++f) measured.states[size_t(2 * f + 1)].position += (0.1f * float(f - 3)) * Vec2{3.0f, 4.0f};
    for (int f = 7; f < 10; ++f) measured.states[size_t(2 * f)].angle -= 0.2f;
    const auto m = compare(measured, reference, tolerance(1.2f, 0.1f));
    // a: angle beyond 0.1 rad at frame 7.
    EXPECT_EQ(m[0].divergenceStep, 7);
    EXPECT_NEAR(m[0].angle.max, 0.2f, 1e-6f);
    EXPECT_NEAR(m[0].angle.rms, std::sqrt(3.0f * 0.04f / 10.0f), 1e-6f);
    EXPECT_EQ(m[0].position.max, 0.0f);
    // b: position error 0.5 (f-3): 1.5 > 1.2 first at frame 6; max 3.0 at frame 9.
    EXPECT_EQ(m[1].divergenceStep, 6);
    EXPECT_NEAR(m[1].position.max, 3.0f, 1e-5f);
    EXPECT_EQ(m[1].position.maxStep, 9);
    EXPECT_NEAR(m[1].positionError[5], 1.0f, 1e-5f);
    EXPECT_EQ(firstDiverged(m), 1);
}

TEST(Compare, NonFiniteStateCountsAsDiverged) {
    const Trajectory reference = straightLines(3);
    Trajectory measured = reference;
    measured.states[5].position.x = std::nanf("");
    const auto m = compare(measured, reference, tolerance(1e30f, 1e30f));
    EXPECT_EQ(m[1].divergenceStep, 2);
    EXPECT_TRUE(std::isinf(m[1].position.max));
}

TEST(Compare, MismatchedTrajectoriesAreRefused) {
    const Trajectory reference = straightLines(4);
    Trajectory renamed = reference;
    renamed.bodies[1] = "c";
    EXPECT_THROW(compare(renamed, reference, {}), Error);
    EXPECT_THROW(compare(straightLines(3), reference, {}), Error);
    Trajectory slower = reference;
    slower.timestep = 1.0f / 30.0f;
    EXPECT_THROW(compare(slower, reference, {}), Error);
}

}  // namespace
}  // namespace perpdot::crosscheck
