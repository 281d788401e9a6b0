// prism-shaderc's targets (docs/targets.md): the --target list, a stage's
// `#pragma prism targets`, es300's refusal of geometry and compute stages, ES-only errors
// at the module's own file:line, the ES 3.00 minimum-limits warning, every es300 program of
// the project's catalogues validated and linked as ES 3.00 (checked again by the reference,
// glslangValidator), every SPIR-V module through SPIRV-Tools (and spirv-val), the data file
// of all three targets, and golden texts of one shader per target.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "baseline.hpp"
#include "corpus_output_checks.hpp"
#include "es300_limits.hpp"
#include "targets.hpp"
#include "tool_runner.hpp"

namespace fs = std::filesystem;
using prism::test::expectMatchesBaseline;
using prism::test::runShaderc;
using prism::test::runShell;
using prism::test::ScratchDir;
using namespace prism::shaderc;

namespace {

const std::string kSource = PRISM_SOURCE_DIR;

// A scratch tree: modules under mods/, stages under sh/.
std::string scratchArgs(const ScratchDir& dir, const std::string& targets) {
    return "--check --cache-dir none --target " + targets + " --base-dir " + dir.str() + " -I mods sh";
}

const char* kPlainFrag =
    "// plain fragment stage\n#version 330 core\nout vec4 o_color;\n"
    "void main() { o_color = vec4(1.0); }\n";

void writeGeometryShader(const ScratchDir& dir, const std::string& pragma) {
    dir.write("sh/sprites.vert",
              "// sprites\n#version 330 core\nin vec3 a_position;\n"
              "void main() { gl_Position = vec4(a_position, 1.0); }\n");
    dir.write("sh/sprites.geom", "// sprites: points to points\n#version 330 core\n" + pragma +
                                     "\nlayout(points) in;\nlayout(points, max_vertices = 1) out;\n"
                                     "void main() { gl_Position = gl_in[0].gl_Position; EmitVertex(); }\n");
    dir.write("sh/sprites.frag", kPlainFrag);
    dir.write("mods/.keep.glsl", "// nothing\n");
}

}  // namespace

TEST(Targets, ListParsesInOrderAndNamesAMisspelling) {
    std::vector<Target> targets;
    EXPECT_EQ(parseTargetList("spirv,gl es300,gl", targets), "");
    EXPECT_EQ(targetListText(targets), "gl es300 spirv");
    const auto error = parseTargetList("gl,es3000", targets);
    EXPECT_NE(error.find("unknown target 'es3000' (did you mean 'es300'?)"), std::string::npos) << error;
    EXPECT_NE(parseTargetList(" , ", targets), "");
}

TEST(Targets, CommandLineRefusesAnUnknownTarget) {
    ScratchDir dir("targets-cli");
    const auto run = runShaderc("--check --target gl,webgl " + kSource + "/shader_sources/flat.vert", dir.str());
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("--target gl,webgl: unknown target 'webgl'"), std::string::npos) << run.output;
}

TEST(Targets, Es300RefusesAGeometryStageNamingShaderFileAndTarget) {
    ScratchDir dir("targets-geom");
    writeGeometryShader(dir, "");
    const auto run = runShaderc(scratchArgs(dir, "gl,es300"), dir.str());
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("sh/sprites.geom: error: shader 'sprites' has a geometry stage, which es300"),
              std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("#pragma prism targets gl spirv"), std::string::npos) << run.output;
    EXPECT_EQ(runShaderc(scratchArgs(dir, "gl"), dir.str()).exitCode, 0);
}

TEST(Targets, Es300RefusesAComputeStageNamingShaderFileAndTarget) {
    ScratchDir dir("targets-comp");
    dir.write("sh/blur.comp", "// blur\n#version 430 core\nlayout(local_size_x = 8) in;\nvoid main() {}\n");
    dir.write("mods/.keep.glsl", "// nothing\n");
    const auto run = runShaderc(scratchArgs(dir, "gl,es300"), dir.str());
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("sh/blur.comp: error: shader 'blur' has a compute stage, which es300"), std::string::npos)
        << run.output;
    EXPECT_EQ(runShaderc(scratchArgs(dir, "gl,spirv"), dir.str()).exitCode, 0);
}

TEST(Targets, Es300RefusesTessellationStagesNamingTheirKind) {
    ScratchDir dir("targets-tess");
    const fs::path tess = fs::path(kSource) / "tests/shaderc/fixtures/programs/tess";
    fs::create_directories(dir.path() / "sh");
    for (const char* stage : {"terrain.vert", "terrain.tesc", "terrain.tese", "terrain.frag"})
        fs::copy_file(tess / stage, dir.path() / "sh" / stage);
    dir.write("mods/.keep.glsl", "// nothing\n");
    const auto run = runShaderc(scratchArgs(dir, "gl,es300"), dir.str());
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("has a tessellation control stage, which es300"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("has a this stage"), std::string::npos) << run.output;
}

TEST(Targets, PragmaLeavesTheShaderOutOfEs300AndKeepsItForGl) {
    ScratchDir dir("targets-pragma");
    writeGeometryShader(dir, "#pragma prism targets gl spirv");
    dir.write("sh/plain.vert",
              "// plain\n#version 330 core\nin vec3 a_position;\n"
              "void main() { gl_Position = vec4(a_position, 1.0); }\n");
    dir.write("sh/plain.frag", kPlainFrag);
    const auto run = runShaderc(scratchArgs(dir, "gl,es300") + " --emit-glsl out", dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_TRUE(fs::exists(dir.path() / "out/sprites.gl.geom"));
    EXPECT_FALSE(fs::exists(dir.path() / "out/sprites.es300.vert"));
    EXPECT_TRUE(fs::exists(dir.path() / "out/plain.es300.frag"));
    EXPECT_TRUE(fs::exists(dir.path() / "out/plain.gl.frag"));
    // Asked for by name, the shader's missing target is an error at the pragma.
    const auto named = runShaderc(scratchArgs(dir, "gl,es300") + " --variant sprites:", dir.str());
    EXPECT_EQ(named.exitCode, 1) << named.output;
    EXPECT_NE(named.output.find("sh/sprites.geom:3:1: error: --variant sprites: asks for shader 'sprites' with "
                                "--target es300, but it declares only targets gl spirv"),
              std::string::npos)
        << named.output;
}

TEST(Targets, PragmaErrorsNameTheLine) {
    ScratchDir dir("targets-pragma-errors");
    writeGeometryShader(dir, "#pragma prism targets gl es300 spirv");
    auto run = runShaderc(scratchArgs(dir, "gl,es300"), dir.str());
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("sh/sprites.geom:3:1: error: shader 'sprites' has a geometry stage, which es300"),
              std::string::npos)
        << run.output;
    writeGeometryShader(dir, "#pragma prism targets gl spirve");
    run = runShaderc(scratchArgs(dir, "gl"), dir.str());
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("sh/sprites.geom:3:1: error: #pragma prism targets: unknown target 'spirve' (did you "
                              "mean 'spirv'?)"),
              std::string::npos)
        << run.output;
    writeGeometryShader(dir, "#pragma prism targets spirv");
    run = runShaderc(scratchArgs(dir, "gl"), dir.str());
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("sh/sprites.geom:3:1: error: #pragma prism targets spirv: list gl too"),
              std::string::npos)
        << run.output;
}

// Desktop-only constructs are errors at the module's own line and column, with the include
// chain, for es300 only: the same files pass as gl.
TEST(Targets, EsOnlyErrorsAreReportedAtTheModuleLine) {
    ScratchDir dir("targets-es-errors");
    dir.write("mods/halves.glsl",
              "// halves: an implicit int -> float conversion, legal in desktop GLSL\n"
              "float halfOf(int n) {\n    float x = n;\n    return x * 0.5;\n}\n");
    dir.write("sh/conv.vert",
              "// conv\n#version 330 core\n#include <halves.glsl>\nin vec3 a_position;\n"
              "void main() { gl_Position = vec4(a_position * halfOf(2), 1.0); }\n");
    dir.write("sh/conv.frag", kPlainFrag);
    dir.write("sh/ivary.vert",
              "// ivary: an integer output without flat\n#version 330 core\nin vec3 a_position;\n"
              "out int v_id;\nvoid main() { v_id = gl_VertexID; gl_Position = vec4(a_position, 1.0); }\n");
    dir.write("sh/ivary.frag", kPlainFrag);
    EXPECT_EQ(runShaderc(scratchArgs(dir, "gl"), dir.str()).exitCode, 0);
    const auto run = runShaderc(scratchArgs(dir, "gl,es300"), dir.str());
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("mods/halves.glsl:3:13: error: '=': cannot convert from"), std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("  included from sh/conv.vert:3"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("sh/ivary.vert:4:5: error: 'int': must be qualified as flat"), std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("for target es300 (GLSL ES 3.00) in program 'ivary'"), std::string::npos) << run.output;
}

// es300 parses each distinct stage once, as gl does (shared_stage_parses.hpp): two variants
// that differ in the fragment stage only parse the vertex stage once, 3 parses for 4 stages.
TEST(Targets, Es300ParsesEachDistinctStageOnce) {
    ScratchDir dir("targets-es-shared");
    dir.write("sh/fog.vert",
              "// fog\n#version 330 core\nin vec3 a_position;\n"
              "void main() { gl_Position = vec4(a_position, 1.0); }\n");
    dir.write("sh/fog.frag",
              "// fog: two variants\n#version 330 core\n#pragma prism variant FOG 0 1\nout vec4 o_color;\n"
              "void main() { o_color = vec4(float(FOG)); }\n");
    dir.write("mods/.keep.glsl", "// nothing\n");
    const auto run = runShaderc(scratchArgs(dir, "gl,es300") + " --stats", dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(
        run.output.find("es300: validated 2 programs (0 shared a token stream, 0 from the cache; 3 stages parsed)"),
        std::string::npos)
        << run.output;
}

TEST(Targets, PackingRuleOfTheEsSpec) {
    EXPECT_EQ(packedRows({{4, 4, 1}}), 4);                     // mat4
    EXPECT_EQ(packedRows({{1, 3, 2}, {1, 1, 2}}), 2);          // two vec3 rows take two floats
    EXPECT_EQ(packedRows({{1, 2, 3}}), 2);                     // three vec2: two rows
    EXPECT_EQ(packedRows({{1, 2, 1}, {1, 1, 3}}), 2);          // vec2 + 2 floats in one row, 1 in the next
    EXPECT_EQ(packedRows({{1, 4, 300}}), 300);                 // vec4[300]
    EXPECT_EQ(packedRows({shapeOfGlslType("mat3x2", 0)}), 2);  // 3 columns of vec2: two share a row
    EXPECT_EQ(shapeOfGlslType("ivec3", 4).count, 4);
}

// One program over each minimum: 300 vertex uniform vectors, 225 fragment ones, 16 vec4
// varyings and 17 samplers. Warnings, not errors: exit 0.
TEST(Targets, LimitsWarningNamesProgramLimitAndCount) {
    ScratchDir dir("targets-limits");
    std::string outs, ins, sum = "vec4(0.0)";
    for (int i = 0; i < 16; ++i) {
        outs += "out vec4 v_" + std::to_string(i) + ";\n";
        ins += "in vec4 v_" + std::to_string(i) + ";\n";
        sum += " + v_" + std::to_string(i);
    }
    std::string writes;
    for (int i = 0; i < 16; ++i) writes += "v_" + std::to_string(i) + " = u_big[" + std::to_string(i) + "];\n";
    dir.write("sh/big.vert", "// big\n#version 330 core\nuniform vec4 u_big[300];\nin vec3 a_position;\n" + outs +
                                 "void main() {\n" + writes + "gl_Position = vec4(a_position, 1.0) + u_big[299];\n}\n");
    std::string samplers, taps;
    for (int i = 0; i < 17; ++i) {
        samplers += "uniform sampler2D u_t" + std::to_string(i) + ";\n";
        taps += " + texture(u_t" + std::to_string(i) + ", vec2(0.5))";
    }
    dir.write("sh/big.frag", "// big\n#version 330 core\nprecision highp float;\nuniform vec4 u_many[225];\n" +
                                 samplers + ins + "out vec4 o_color;\nvoid main() { o_color = u_many[224] + " + sum +
                                 taps + "; }\n");
    dir.write("mods/.keep.glsl", "// nothing\n");
    EXPECT_EQ(runShaderc(scratchArgs(dir, "gl"), dir.str()).output, "");
    const auto run = runShaderc(scratchArgs(dir, "gl,es300"), dir.str());
    EXPECT_EQ(run.exitCode, 0) << run.output;
    for (const std::string expected :
         {"sh/big.vert: warning: es300: program 'big' uses 300 vertex uniform vectors "
          "(GL_MAX_VERTEX_UNIFORM_VECTORS), over the ES 3.00 minimum of 256",
          "sh/big.frag: warning: es300: program 'big' uses 225 fragment uniform vectors "
          "(GL_MAX_FRAGMENT_UNIFORM_VECTORS), over the ES 3.00 minimum of 224",
          "sh/big.vert: warning: es300: program 'big' uses 16 varying vectors (GL_MAX_VARYING_VECTORS), over the ES "
          "3.00 minimum of 15",
          "sh/big.frag: warning: es300: program 'big' uses 17 fragment texture units (GL_MAX_TEXTURE_IMAGE_UNITS), "
          "over the ES 3.00 minimum of 16"})
        EXPECT_NE(run.output.find(expected), std::string::npos) << expected << "\n" << run.output;
}

// Every program of the project's catalogues, every variant, validated and linked as ES 3.00
// by prism-shaderc; then each emitted es300 vert+frag pair again by the reference tool,
// glslangValidator -l (linking both stages as ES 3.00).
TEST(Targets, EveryEs300ProgramOfTheProjectValidatesAndLinks) {
    ScratchDir dir("targets-catalogue");
    const std::string m = kSource + "/modules", sh = kSource + "/shader_sources";
    const std::vector<std::pair<std::string, std::string>> catalogues = {
        {"", sh},
        {"rain", sh + "/rain"},
        {"diffraction", sh + "/diffraction"},
        {"bluenoise", sh + "/bluenoise"},
        {"water", sh + "/water"},  // its compute passes opt out of es300 (#pragma prism targets gl spirv)
    };
    int programs = 0;
    for (const auto& [name, inputs] : catalogues) {
        const std::string out = (dir.path() / (name.empty() ? "project" : name)).string();
        const std::string contract = name.empty() ? "" : " --contract " + m + "/" + name + "/contract.json";
        const auto run = runShaderc("--check --cache-dir none --target gl,es300 --emit-glsl " + out + " -I " + m +
                                        " --contract " + m + "/contract.json" + contract + " " + inputs,
                                    dir.str());
        ASSERT_EQ(run.exitCode, 0) << name << ":\n" << run.output;
        EXPECT_EQ(run.output, "") << name;
        for (const auto& entry : fs::directory_iterator(out)) {
            const std::string vert = entry.path().string();
            if (!vert.ends_with(".es300.vert")) continue;
            const std::string frag = vert.substr(0, vert.size() - 4) + "frag";
            EXPECT_EQ(prism::test::readFile(vert).rfind("#version 300 es\n", 0), 0u) << vert;
            const auto ref = runShell("glslangValidator -l -i '" + vert + "' '" + frag + "'");
            EXPECT_EQ(ref.exitCode, 0) << vert << "\n" << ref.output;
            // the check's own test: ReferenceCorpusChecks.SamplersLeftAtLowpNeedAPrecisionForTheirType
            EXPECT_EQ(prism::test::lowpLines(ref.output), "") << vert << " and its fragment stage compute at lowp";
            ++programs;
        }
    }
    EXPECT_GT(programs, 100) << "fewer es300 programs than the catalogues' variants";
}

TEST(GoldenTargets, PhongPerTarget) {
    ScratchDir dir("targets-golden");
    const auto run = runShaderc("--check --cache-dir none --base-dir " + kSource +
                                    " --variant 'phong:BLINN=1,FOG=1,DIRECTIONAL_LIGHTS=1,POINT_LIGHTS=1' --target "
                                    "gl,es300,spirv --emit-glsl out --emit-spirv out -I " +
                                    kSource + "/modules --contract " + kSource + "/modules/contract.json " + kSource +
                                    "/shader_sources/phong.vert " + kSource + "/shader_sources/phong.frag",
                                dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string base = "phong.BLINN-1_FOG-1_DIRECTIONAL_LIGHTS-1_POINT_LIGHTS-1.";
    for (const std::string file : {"gl.vert", "gl.frag", "es300.vert", "es300.frag"}) {
        SCOPED_TRACE(file);
        expectMatchesBaseline(prism::test::readFile(dir.path() / "out" / (base + file)), "targets/phong." + file);
    }
    // SPIR-V as the reference disassembler reads it (spirv-dis, no header comment: the
    // generator's version line would tie the baseline to a tool release).
    for (const std::string stage : {"vert", "frag"}) {
        SCOPED_TRACE(stage);
        const auto dis = runShell("spirv-dis --no-header --raw-id 'out/" + base + stage + ".spv'", dir.str());
        ASSERT_EQ(dis.exitCode, 0) << dis.output;
        expectMatchesBaseline(dis.output, "targets/phong.spirv." + stage + ".spvasm");
    }
}

// Every SPIR-V module of the project's catalogues, every variant (compute passes included):
// prism-shaderc runs SPIRV-Tools' validator on each; the reference tool, spirv-val, checks
// each written .spv again.
TEST(Targets, EverySpirvModuleOfTheProjectPassesTheValidator) {
    ScratchDir dir("targets-spirv");
    const std::string m = kSource + "/modules", sh = kSource + "/shader_sources";
    int modules = 0;
    for (const std::string name : {"", "rain", "diffraction", "bluenoise", "water"}) {
        const std::string out = (dir.path() / (name.empty() ? "project" : name)).string();
        const std::string contract = name.empty() ? "" : " --contract " + m + "/" + name + "/contract.json";
        const auto run = runShaderc("--check --cache-dir none --target gl,spirv --emit-spirv " + out + " -I " + m +
                                        " --contract " + m + "/contract.json" + contract + " " + sh + "/" + name,
                                    dir.str());
        ASSERT_EQ(run.exitCode, 0) << name << ":\n" << run.output;
        EXPECT_EQ(run.output, "") << name;
        std::string files;
        for (const auto& entry : fs::directory_iterator(out)) {
            files += " '" + entry.path().string() + "'";
            ++modules;
        }
        const auto ref = runShell("for f in" + files + "; do spirv-val --target-env vulkan1.1 \"$f\" || exit 1; done");
        EXPECT_EQ(ref.exitCode, 0) << name << "\n" << ref.output;
    }
    EXPECT_GT(modules, 200) << "fewer SPIR-V modules than the catalogues' stages";
}

// The data file keeps every target of a variant: the es300 text (its pieces shared with the
// gl text) and the SPIR-V words with their reflection, whose block layout agrees with the
// reference reflection (spirv-cross --reflect); the file compiles.
TEST(Targets, CatalogueStoresEveryTargetAndTheBlockLayoutMatchesTheReference) {
    ScratchDir dir("targets-data");
    const auto run =
        runShaderc("-o cat.hpp --cache-dir none --target gl,es300,spirv --emit-spirv spv --base-dir " + kSource +
                       " --variant 'phong:BLINN=1,FOG=0,DIRECTIONAL_LIGHTS=1,POINT_LIGHTS=1' -I " + kSource +
                       "/modules --contract " + kSource + "/modules/contract.json " + kSource +
                       "/shader_sources/phong.vert " + kSource + "/shader_sources/phong.frag",
                   dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const auto data = prism::test::readFile(dir.path() / "cat.cpp");
    EXPECT_NE(data.find("phong_v0_es300_stages,"), std::string::npos);
    EXPECT_NE(data.find("\n    0x07230203, "), std::string::npos) << "no SPIR-V magic number in the data file";
    const auto reflected = runShell(
        "spirv-cross spv/phong.BLINN-1_FOG-0_DIRECTIONAL_LIGHTS-1_POINT_LIGHTS-1.frag.spv --reflect", dir.str());
    ASSERT_EQ(reflected.exitCode, 0) << reflected.output;
    const std::regex member(
        R"re("name" : "(u_\w+)",\s*"type" : "\w+",\s*(?:"array" : \[[^\]]*\],\s*)?"offset" : (\d+))re");
    int members = 0;
    for (std::sregex_iterator it(reflected.output.begin(), reflected.output.end(), member), end; it != end; ++it) {
        const std::string row = "{\"" + (*it)[1].str() + "\", ";
        const auto at = data.find(row, data.find("phong_v0_resource0_members[]"));
        ASSERT_NE(at, std::string::npos) << row;
        EXPECT_NE(data.substr(at, data.find('}', at) - at).find(", " + (*it)[2].str() + ", "), std::string::npos)
            << data.substr(at, 60) << " vs spirv-cross offset " << (*it)[2];
        ++members;
    }
    EXPECT_GT(members, 5) << reflected.output;
    const std::smatch size = [&] {
        std::smatch m;
        std::regex_search(reflected.output, m, std::regex(R"("block_size" : (\d+))"));
        return m;
    }();
    EXPECT_NE(data.find("{\"gl_DefaultUniformBlock\", 0, 0, prism::catalog::ResourceKind::UniformBuffer, " +
                        size[1].str() + ", 1, phong_v0_resource0_members}"),
              std::string::npos);
    const auto compiled =
        runShell("c++ -std=c++20 -fsyntax-only -I " + kSource + "/foundation/catalog/include -I . cat.cpp", dir.str());
    EXPECT_EQ(compiled.exitCode, 0) << compiled.output;
}

// Two variants with one token stream (an axis the code never reads) are compiled once per
// target: the second takes the first's es300 verdict and SPIR-V, and the data file shares the
// words.
TEST(Targets, VariantsWithOneTokenStreamShareTheirTargets) {
    ScratchDir dir("targets-shared");
    dir.write("sh/plain.vert",
              "// plain\n#version 330 core\n#pragma prism variant QUALITY 1 2\nin vec3 a_position;\n"
              "uniform mat4 u_world;\nvoid main() { gl_Position = u_world * vec4(a_position, 1.0); }\n");
    dir.write("sh/plain.frag",
              "// plain\n#version 330 core\nuniform vec4 u_color;\nout vec4 o_color;\n"
              "void main() { o_color = u_color; }\n");
    dir.write("mods/.keep.glsl", "// nothing\n");
    const auto run = runShaderc("--stats -o p.hpp --cache-dir none --target gl,es300,spirv -I mods sh", dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("1 shared a token stream"), std::string::npos) << run.output;
    const auto data = prism::test::readFile(dir.path() / "p.cpp");
    const auto count = [&](const std::string& what) {
        std::size_t n = 0;
        for (auto at = data.find(what); at != std::string::npos; at = data.find(what, at + 1)) ++n;
        return n;
    };
    EXPECT_EQ(count("constexpr std::uint32_t "), 2u) << "one word array per distinct stage\n" << data;
    for (const std::string stage : {"vert", "frag"})
        EXPECT_EQ(count("plain_v0_" + stage + "_spirv}"), 2u) << "both variants' " << stage << " stages\n" << data;
    // Both variants' rows: their own es300 text (the defines differ), the first one's layout.
    for (const std::string quality : {"1", "2"}) {
        const auto at = data.find("{\"QUALITY=" + quality + "\"");
        ASSERT_NE(at, std::string::npos) << data;
        const std::string row = data.substr(at, data.find('\n', at) - at);
        EXPECT_NE(row.find("plain_v" + std::to_string(std::stoi(quality) - 1) + "_es300_stages"), std::string::npos)
            << row;
        EXPECT_NE(row.find("plain_v0_resources"), std::string::npos) << row;
    }
}

// glslang 12's automatic locations (the spirv target's relaxed rules) do not avoid the
// explicit ones of the same interface: a stage that mixes them can get two variables at one
// location. Prism says so at the declaration glslang placed, with a note at the explicit one,
// before SPIRV-Tools would reject the module without a line; gl, which links by name, takes
// it; a mix whose locations do not meet compiles for spirv too.
TEST(Targets, SpirvNamesTheDeclarationWhereAnAutomaticLocationCollides) {
    ScratchDir dir("targets-spirv-locations");
    const auto write = [&](int explicitLocation) {
        const std::string at = "layout(location = " + std::to_string(explicitLocation) + ") ";
        dir.write("sh/mix.vert", "// mix\n#version 420 core\nin vec3 a_position;\nout vec3 v_normal;\n" + at +
                                     "out vec3 v_extra;\nvoid main() { v_normal = a_position; v_extra = a_position; "
                                     "gl_Position = vec4(a_position, 1.0); }\n");
        dir.write("sh/mix.frag", "// mix\n#version 420 core\nin vec3 v_normal;\n" + at +
                                     "in vec3 v_extra;\nout vec4 o_color;\n"
                                     "void main() { o_color = vec4(v_normal + v_extra, 1.0); }\n");
    };
    dir.write("mods/.keep.glsl", "// nothing\n");
    write(0);
    EXPECT_EQ(runShaderc(scratchArgs(dir, "gl"), dir.str()).exitCode, 0);
    const auto run = runShaderc(scratchArgs(dir, "gl,spirv"), dir.str());
    EXPECT_EQ(run.exitCode, 1) << run.output;
    for (const std::string expected :
         {"sh/mix.vert:4:10: error: for target spirv, glslang puts the vert output 'v_normal' at location 0, which "
          "'v_extra' already takes",
          "sh/mix.vert:5:31: note: 'v_extra' is at location 0 here",
          "sh/mix.frag:3:9: error: for target spirv, glslang puts the frag input 'v_normal' at location 0",
          "give every input of this stage a layout(location), or none"})
        EXPECT_NE(run.output.find(expected), std::string::npos) << expected << "\n" << run.output;
    EXPECT_EQ(run.output.find("SPIRV-Tools rejected"), std::string::npos) << run.output;
    write(3);
    const auto apart = runShaderc(scratchArgs(dir, "gl,spirv"), dir.str());
    EXPECT_EQ(apart.exitCode, 0) << apart.output;
}
