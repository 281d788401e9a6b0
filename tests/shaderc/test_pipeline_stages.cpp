// prism-shaderc's stages as main() sequences them (main.cpp): a usage error found by the
// command-line stage stops the run before anything is read or written, and the up-to-date
// stage (up_to_date.hpp) ends a repeated run before resolution, writing only the depfile.
// The client's rules are decided once by the command-line stage (target_rules.hpp), and the
// output stage's generators (output_generator.hpp) name every path they write.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "args.hpp"
#include "output_generator.hpp"
#include "target_rules.hpp"
#include "tool_runner.hpp"
#include "up_to_date.hpp"

namespace fs = std::filesystem;
using prism::test::readFile;
using prism::test::runShaderc;
using prism::test::ScratchDir;

namespace {

// parseArgs on `line` split at spaces (the program name first).
prism::shaderc::Options optionsOf(const std::string& line) {
    std::vector<std::string> words = {"prism-shaderc"};
    std::istringstream in(line);
    for (std::string w; in >> w;) words.push_back(w);
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(w.data());
    auto args = prism::shaderc::parseArgs(static_cast<int>(argv.size()), argv.data());
    EXPECT_TRUE(args.options.has_value()) << line;
    return args.options.value_or(prism::shaderc::Options{});
}

void writeValidShader(const ScratchDir& dir) {
    dir.write("s/a.vert", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n");
    dir.write("s/a.frag", "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n");
}

}  // namespace

TEST(PipelineStages, AHeaderNamedLikeItsDataFileIsAUsageError) {
    ScratchDir dir("stages-data-path");
    writeValidShader(dir);
    auto run = runShaderc("-o out.cpp s", dir.str());
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("prism-shaderc: error: -o out.cpp: the data file would overwrite the header; name the "
                              "header .hpp or .h"),
              std::string::npos)
        << run.output;
    EXPECT_FALSE(fs::exists(dir.path() / "out.cpp"));
}

TEST(PipelineStages, ARepeatedRunEndsBeforeResolutionAndWritesTheDepfile) {
    ScratchDir dir("stages-up-to-date");
    writeValidShader(dir);
    const std::string args = "-o out.hpp --depfile out.d --stats --cache-dir none s";
    auto first = runShaderc(args, dir.str());
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_NE(first.output.find("prism-shaderc: resolved "), std::string::npos) << first.output;
    fs::remove(dir.path() / "out.d");
    auto again = runShaderc(args, dir.str());
    EXPECT_EQ(again.exitCode, 0) << again.output;
    EXPECT_EQ(again.output, "") << "nothing resolved, validated or reported";
    EXPECT_NE(readFile(dir.path() / "out.d").find("s/a.frag"), std::string::npos);
}

TEST(PipelineStages, TheClientsRulesAreDecidedByTheCommandLine) {
    using namespace prism::shaderc;
    EXPECT_EQ(optionsOf("-o out.hpp s").rules, openGlClientRules());
    const TargetRules vulkan = optionsOf("--client vulkan --target-env vulkan1.3 -o out.hpp s").rules;
    EXPECT_EQ(vulkan, vulkanClientRules(SpirvEnv::Vulkan1_3));
    EXPECT_EQ(vulkan.spirvEnv, SpirvEnv::Vulkan1_3);
    EXPECT_TRUE(vulkan.linksStageByStage && vulkan.takesVulkanOnlyStages);
    EXPECT_FALSE(vulkan.needsFragmentStage || vulkan.checksContract || vulkan.explainsVulkanGlsl);
    EXPECT_EQ(optionsOf("--client vulkan -o out.hpp s").rules.spirvEnv, SpirvEnv::Vulkan1_2);
    // The spirv target's rules are its own, whatever the client.
    EXPECT_TRUE(spirvTargetRules().relaxedLayout);
    EXPECT_FALSE(spirvTargetRules().linksStageByStage);
}

TEST(PipelineStages, EachOutputOptionNamesItsGeneratorsPaths) {
    using prism::shaderc::outputPathsNamed;
    EXPECT_EQ(outputPathsNamed(optionsOf("-o g/out.hpp s")), (std::vector<std::string>{"g/out.hpp", "g/out.cpp"}));
    EXPECT_EQ(outputPathsNamed(optionsOf("--check --depfile c.d --stamp c.stamp s")), std::vector<std::string>{});
    const auto all = optionsOf(
        "-o out.hpp --target gl,es300,spirv --emit-spirv spv --emit-web web.js --emit-reflection r.json "
        "--emit-glsl glsl s");
    EXPECT_EQ(outputPathsNamed(all),
              (std::vector<std::string>{"out.hpp", "out.cpp", "spv", "web.js", "r.json", "glsl"}));
    std::set<std::string> names;
    for (const auto& g : prism::shaderc::outputGenerators()) names.insert(std::string(g->name()));
    EXPECT_EQ(names.size(), 5u) << "each output once";
}

// What a record of "nothing changed" relies on: every file a run writes is a generator's
// named path, inside one of them, the build system's depfile and stamp, or the record itself.
TEST(PipelineStages, EveryFileWrittenLiesUnderAGeneratorsNamedPaths) {
    ScratchDir dir("stages-generator-paths");
    writeValidShader(dir);
    const std::string args =
        "-o gen/out.hpp --depfile out.d --stamp out.stamp --cache-dir none --target gl,es300,spirv --emit-spirv spv "
        "--emit-web web/out.js --emit-reflection r.json --emit-glsl glsl";
    auto run = runShaderc(args + " s", dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::vector<std::string> named = prism::shaderc::outputPathsNamed(optionsOf(args + " s"));
    named.insert(named.end(), {"out.d", "out.stamp", "s", prism::shaderc::runRecordPath(optionsOf(args + " s"))});
    std::size_t files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(dir.path())) {
        if (!entry.is_regular_file()) continue;
        const std::string path = fs::relative(entry.path(), dir.path()).generic_string();
        bool under = false;
        for (const auto& n : named) under = under || path == n || path.starts_with(n + "/");
        EXPECT_TRUE(under) << path << " is written but named by no generator";
        ++files;
    }
    EXPECT_GE(files, 2u + 2u + 2u + 1u + 1u + 4u) << "sources, header and data, .spv, web, JSON, GLSL texts";
}
