// The README's quick-start is the program the install test builds against the installed package:
// this test fails if the two ever differ, so the README's code is always compiled and run.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace {

std::string readFile(const std::string& path) {
    std::ifstream in(path);
    EXPECT_TRUE(in) << "cannot open " << path;
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(Readme, QuickStartIsTheCompiledExample) {
    const std::string root = PERPDOT_TEST_DATA "/../..";
    const std::string readme = readFile(root + "/README.md");
    const std::string example = readFile(root + "/examples/quickstart/main.cpp");
    const std::string marker = "<!-- quickstart: examples/quickstart/main.cpp -->\n```cpp\n";
    const size_t begin = readme.find(marker);
    ASSERT_NE(begin, std::string::npos) << "README.md lacks the quick-start marker";
    const size_t codeBegin = begin + marker.size();
    const size_t codeEnd = readme.find("```", codeBegin);
    ASSERT_NE(codeEnd, std::string::npos);
    EXPECT_EQ(readme.substr(codeBegin, codeEnd - codeBegin), example);
}

}  // namespace
