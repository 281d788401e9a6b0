// The catalogue's record of where each file was found (catalog::SourceFile::searchDir):
// a module found through an -I directory outside --base-dir (an installed Prism's) is
// embedded relative to that directory with the directory's number, so hot reload can find
// it again, while files under --base-dir keep their rows unchanged.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "tool_runner.hpp"

namespace {
namespace fs = std::filesystem;
using prism::test::readFile;
using prism::test::runShaderc;
using prism::test::ScratchDir;

const std::string kFixture = std::string(PRISM_SOURCE_DIR) + "/tests/shaderc/fixtures/variants";

TEST(SearchDirs, ModulesOutsideTheBaseDirRecordTheirIncludeDirectory) {
    ScratchDir dir("search-dirs");
    fs::create_directories(dir.path() / "project");
    fs::create_directories(dir.path() / "prefix");
    fs::create_directories(dir.path() / "first");  // -I 1: empty, so the modules are found in -I 2
    fs::copy(kFixture + "/shaders", dir.path() / "project/shaders", fs::copy_options::recursive);
    fs::copy(kFixture + "/modules", dir.path() / "prefix/modules", fs::copy_options::recursive);
    fs::copy(kFixture + "/contract.json", dir.path() / "prefix/modules/contract.json");  // as Prism installs it
    const std::string args =
        "-o gen/c.hpp --base-dir project -I first -I prefix/modules --contract prefix/modules/contract.json "
        "project/shaders";
    const auto run = runShaderc(args, dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string data = readFile(dir.path() / "gen/c.cpp");
    EXPECT_TRUE(std::regex_search(data, std::regex(R"(\{[0-9]+, "lights\.glsl", 2\})"))) << "a line-table row";
    EXPECT_TRUE(std::regex_search(data, std::regex(R"(\{"lights", "lights\.glsl", .*, 2\},)"))) << "a module row";
    EXPECT_TRUE(std::regex_search(data, std::regex(R"(\{0, "shaders/tinted\.vert"\})"))) << "a base-dir row";
    EXPECT_NE(data.find("contract_files[] = { {0, \"contract.json\", 2}, };"), std::string::npos) << "the contract";
    EXPECT_EQ(data.find("\"../"), std::string::npos) << "no embedded path climbs out of the base dir";
    EXPECT_EQ(data.find(dir.str()), std::string::npos) << "no absolute path";
}

}  // namespace
