// Snapshot format versions: snapshots written by older code still load and continue. The files in
// tests/data/snapshot_v1/ were written by the code of e7499b5 (format 1: joint data as raw struct
// bytes) from built-in scenes and from test::jointZoo(); together they hold every joint type,
// sleeping islands, warm-started contacts, sensors, a bullet, a kinematic body and conveyors.
// tests/data/snapshot_v4/ holds format 4 written by the code of 2573500: four of the format-1 files
// loaded and saved again, and the gears and pulley scenes at step 40 (`perpdot run --save-at`,
// the run header removed), so every joint type of that code. tests/data/snapshot_v5/ holds format
// 5 (bodies and shapes taken out with setEnabled): the format-4 files loaded and saved again, and
// runtime_changes.snap, the world of RuntimeSnapshot.ChangesMadeAtRunTimeSurviveARestoreBitForBit
// (runtime_api_test.cpp) where it is saved: changed at run time (a type, a mass override, fixed
// rotation, a filter, a sensor toggle, a kinematic target, a disabled body and shape, a shifted origin).
// tests/data/snapshot_v6/ holds format 6 (each body's rest sink, support_sinks.hpp): the format-5
// files loaded and saved again.
//
// A loaded old snapshot must continue exactly like the same state restored from the current
// format: the old file is loaded, saved in today's format, that is restored into a second world,
// and both are stepped with the state hash compared each step. (Not against hashes recorded when
// the files were written: legitimate solver changes change those.)
#include <algorithm>
#include <bit>
#include <cstring>
#include <typeinfo>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/joints/joint_revolute.hpp"
#include "core/snapshot/snapshot_fields.hpp"
#include "joint_zoo.hpp"
#include "perpdot/error.hpp"
#include "perpdot/state_hash.hpp"
#include "perpdot/world.hpp"

namespace perpdot {
namespace {

using Bytes = std::vector<uint8_t>;

Bytes readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::filesystem::path> snapshotFiles(const std::filesystem::path& directory) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(directory))
        if (entry.path().extension() == ".snap") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

uint32_t versionOf(const Bytes& bytes) {
    return uint32_t(bytes[8]) | uint32_t(bytes[9]) << 8 | uint32_t(bytes[10]) << 16 | uint32_t(bytes[11]) << 24;
}

// Each file of `directory` (format `version`) loads, saves in today's format, and steps exactly like
// that restored into a second world.
void expectOldFilesContinueLikeTheCurrentFormat(const char* directory, uint32_t version, size_t count) {
    const std::vector<std::filesystem::path> files = snapshotFiles(directory);
    ASSERT_EQ(files.size(), count);
    for (const auto& path : files) {
        const Bytes old = readFile(path);
        ASSERT_EQ(versionOf(old), version) << path;
        World fromOld;
        ASSERT_NO_THROW(fromOld.restore(old)) << path;
        const Bytes current = fromOld.snapshot();
        World fromCurrent;
        fromCurrent.restore(current);
        EXPECT_EQ(fromCurrent.snapshot(), current) << path;
        EXPECT_EQ(stateHash(fromOld), stateHash(fromCurrent)) << path;
        for (int step = 0; step < 60; ++step) {
            fromOld.step(1.0f / 60);
            fromCurrent.step(1.0f / 60);
            ASSERT_EQ(stateHash(fromOld), stateHash(fromCurrent)) << path << " step " << step;
        }
        EXPECT_EQ(fromOld.snapshot(), fromCurrent.snapshot()) << path;
    }
}

TEST(SnapshotFormat, FormatOneFilesLoadAndContinueLikeTheCurrentFormat) {
    expectOldFilesContinueLikeTheCurrentFormat(PERPDOT_TEST_DATA "/snapshot_v1", 1, 10);
}

TEST(SnapshotFormat, FormatFourFilesLoadAndContinueLikeTheCurrentFormat) {
    expectOldFilesContinueLikeTheCurrentFormat(PERPDOT_TEST_DATA "/snapshot_v4", 4, 6);
}

TEST(SnapshotFormat, FormatFiveFilesLoadAndContinueLikeTheCurrentFormat) {
    expectOldFilesContinueLikeTheCurrentFormat(PERPDOT_TEST_DATA "/snapshot_v5", 5, 7);
}

// While the format is 6, a format-6 file saves back byte for byte. A new format version replaces
// this by a check like the ones above and adds files of its own.
static_assert(formatVersion == 6, "format 6 is no longer current: see the comment above");
TEST(SnapshotFormat, FormatSixFilesSaveBackByteForByte) {
    const std::vector<std::filesystem::path> files = snapshotFiles(PERPDOT_TEST_DATA "/snapshot_v6");
    ASSERT_EQ(files.size(), 7u);
    for (const auto& path : files) {
        const Bytes saved = readFile(path);
        ASSERT_EQ(versionOf(saved), 6u) << path;
        World world;
        ASSERT_NO_THROW(world.restore(saved)) << path;
        EXPECT_EQ(world.snapshot(), saved) << path;
    }
}

// The world of runtime_changes.snap, rebuilt: its disabled body and shape stay out after loading,
// and come back into the broadphase when enabled.
TEST(SnapshotFormat, FormatFiveKeepsDisabledBodiesAndShapesOut) {
    World world;
    world.restore(readFile(PERPDOT_TEST_DATA "/snapshot_v5/runtime_changes.snap"));
    int disabledBodies = 0, disabledShapes = 0;
    for (BodyId body : world.bodies()) {
        disabledBodies += !world.isEnabled(body);
        for (ShapeId shape : world.shapes(body)) disabledShapes += !world.isEnabled(shape);
    }
    EXPECT_EQ(disabledBodies, 1);
    EXPECT_EQ(disabledShapes, 1);
}

// The joint zoo's file holds every joint type, each with its warm-start impulses (read back
// through the reactions, which are the stored impulses over the substep).
TEST(SnapshotFormat, FormatOneJointZooKeepsEveryJointAndItsImpulses) {
    World fromOld;
    fromOld.restore(readFile(PERPDOT_TEST_DATA "/snapshot_v1/joint_zoo_40.snap"));
    const World rebuilt = test::jointZoo();
    const std::vector<JointId> joints = fromOld.joints();
    ASSERT_EQ(joints.size(), rebuilt.joints().size());
    for (size_t i = 0; i < joints.size(); ++i) {
        EXPECT_EQ(fromOld.jointType(joints[i]), rebuilt.jointType(rebuilt.joints()[i]));
        EXPECT_EQ(fromOld.jointType(joints[i]), static_cast<JointType>(i)) << "one joint of each type, in enum order";
        EXPECT_TRUE(length(fromOld.jointReactionForce(joints[i])) > 0 || fromOld.jointReactionTorque(joints[i]) != 0)
            << "joint " << i << " lost its impulses";
    }
}

// Format 1 stored a joint's type data as the struct's bytes: the field list must walk exactly that
// layout. Every member gets distinct bits, the struct's bytes are read back with readLayoutV1 and
// must give the same fields (compared through the current format's bytes).
template <class T>
void expectLayoutV1ReadsRawBytes() {
    T original{};
    uint32_t next = 0x3F800001;
    const auto fill = [&](auto& self, auto& value) -> void {
        using V = std::remove_reference_t<decltype(value)>;
        if constexpr (std::is_same_v<V, bool>) value = (next++ & 1) != 0;
        else if constexpr (std::is_same_v<V, float>) value = std::bit_cast<float>(next++);
        else if constexpr (std::is_same_v<V, Vec2>) value = {std::bit_cast<float>(next++), std::bit_cast<float>(next++)};
        else std::apply([&](const auto&... f) { (self(self, value.*(f.member)), ...); }, fieldsOf<V>());
    };
    fill(fill, original);
    Bytes raw(sizeof(T), 0xAB);  // padding bytes hold garbage: they must be skipped
    std::memcpy(raw.data(), &original, sizeof(T));
    ByteReader in(raw);
    in.version = 1;
    T read{};
    size_t offset = 0;
    readLayoutV1(in, read, offset);
    in.expectEnd();
    ByteWriter a, b;
    writeFields(a, original);
    writeFields(b, read);
    EXPECT_EQ(a.bytes, b.bytes) << typeid(T).name();
}

TEST(SnapshotFormat, FormatOneJointLayoutIsReadFromTheFieldLists) {
    expectLayoutV1ReadsRawBytes<RevoluteJoint>();
}

TEST(SnapshotFormat, UnknownVersionsAreRefusedByNumber) {
    Bytes bytes = test::jointZoo().snapshot();
    for (uint32_t version : {0u, versionOf(bytes) + 1, 0xFFFFFFFFu}) {
        for (int k = 0; k < 4; ++k) bytes[8 + k] = uint8_t(version >> (8 * k));
        World world;
        try {
            world.restore(bytes);
            ADD_FAILURE() << "version " << version << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("format version " + std::to_string(version)), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace perpdot
