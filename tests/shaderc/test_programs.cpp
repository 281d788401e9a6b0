// prism-shaderc's programs (issue 24, items 2 to 4) through the real command line:
// tessellation folders, warnings for the files of an input folder that are no stage,
// `--program NAME=FILE,...` with its errors and shared stages, names that are not C++
// identifiers, and differential checks against `glslangValidator -l` on
// fixtures/programs/.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "module_naming.hpp"
#include "tool_runner.hpp"

namespace fs = std::filesystem;
using prism::test::readFile;
using prism::test::runShaderc;
using prism::test::runShell;
using prism::test::ScratchDir;

namespace {

const fs::path kPrograms = fs::path(PRISM_SOURCE_DIR) / "tests/shaderc/fixtures/programs";

std::string fixture(const std::string& relative) {
    return (kPrograms / relative).string();
}

std::string glslangLinks(const std::vector<std::string>& files) {
    std::string line = "glslangValidator -l";
    for (const auto& f : files) line += " '" + fixture(f) + "'";
    return line;
}

std::string prismChecks(const std::vector<std::string>& files) {
    std::string line = "--check --program p=";
    for (std::size_t i = 0; i < files.size(); ++i) line += (i ? "," : "") + fixture(files[i]);
    return line;
}

// Both tools on the same stage files: the same verdict.
void expectSameVerdictAsGlslang(const std::vector<std::string>& files, bool accepted) {
    const auto reference = runShell(glslangLinks(files));
    EXPECT_EQ(reference.exitCode == 0, accepted) << "glslang's verdict is not the fixture's:\n" << reference.output;
    const auto prism = runShaderc(prismChecks(files));
    EXPECT_EQ(prism.exitCode == 0, accepted) << prism.output;
}

}  // namespace

TEST(ProgramsGlslang, TessellationProgramAgrees) {
    expectSameVerdictAsGlslang({"tess/terrain.vert", "tess/terrain.tesc", "tess/terrain.tese", "tess/terrain.frag"},
                               true);
}

TEST(ProgramsGlslang, TessellationTypeClashAgrees) {
    expectSameVerdictAsGlslang({"tess_mismatch/terrain.vert", "tess_mismatch/terrain.tesc",
                                "tess_mismatch/terrain.tese", "tess_mismatch/terrain.frag"},
                               false);
    const auto prism = runShaderc("--check " + fixture("tess_mismatch"));
    EXPECT_NE(prism.output.find("terrain.tese:5:9: error: tese input 'tc_position' is `smooth vec4` but the tesc "
                                "output is `smooth vec3` (type mismatch)"),
              std::string::npos)
        << prism.output;
}

TEST(ProgramsGlslang, InterfaceMatchedByLocationAgrees) {
    expectSameVerdictAsGlslang({"location/matched.vert", "location/matched.frag"}, true);
}

// glslang -l pairs by name only, so it misses this clash, which a GL driver links by
// location: Prism goes further than the reference here.
TEST(ProgramsGlslang, LocationTypeClashGlslangMissesIsAnError) {
    EXPECT_EQ(runShell(glslangLinks({"location/clash.vert", "location/clash.frag"})).exitCode, 0);
    const auto prism = runShaderc(prismChecks({"location/clash.vert", "location/clash.frag"}));
    EXPECT_EQ(prism.exitCode, 1) << prism.output;
    EXPECT_NE(prism.output.find("clash.frag:3:30: error: frag input 'in_uv' (location 0) is `smooth vec3` but the "
                                "vert output 'v_texcoord' (location 0) is `smooth vec2`"),
              std::string::npos)
        << prism.output;
}

TEST(ProgramsCli, TessellationFolderIsOneProgramOfFourStagesInPipelineOrder) {
    ScratchDir out("programs-tess");
    const auto r = runShaderc("-o " + out.str() + "/tess.hpp " + fixture("tess"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto data = readFile(out.path() / "tess.cpp");
    const std::regex stages(R"(Stage::(\w+), )");
    std::string order;
    for (std::sregex_iterator it(data.begin(), data.end(), stages), end; it != end; ++it) order += (*it)[1].str() + " ";
    EXPECT_EQ(order, "Vertex TessControl TessEvaluation Fragment ");
    EXPECT_NE(readFile(out.path() / "tess.hpp").find("    terrain = 0,"), std::string::npos);
}

TEST(ProgramsCli, ControlStageWithoutEvaluationStageIsAnError) {
    ScratchDir dir("programs-tesc-alone");
    for (const char* ext : {"vert", "tesc", "frag"})
        fs::copy_file(kPrograms / "tess" / (std::string("terrain.") + ext), dir.path() / (std::string("t.") + ext));
    const auto r = runShaderc("--check " + dir.str());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("t.vert: error: shader 't' has a tessellation control stage but no evaluation stage: "
                            "expected " +
                            dir.str() + "/t.tese"),
              std::string::npos)
        << r.output;
}

TEST(ProgramsCli, FolderFilesThatAreNoStageAreWarningsNamingThemButModulesAreNot) {
    ScratchDir dir("programs-warn");
    fs::copy_file(kPrograms / "shared/fullscreen.vert", dir.path() / "post.vert");
    fs::copy_file(kPrograms / "shared/tonemap.frag", dir.path() / "post.frag");
    dir.write("notes.md", "# notes\n");
    dir.write("post.hlsl", "float4 main() : SV_Target { return 1; }\n");
    dir.write("common.glsl", "// A module the stages may include.\nfloat one() { return 1.0; }\n");
    const auto r = runShaderc("--check " + dir.str());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(dir.str() + "/notes.md: warning: not a stage Prism takes (.vert, .tesc, .tese, .geom, "
                                        ".frag or .comp (with --client vulkan also .mesh, .task, .rgen, .rint, "
                                        ".rahit, .rchit, .rmiss or .rcall)) nor a module (.glsl); skipped"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(dir.str() + "/post.hlsl: warning: not a stage"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("common.glsl"), std::string::npos) << r.output;
}

// A Vulkan-only stage in a folder under the OpenGL client is no silent skip and no mere
// warning: the folder is most likely Vulkan code built without --client vulkan.
TEST(ProgramsCli, FolderMeshStageUnderTheGlClientIsOneErrorNamingTheClient) {
    ScratchDir dir("programs-mesh");
    fs::copy_file(kPrograms / "shared/tonemap.frag", dir.path() / "post.frag");
    dir.write("post.mesh", "#version 450\n");
    const auto r = runShaderc("--check " + dir.str());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(
        r.output.find(dir.str() + "/post.mesh: error: a .mesh stage is Vulkan GLSL: build it with --client vulkan"),
        std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("mixes a mesh pipeline"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("no fragment stage"), std::string::npos) << r.output;
}

TEST(ProgramsCli, FolderWithoutStagesIsAnErrorNotZeroOfZero) {
    ScratchDir dir("programs-none");
    dir.write("a.hlsl", "float4 main() : SV_Target { return 1; }\n");
    const auto r = runShaderc("--check --stats " + dir.str());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(dir.str() + "/a.hlsl: warning: not a stage"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(dir.str() + ": error: no stage files"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("validated 0 of 0"), std::string::npos) << r.output;
}

TEST(ProgramsCli, SharedVertexStageIsParsedOnceAndNamesAreMangledReversibly) {
    ScratchDir out("programs-shared");
    const std::string vert = fixture("shared/fullscreen.vert");
    const auto r = runShaderc("--stats --cache-dir none -o " + out.str() +
                              "/post.hpp --program blur-h=" + fixture("shared/blur_h.frag") + "," + vert +
                              " --program 16bit_storage=" + vert + "," + fixture("shared/tonemap.frag") +
                              " --program tonemap=" + vert + "," + fixture("shared/tonemap.frag"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // 3 programs of 2 stages: the vertex stage once, blur_h.frag once, tonemap.frag once
    // (16bit_storage and tonemap are one token stream: validated once).
    EXPECT_NE(r.output.find("validated 2 of 3 programs (1 shared a token stream, 0 from the cache; 3 stages parsed)"),
              std::string::npos)
        << r.output;
    const auto header = readFile(out.path() / "post.hpp");
    const std::string blur = prism::shaderc::mangleName("blur-h"),
                      storage = prism::shaderc::mangleName("16bit_storage");
    EXPECT_EQ(blur, "_626c75722d68");
    EXPECT_EQ(prism::shaderc::demangleName(storage), "16bit_storage");
    EXPECT_NE(header.find("    " + storage + " = 0,\n    " + blur + " = 1,\n    tonemap = 2,"), std::string::npos)
        << header;
    EXPECT_NE(header.find("\"16bit_storage\",\n    \"blur-h\",\n    \"tonemap\","), std::string::npos) << header;
    // Stages in pipeline order although blur-h named its fragment stage first; its vertex
    // stage is the one 16bit_storage stores (each distinct text is stored once).
    const auto data = readFile(out.path() / "post.cpp");
    EXPECT_NE(
        data.find(blur + "_v0_stages[] = {\n    {prism::catalog::Stage::Vertex, " + storage + "_v0_vert_chunks, " +
                  storage + "_v0_vert_files},\n    {prism::catalog::Stage::Fragment, " + blur + "_v0_frag_chunks"),
        std::string::npos)
        << data;
}

TEST(ProgramsCli, DeclaredProgramBesideSameNamePairsOfAFolder) {
    const auto r = runShaderc("--check " + fixture("tess") + " --program post=" + fixture("shared/fullscreen.vert") +
                              "," + fixture("shared/tonemap.frag") + " --stats --cache-dir none");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("of 2 programs"), std::string::npos) << r.output;
}

TEST(ProgramsCli, FolderFilesThatADeclarationNamesAreNotPairedByName) {
    ScratchDir dir("programs-claimed");
    for (const char* f : {"fullscreen.vert", "blur_h.frag", "tonemap.frag"})
        fs::copy_file(kPrograms / "shared" / f, dir.path() / f);
    fs::copy_file(kPrograms / "shared/fullscreen.vert", dir.path() / "plain.vert");
    fs::copy_file(kPrograms / "shared/tonemap.frag", dir.path() / "plain.frag");
    const std::string d = dir.str() + "/";
    const auto r =
        runShaderc("--check --stats --cache-dir none " + dir.str() + " --program blur-h=" + d + "fullscreen.vert," + d +
                   "blur_h.frag --program tonemap=" + d + "tonemap.frag," + d + "fullscreen.vert");
    // Without the rule, fullscreen, blur_h and tonemap would be incomplete same-name sets.
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("of 3 programs"), std::string::npos) << r.output;
}

namespace {

struct DeclarationError {
    std::string argument;  // after --program, with {F} for the fixtures folder
    std::string message;   // after "--program <argument>: error: "
};

}  // namespace

TEST(ProgramsCli, EachBadDeclarationIsAGccStyleErrorNamingTheArgument) {
    const std::string f = kPrograms.string();
    const std::vector<DeclarationError> cases = {
        {"p=" + f + "/shared/fullscreen.vert," + f + "/shared/x.frg",
         "'" + f + "/shared/x.frg': unknown stage extension; use .vert, .tesc, .tese, .geom, .frag or .comp"},
        {"p=" + f + "/shared/missing.frag," + f + "/shared/fullscreen.vert",
         "'" + f + "/shared/missing.frag': no such file"},
        {"p=" + f + "/shared/fullscreen.vert," + f + "/shared/blur_h.frag," + f + "/shared/tonemap.frag",
         "'" + f + "/shared/blur_h.frag' and '" + f + "/shared/tonemap.frag' are both frag stages"},
        {"p=" + f + "/shared/blur_h.frag", "shader 'p' has no vertex stage (nor a compute stage)"},
        {f + "/shared/fullscreen.vert", "expected NAME=FILE[,FILE...]"},
        {"a/b=" + f + "/shared/fullscreen.vert," + f + "/shared/blur_h.frag", "program name 'a/b' contains '/'"},
        {"a:b=" + f + "/shared/fullscreen.vert," + f + "/shared/blur_h.frag",
         "program name 'a:b' contains '/', '\\', "
         "',' or ':'"},
        {"p=" + f + "/shared/fullscreen.vert,," + f + "/shared/blur_h.frag", "an empty file name in the list"},
    };
    for (const auto& c : cases) {
        const auto r = runShaderc("--check --program '" + c.argument + "'");
        EXPECT_NE(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find("--program " + c.argument + ": error: " + c.message), std::string::npos)
            << "for --program " << c.argument << ":\n"
            << r.output;
    }
}

TEST(ProgramsCli, DuplicateProgramNameIsAnError) {
    const std::string pair = fixture("shared/fullscreen.vert") + "," + fixture("shared/tonemap.frag");
    auto r = runShaderc("--check --program post=" + pair + " --program post=" + pair);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("--program post=" + pair + ": error: program 'post' is declared twice"), std::string::npos)
        << r.output;
    r = runShaderc("--check " + fixture("tess") + " --program terrain=" + pair);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("program 'terrain' is declared twice"), std::string::npos) << r.output;
}

TEST(ProgramsCli, MissingFileIsAnInputErrorLikeAMissingPositionalInput) {
    const auto r = runShaderc("--check --program p=/nonexistent/a.vert," + fixture("shared/tonemap.frag"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
}
