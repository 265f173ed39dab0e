// docs/scene-format.md is the format's specification: every key the scene reader accepts
// (scene_keys.hpp, the lists the reader refuses other keys with) must appear in it as `key`.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"
#include "scene/scene_keys.hpp"

namespace {

std::string readDoc(const std::string& name) {
    std::ifstream in(PERPDOT_TEST_DATA "/../../" + name);
    EXPECT_TRUE(in) << "cannot open " << name;
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(SceneFormatDoc, EveryAcceptedKeyIsDocumented) {
    const std::string doc = readDoc("docs/scene-format.md");
    size_t keys = 0;
    for (const perpdot::scene_keys::KeyList list : perpdot::scene_keys::all())
        for (const std::string_view key : list) {
            ++keys;
            std::string quoted(1, '`');  // built by append: GCC 12 warns wrongly on "`" + key + "`"
            quoted.append(key).push_back('`');
            EXPECT_NE(doc.find(quoted), std::string::npos)
                << "the reader accepts \"" << key << "\" but docs/scene-format.md does not document it";
        }
    EXPECT_GE(keys, 60u);  // the lists are not empty by accident
}

// The lists are the reader's: a listed key is accepted where the list applies, and a key in no
// list is refused with its JSON path.
TEST(SceneFormatDoc, ReaderUsesTheKeyLists) {
    const std::string head = R"({"format": "perpdot-scene/1", "bodies": [{"name": "a", "shapes": [{"type": "circle", "radius": 1)";
    EXPECT_NO_THROW(perpdot::parseScene(head + R"(, "center": [0, 1]}]}]})"));
    try {
        perpdot::parseScene(head + R"(, "centre": [0, 1]}]}]})");
        FAIL() << "a misspelled key was accepted";
    } catch (const perpdot::Error& e) {
        EXPECT_STREQ(e.what(), "bodies[0].shapes[0].centre: unknown key");
    }
}

TEST(SceneFormatDoc, ReadmeLinksTheSpecification) {
    const std::string readme = readDoc("README.md");
    EXPECT_NE(readme.find("(docs/scene-format.md)"), std::string::npos);
    EXPECT_EQ(readme.find("shared/scene-format.md"), std::string::npos) << "users cloning the repository lack ../shared";
}

}  // namespace
