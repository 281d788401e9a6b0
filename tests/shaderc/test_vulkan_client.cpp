// prism-shaderc --client vulkan as a program, differential against glslc: every case of
// fixtures/vulkan is accepted as `glslc --target-env=vulkan1.2` accepts it (and a broken
// one refused by both), the OpenGL client refuses each Vulkan-only construct with one
// error that names it, its line and --client vulkan, and every SPIR-V module emitted
// passes `spirv-val` (SPIRV-Tools' command line, a check independent of the library).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "tool_runner.hpp"

namespace fs = std::filesystem;
using prism::test::readFile;
using prism::test::runShaderc;
using prism::test::runShell;
using prism::test::ScratchDir;

namespace {

const fs::path kCases = fs::path(PRISM_SOURCE_DIR) / "tests/shaderc/fixtures/vulkan";
const std::vector<std::string> kCaseFolders{"push_constants", "descriptor_sets", "vertex_index",
                                            "spec_constants", "subpass_input",   "extensions",
                                            "mesh",           "ray_tracing",     "reflection"};

std::string modulesArg() {
    return "-I " + (kCases / "modules").string();
}

std::vector<fs::path> stageFiles(const std::string& folder) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(kCases / folder)) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

int glslcStatus(const fs::path& stage, const std::string& includeDir) {
    return runShell("glslc --target-env=vulkan1.2 -I '" + includeDir + "' -c '" + stage.string() + "' -o /dev/null")
        .exitCode;
}

int countOf(const std::string& text, const std::string& what) {
    int n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST(VulkanClient, EveryCaseIsAcceptedAsGlslcAcceptsIt) {
    for (const auto& folder : kCaseFolders) {
        for (const auto& stage : stageFiles(folder))
            EXPECT_EQ(glslcStatus(stage, (kCases / "modules").string()), 0) << "glslc refuses " << stage;
        const auto run =
            runShaderc("--client vulkan --check --cache-dir none " + modulesArg() + " " + (kCases / folder).string());
        EXPECT_EQ(run.exitCode, 0) << folder << ":\n" << run.output;
        EXPECT_EQ(run.output.find("error"), std::string::npos) << run.output;
    }
}

// A stage output without a location: SPIR-V for Vulkan needs one, so both refuse it.
TEST(VulkanClient, MissingLocationIsRefusedAsGlslcRefusesIt) {
    ScratchDir dir("vulkan-location");
    dir.write("s/bad.vert", "#version 450\nout vec4 v_color;\nvoid main() { v_color = vec4(1.0); }\n");
    dir.write("s/bad.frag",
              "#version 450\nin vec4 v_color;\nlayout(location = 0) out vec4 o;\n"
              "void main() { o = v_color; }\n");
    EXPECT_NE(glslcStatus(dir.path() / "s/bad.vert", dir.str()), 0);
    const auto run = runShaderc("--client vulkan --check --cache-dir none s", dir.str());
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("s/bad.vert:2:"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("location"), std::string::npos) << run.output;
}

struct GlRefusal {
    std::string folder, file, construct;
    int line;
};

// The OpenGL client (the default) refuses each construct once, at its own line.
TEST(VulkanClient, OpenGlClientNamesTheConstructAndTheVulkanClient) {
    const std::vector<GlRefusal> cases{
        {"push_constants", "tinted.vert", "push_constant", 3},
        {"descriptor_sets", "sets.vert", "descriptor set", 3},
        {"vertex_index", "fullscreen.vert", "gl_VertexIndex", 5},
        {"spec_constants", "blur.comp", "constant_id", 3},
        {"subpass_input", "composite.frag", "input_attachment_index", 3},
    };
    for (const auto& c : cases) {
        const auto run = runShaderc("--check --cache-dir none --glsl-version 450 " + modulesArg() + " " +
                                    (kCases / c.folder).string());
        EXPECT_EQ(run.exitCode, 1) << run.output;
        const std::string where = (kCases / c.folder / c.file).string() + ":" + std::to_string(c.line) + ":";
        EXPECT_NE(run.output.find(where), std::string::npos) << where << "\n" << run.output;
        EXPECT_NE(run.output.find("'" + c.construct + "' is Vulkan GLSL"), std::string::npos) << run.output;
        EXPECT_NE(run.output.find("--client vulkan"), std::string::npos) << run.output;
        const std::string file = (kCases / c.folder / c.file).string() + ":";
        EXPECT_EQ(countOf(run.output, file), 1) << "one message for " << file << "\n" << run.output;
    }
}

TEST(VulkanClient, OpenGlClientRefusesVulkanStageKinds) {
    for (const auto& folder : {"mesh", "ray_tracing"}) {
        const auto run = runShaderc("--check --cache-dir none " + (kCases / folder).string());
        EXPECT_EQ(run.exitCode, 1) << run.output;
        const std::regex refusal(R"(/(meshlet\.mesh|meshlet\.task|scene\.rgen|scene\.rmiss|scene\.rchit): error: )"
                                 R"(a \.\w+ stage is Vulkan GLSL: build it with --client vulkan)");
        EXPECT_TRUE(std::regex_search(run.output, refusal)) << run.output;
    }
}

// Every module of every case, as --emit-spirv writes it, passes spirv-val for Vulkan 1.2.
TEST(VulkanClient, EveryEmittedModulePassesSpirvVal) {
    ScratchDir dir("vulkan-spv");
    std::string inputs;
    for (const auto& folder : kCaseFolders) inputs += " " + (kCases / folder).string();
    const auto run =
        runShaderc("--client vulkan --check --cache-dir none --emit-spirv spv " + modulesArg() + inputs, dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::set<std::string> expected;
    for (const auto& folder : kCaseFolders)
        for (const auto& stage : stageFiles(folder)) expected.insert(stage.filename().string() + ".spv");
    std::set<std::string> written;
    for (const auto& e : fs::directory_iterator(dir.path() / "spv")) {
        written.insert(e.path().filename().string());
        const auto val = runShell("spirv-val --target-env vulkan1.2 '" + e.path().string() + "'");
        EXPECT_EQ(val.exitCode, 0) << e.path() << ": " << val.output;
        EXPECT_EQ(readFile(e.path()).substr(0, 4), std::string("\x03\x02\x23\x07", 4)) << e.path();
    }
    EXPECT_EQ(written, expected);
}

TEST(VulkanClient, TargetEnvPicksTheSpirvVersion) {
    ScratchDir dir("vulkan-env");
    const auto folder = (kCases / "vertex_index").string();
    ASSERT_EQ(runShaderc("--client vulkan --target-env vulkan1.0 --check --emit-spirv a " + folder, dir.str()).exitCode,
              0);
    ASSERT_EQ(runShaderc("--client vulkan --target-env vulkan1.3 --check --emit-spirv b " + folder, dir.str()).exitCode,
              0);
    EXPECT_EQ(readFile(dir.path() / "a/fullscreen.vert.spv").substr(4, 4), std::string("\x00\x00\x01\x00", 4));
    EXPECT_EQ(readFile(dir.path() / "b/fullscreen.vert.spv").substr(4, 4), std::string("\x00\x06\x01\x00", 4));
    EXPECT_EQ(runShell("spirv-val --target-env vulkan1.0 " + (dir.path() / "a/fullscreen.vert.spv").string()).exitCode,
              0);
}

TEST(VulkanClient, BadTargetEnvIsAUsageError) {
    const auto folder = (kCases / "vertex_index").string();
    auto run = runShaderc("--client vulkan --target-env vulkan2.0 --check " + folder);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("--target-env vulkan2.0: not a Vulkan version; use vulkan1.0, vulkan1.1, vulkan1.2 or "
                              "vulkan1.3"),
              std::string::npos)
        << run.output;
    run = runShaderc("--client vulkan --target-env opengl4.5 --check " + folder);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    run = runShaderc("--target-env vulkan1.2 --check " + folder);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("add --client vulkan or drop --target-env"), std::string::npos) << run.output;
    run = runShaderc("--check --emit-spirv spv " + folder);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("writes SPIR-V, and this run makes none; add the spirv target (--target gl,spirv), "
                              "or --client vulkan for Vulkan GLSL, or drop --emit-spirv"),
              std::string::npos)
        << run.output;
    run = runShaderc("--client metal --check " + folder);
    EXPECT_EQ(run.exitCode, 2) << run.output;
}

// A Vulkan-client catalogue's output is SPIR-V: --target spirv says so and changes nothing;
// gl and es300 are OpenGL text, a usage error that names --client opengl.
TEST(VulkanClient, TargetMayOnlySaySpirv) {
    const auto folder = (kCases / "vertex_index").string();
    ScratchDir dir("vulkan-target");
    ASSERT_EQ(runShaderc("--client vulkan --check --cache-dir none --emit-spirv a " + folder, dir.str()).exitCode, 0);
    ASSERT_EQ(runShaderc("--client vulkan --target spirv --check --cache-dir none --emit-spirv b " + folder, dir.str())
                  .exitCode,
              0);
    EXPECT_EQ(prism::test::readFile(dir.path() / "a/vertex_index.vert.spv"),
              prism::test::readFile(dir.path() / "b/vertex_index.vert.spv"));
    for (const std::string list : {"gl", "gl,spirv", "es300"}) {
        const auto run = runShaderc("--client vulkan --target " + list + " --check " + folder);
        EXPECT_EQ(run.exitCode, 2) << run.output;
        EXPECT_NE(run.output.find("--target " + list +
                                  " with --client vulkan: a Vulkan-client catalogue's output is "
                                  "SPIR-V"),
                  std::string::npos)
            << run.output;
    }
}

// Includes, module paths and "included from" work as with the OpenGL client.
TEST(VulkanClient, ModuleErrorsKeepTheirFileLineAndIncluder) {
    ScratchDir dir("vulkan-include");
    dir.write("m/tone.glsl", "// Tone mapping.\nvec3 tone(vec3 c) {\n    return c / (c + missing);\n}\n");
    dir.write("s/post.vert", "#version 450\nvoid main() { gl_Position = vec4(float(gl_VertexIndex)); }\n");
    dir.write("s/post.frag",
              "#version 450\n#include \"tone.glsl\"\nlayout(location = 0) out vec4 o;\n"
              "void main() { o = vec4(tone(vec3(1.0)), 1.0); }\n");
    const auto run = runShaderc("--client vulkan --check --cache-dir none -I m s", dir.str());
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("m/tone.glsl:3:"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("included from s/post.frag:2"), std::string::npos) << run.output;
}

// glslang predefines VULKAN for Vulkan GLSL: include resolution sees it as the compiler does.
TEST(VulkanClient, IncludesFollowTheVulkanMacro) {
    ScratchDir dir("vulkan-macro");
    dir.write("m/vk.glsl", "// The Vulkan side.\nlayout(location = 0) out vec4 o;\n");
    dir.write("m/gl.glsl", "// The OpenGL side.\nout vec4 o;\n");
    dir.write("s/pick.vert", "#version 450\nvoid main() { gl_Position = vec4(0.0); }\n");
    dir.write("s/pick.frag",
              "#version 450\n#ifdef VULKAN\n#include \"vk.glsl\"\n#else\n#include \"gl.glsl\"\n#endif\n"
              "void main() { o = vec4(1.0); }\n");
    const auto vk = runShaderc("--client vulkan -o out.hpp --cache-dir none -I m s", dir.str());
    ASSERT_EQ(vk.exitCode, 0) << vk.output;
    const auto data = readFile(dir.path() / "out.cpp");
    EXPECT_NE(data.find("{1, \"m/vk.glsl\"}"), std::string::npos) << "the stage's line table names the module";
    EXPECT_EQ(data.find("{1, \"m/gl.glsl\"}"), std::string::npos);
}

// Two programs with one identical stage: its SPIR-V is stored once.
TEST(VulkanClient, EachDistinctModuleIsStoredOnce) {
    ScratchDir dir("vulkan-once");
    const std::string vert = "#version 450\nvoid main() { gl_Position = vec4(float(gl_VertexIndex)); }\n";
    dir.write("s/a.vert", vert);
    dir.write("s/b.vert", vert);
    dir.write("s/a.frag", "#version 450\nlayout(location = 0) out vec4 o;\nvoid main() { o = vec4(1.0); }\n");
    dir.write("s/b.frag", "#version 450\nlayout(location = 0) out vec4 o;\nvoid main() { o = vec4(0.5); }\n");
    ASSERT_EQ(runShaderc("--client vulkan -o out.hpp --cache-dir none s", dir.str()).exitCode, 0);
    const auto data = readFile(dir.path() / "out.cpp");
    EXPECT_EQ(countOf(data, "_spirv[] = {"), 3) << data;
}

// The client is part of every reuse decision: the outputs, the validation cache and the
// no-op check never hand one client's results to the other.
TEST(VulkanClient, SwitchingTheClientRebuildsAndTheCacheKeepsSpirv) {
    ScratchDir dir("vulkan-switch");
    dir.write("s/plain.vert",
              "#version 450\nlayout(location = 0) in vec3 a_position;\n"
              "void main() { gl_Position = vec4(a_position, 1.0); }\n");
    dir.write("s/plain.frag", "#version 450\nlayout(location = 0) out vec4 o;\nvoid main() { o = vec4(1.0); }\n");
    const std::string args = "-o out.hpp --stamp out.stamp --stats s";
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    const auto gl = readFile(dir.path() / "out.cpp");
    EXPECT_EQ(gl.find("spirv"), std::string::npos);
    auto vk = runShaderc("--client vulkan " + args, dir.str());
    ASSERT_EQ(vk.exitCode, 0) << vk.output;
    EXPECT_NE(vk.output.find("0 from the cache"), std::string::npos) << vk.output;
    const auto vulkan = readFile(dir.path() / "out.cpp");
    EXPECT_NE(vulkan.find("0x07230203"), std::string::npos);
    EXPECT_NE(vulkan.find("\"vulkan1.2\"};"), std::string::npos);
    fs::remove(dir.path() / "out.cpp");
    vk = runShaderc("--client vulkan " + args, dir.str());
    ASSERT_EQ(vk.exitCode, 0) << vk.output;
    EXPECT_NE(vk.output.find("1 from the cache"), std::string::npos) << vk.output;
    EXPECT_EQ(readFile(dir.path() / "out.cpp"), vulkan) << "the cache must give back the same SPIR-V and reflection";
    ASSERT_EQ(runShaderc(args, dir.str()).exitCode, 0);
    EXPECT_EQ(readFile(dir.path() / "out.cpp"), gl);
}

}  // namespace

namespace {

// The same bytes whatever -j, and no path of this machine in them (no SPIR-V debug information).
TEST(VulkanClient, OutputsAreDeterministicAndHermetic) {
    ScratchDir dir("vulkan-determinism");
    const std::string args = " --client vulkan --cache-dir none -o out.hpp --base-dir " + kCases.string() + " " +
                             modulesArg() + " " + (kCases / "reflection").string() + " " +
                             (kCases / "extensions").string() + " " + (kCases / "mesh").string();
    fs::create_directories(dir.path() / "a");
    fs::create_directories(dir.path() / "b");
    ASSERT_EQ(runShaderc("-j 1" + args, (dir.path() / "a").string()).exitCode, 0);
    ASSERT_EQ(runShaderc("-j 4" + args, (dir.path() / "b").string()).exitCode, 0);
    const auto one = readFile(dir.path() / "a/out.hpp") + readFile(dir.path() / "a/out.cpp");
    EXPECT_EQ(one, readFile(dir.path() / "b/out.hpp") + readFile(dir.path() / "b/out.cpp"));
    EXPECT_EQ(one.find(PRISM_SOURCE_DIR), std::string::npos);
    EXPECT_EQ(one.find(dir.str()), std::string::npos);
}

}  // namespace
