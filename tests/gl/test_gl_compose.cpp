// Run-time composition: dependency order (a diamond pulled in once), source layout,
// errors mapped to module files, and rendering with the composed program.
#include <algorithm>
#include <iostream>

#include "gl_test_support.hpp"
#include "prism/test/gl_test.hpp"
#include "prism/gl/compose.hpp"
#include "prism/gl/module_library.hpp"
#include "prism/shaders.hpp"

namespace {

namespace cat = prism::catalog;
using prism::gl::ComposeStage;
using prism::gl::CompositionError;

// A diamond: top -> {left, right} -> base. Each module's text is a function
// returning its own share of the final colour.
inline constexpr std::string_view kBase[] = {"// base\nfloat baseValue() { return 0.25; }\n"};
inline constexpr std::string_view kLeft[] = {
    "// left: #include \"base.glsl\" blanked below\n\n"
    "float leftValue() { return baseValue(); }\n"};
inline constexpr std::string_view kRight[] = {"\nfloat rightValue() { return baseValue() * 2.0; }\n"};
inline constexpr std::string_view kTop[] = {"\n\nvec4 topColor() { return vec4(leftValue(), rightValue(), ",
                                            "0.0, 1.0); }\n"};  // two chunks
// Line 3 of faulty.glsl has a type error.
inline constexpr std::string_view kFaulty[] = {
    "// faulty\nfloat okay() { return 1.0; }\nfloat bad() { return vec3(1.0); }\n"};
inline constexpr std::string_view kLoopA[] = {"float a() { return 1.0; }\n"};
inline constexpr std::string_view kLoopB[] = {"float b() { return 1.0; }\n"};

inline constexpr std::uint32_t kOnBase[] = {0};
inline constexpr std::uint32_t kTopDeps[] = {1, 2};
inline constexpr std::uint32_t kLoopADeps[] = {6};
inline constexpr std::uint32_t kLoopBDeps[] = {5};

inline constexpr cat::Module kModules[] = {
    {"base", "modules/base.glsl", "", kBase, {}},               // 0
    {"left", "modules/left.glsl", "", kLeft, kOnBase},          // 1
    {"right", "modules/right.glsl", "", kRight, kOnBase},       // 2
    {"top", "modules/top.glsl", "", kTop, kTopDeps},            // 3
    {"faulty", "modules/faulty.glsl", "", kFaulty, {}},         // 4
    {"loop_a", "modules/loop_a.glsl", "", kLoopA, kLoopADeps},  // 5
    {"loop_b", "modules/loop_b.glsl", "", kLoopB, kLoopBDeps},  // 6
};

inline constexpr cat::Catalog kCatalog{{}, kModules, prism::test::kContractAttributes, {}, "#version 330 core"};
inline constexpr cat::Catalog kCatalog150{{}, kModules, prism::test::kContractAttributes, {}, "#version 150 core"};

const char* kVertexSource =
    "in vec2 a_position;\n"
    "void main() { gl_Position = vec4(a_position, 0.0, 1.0); }\n";
const char* kFragmentSource =
    "out vec4 fragColor;\n"
    "void main() { fragColor = topColor(); }\n";

std::size_t occurrences(const std::string& text, std::string_view what) {
    std::size_t n = 0;
    for (std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

TEST(ComposeOrder, DiamondIsPulledInOnceDependenciesFirst) {
    const std::uint32_t top[] = {3};
    EXPECT_EQ(prism::gl::moduleOrder(kCatalog, top), (std::vector<std::uint32_t>{0, 1, 2, 3}));
    // Stable: modules asked for come in the order asked, after their dependencies.
    const std::uint32_t rightThenTop[] = {2, 3};
    EXPECT_EQ(prism::gl::moduleOrder(kCatalog, rightThenTop), (std::vector<std::uint32_t>{0, 2, 1, 3}));
    const std::uint32_t repeated[] = {0, 3, 0, 1};
    EXPECT_EQ(prism::gl::moduleOrder(kCatalog, repeated), (std::vector<std::uint32_t>{0, 1, 2, 3}));
}

TEST(ComposeOrder, CycleAndUnknownIdAreErrors) {
    const std::uint32_t loop[] = {5};
    try {
        prism::gl::moduleOrder(kCatalog, loop);
        FAIL() << "a dependency cycle was accepted";
    } catch (const CompositionError& e) {
        // The build step's message, at the module that closes the cycle (it once was a bare
        // "module dependency cycle: loop_a -> loop_b -> loop_a" with no file and no hint).
        ASSERT_EQ(e.diagnostics.size(), 1u) << e.what();
        EXPECT_EQ(e.diagnostics.front(),
                  "modules/loop_b.glsl: error: include cycle: modules/loop_a.glsl -> modules/loop_b.glsl -> "
                  "modules/loop_a.glsl; add an include guard or #pragma once, or break the cycle\n")
            << e.what();
    }
    const std::uint32_t unknown[] = {42};
    try {
        prism::gl::moduleOrder(kCatalog, unknown);
        FAIL() << "module id 42 was accepted";
    } catch (const CompositionError& e) {
        EXPECT_NE(std::string(e.what()).find("module id 42"), std::string::npos) << e.what();
    }
}

TEST(ComposeLayout, OneVersionLineLineDirectivesAndFilesTable) {
    const ComposeStage stage{cat::Stage::Fragment, {3}, kFragmentSource, "app/custom.frag"};
    const cat::Define defines[] = {{"QUALITY", "2"}};
    const prism::gl::StageText text = prism::gl::composeStage(kCatalog, stage, defines);
    EXPECT_EQ(text.source.rfind("#version 330 core\n#define QUALITY 2\n#line 1 1\n// base\n", 0), 0u) << text.source;
    EXPECT_EQ(occurrences(text.source, "#version"), 1u);
    EXPECT_EQ(occurrences(text.source, "float baseValue()"), 1u) << text.source;
    EXPECT_NE(text.source.find("#line 1 4\n\n\nvec4 topColor() { return vec4(leftValue(), rightValue(), 0.0, 1.0); }\n"
                               "#line 1 0\nout vec4 fragColor;\n"),
              std::string::npos)
        << text.source;
    ASSERT_EQ(text.files.size(), 5u);
    EXPECT_EQ(text.files[0].number, 0u);
    EXPECT_EQ(text.files[0].path, "app/custom.frag");
    EXPECT_EQ(text.files[1].path, "modules/base.glsl");
    EXPECT_EQ(text.files[2].path, "modules/left.glsl");
    EXPECT_EQ(text.files[3].path, "modules/right.glsl");
    EXPECT_EQ(text.files[4].path, "modules/top.glsl");
}

// The `#line` rule is prism/catalog/line_directive.hpp's: GLSL ES (any version) and GLSL
// 3.30+ name the next line N, older GLSL N + 1, so every file still starts at its line 1.
TEST(ComposeLayout, LineDirectivesFollowTheVersionsRule) {
    const ComposeStage stage{cat::Stage::Fragment, {0}, kFragmentSource, "app/custom.frag"};
    cat::Catalog es = kCatalog;
    es.versionDirective = "#version 300 es";
    const auto esText = prism::gl::composeStage(es, stage);
    EXPECT_EQ(esText.source.rfind("#version 300 es\n#line 1 1\n// base\n", 0), 0u) << esText.source;
    EXPECT_NE(esText.source.find("#line 1 0\n"), std::string::npos) << esText.source;
    cat::Catalog old = kCatalog;
    old.versionDirective = "#version 150";
    const auto oldText = prism::gl::composeStage(old, stage);
    EXPECT_EQ(oldText.source.rfind("#version 150\n#line 0 1\n// base\n", 0), 0u) << oldText.source;
    EXPECT_NE(oldText.source.find("#line 0 0\n"), std::string::npos) << oldText.source;
}

// The user's source is read as the build step reads a stage file: its #version is kept
// (it once was replaced by the catalogue's, hiding a stage that needs 450), and its
// #include lines are found in the build step's search order and join the modules.
TEST(ComposeLayout, UserVersionLineIsKept) {
    const ComposeStage withVersion{cat::Stage::Fragment, {0}, "#version 450\nvoid f() {}\n", "u.frag"};
    const auto text = prism::gl::composeStage(kCatalog, withVersion);
    EXPECT_EQ(text.source.rfind("#version 450\n#line 1 1\n// base\n", 0), 0u) << text.source;
    EXPECT_EQ(occurrences(text.source, "#version"), 1u);
    EXPECT_NE(text.source.find("#line 1 0\n\nvoid f() {}\n"), std::string::npos) << text.source;
}

TEST(ComposeLayout, UserIncludeJoinsTheModules) {
    const ComposeStage withInclude{cat::Stage::Fragment, {}, "void f() {}\n  #include \"top.glsl\"\n", "app/u.frag"};
    const auto text = prism::gl::composeStage(kCatalog, withInclude);
    ASSERT_EQ(text.files.size(), 5u) << text.source;  // top and its dependencies, first
    EXPECT_EQ(text.files[4].path, "modules/top.glsl");
    EXPECT_NE(text.source.find("#line 1 0\nvoid f() {}\n\n"), std::string::npos) << text.source;
    EXPECT_EQ(text.source.find("#include", text.source.find("#line 1 0")), std::string::npos) << text.source;
}

TEST(ComposeLayout, MissingUserIncludeIsTheBuildStepsError) {
    const ComposeStage withInclude{cat::Stage::Fragment, {}, "void f() {}\n  #include \"lights.glsl\"\n", "u.frag"};
    try {
        prism::gl::composeStage(kCatalog, withInclude);
        FAIL() << "an #include of no module was accepted";
    } catch (const CompositionError& e) {
        ASSERT_FALSE(e.diagnostics.empty()) << e.what();
        EXPECT_EQ(e.diagnostics.front().rfind("u.frag:2:12: error: ", 0), 0u) << e.what();
        EXPECT_NE(e.diagnostics.front().find("lights.glsl"), std::string::npos) << e.what();
    }
}

class ComposeGl : public prism::test::GlTest {};

TEST_F(ComposeGl, ComposedDiamondRenders) {
    const ComposeStage stages[] = {{cat::Stage::Vertex, {}, kVertexSource, ""},
                                   {cat::Stage::Fragment, {3}, kFragmentSource, ""}};
    prism::gl::Program program = prism::gl::composeProgram(kCatalog, stages, "diamond");
    EXPECT_EQ(glGetAttribLocation(program.id(), "a_position"), 0);  // contract binding applied
    prism::gl::Framebuffer fb(prism::test::kSize, prism::test::kSize);
    prism::test::drawTriangle(fb, program);
    EXPECT_EQ(fb.readImage8().at(prism::test::kSize / 2, prism::test::kSize / 2),
              (prism::image::Rgba8{64, 128, 0, 255}));
}

// Both the #line semantics of the driver and the files table are checked here: an
// off-by-one in either moves the reported line away from 3.
TEST_F(ComposeGl, ErrorInModuleMapsToModulePathAndLine) {
    for (const cat::Catalog* catalog : {&kCatalog, &kCatalog150}) {
        const ComposeStage stages[] = {{cat::Stage::Vertex, {}, kVertexSource, ""},
                                       {cat::Stage::Fragment, {3, 4}, kFragmentSource, ""}};
        try {
            prism::gl::composeProgram(*catalog, stages, "faulty");
            ADD_FAILURE() << "the faulty module compiled under " << catalog->versionDirective;
        } catch (const CompositionError& e) {
            // Found by the build step's glslang check, before the driver sees it.
            ASSERT_FALSE(e.diagnostics.empty()) << e.what();
            EXPECT_NE(e.diagnostics.front().find("modules/faulty.glsl:3:"), std::string::npos)
                << catalog->versionDirective << "\n"
                << e.what();
        }
    }
}

TEST_F(ComposeGl, ErrorInUserCodeMapsToUserName) {
    const ComposeStage stages[] = {
        {cat::Stage::Vertex, {}, kVertexSource, ""},
        {cat::Stage::Fragment, {3}, "out vec4 fragColor;\n\nvoid main() { fragColor = nope(); }\n", "app/mine.frag"}};
    try {
        prism::gl::composeProgram(kCatalog, stages, "mine");
        FAIL() << "user code calling an undefined function compiled";
    } catch (const CompositionError& e) {
        EXPECT_NE(std::string(e.what()).find("app/mine.frag:3:27: error: 'nope'"), std::string::npos) << e.what();
    }
}

// The checks of the build step run at composition: a misspelled contract attribute in a
// module is an error at the module's file and line, with the contract's name suggested.
inline constexpr std::string_view kMisspelled[] = {
    "// misspelled attribute\n"
    "in vec2 a_positon;\n"
    "vec4 misspelledPosition() { return vec4(a_positon, 0.0, 1.0); }\n"};
inline constexpr cat::Module kMisspelledModules[] = {{"misspelled", "lib/misspelled.glsl", "", kMisspelled, {}}};
inline constexpr cat::Catalog kMisspelledCatalog{
    {}, kMisspelledModules, prism::test::kContractAttributes, {}, "#version 330 core"};

TEST_F(ComposeGl, MisspelledAttributeIsAnErrorAtTheModuleLineWithASuggestion) {
    const ComposeStage stages[] = {
        {cat::Stage::Vertex, {0}, "void main() { gl_Position = misspelledPosition(); }\n", "app/misspelled.vert"},
        {cat::Stage::Fragment, {}, "out vec4 fragColor;\nvoid main() { fragColor = vec4(1.0); }\n", "app/plain.frag"}};
    try {
        prism::gl::composeProgram(kMisspelledCatalog, stages, "misspelled");
        FAIL() << "a_positon, which the runtime never provides, linked silently";
    } catch (const CompositionError& e) {
        const std::string what = e.what();
        std::cout << what << "\n";  // docs/runtime.md quotes this diagnostic
        EXPECT_NE(what.find("lib/misspelled.glsl:2:"), std::string::npos) << what;
        EXPECT_NE(what.find("a_positon"), std::string::npos) << what;
        EXPECT_NE(what.find("did you mean 'a_position'"), std::string::npos) << what;
    }
}

// A generated catalogue records its contract files (Catalog::contractFiles): a contract
// error names them without the source tree.
TEST_F(ComposeGl, ContractErrorNamesTheGeneratedCataloguesContractFiles) {
    const ComposeStage stages[] = {
        {cat::Stage::Vertex,
         {},
         "in vec3 a_positon;\nvoid main() { gl_Position = vec4(a_positon, 1.0); }\n",
         "app/misspelled.vert"},
        {cat::Stage::Fragment, {}, "out vec4 fragColor;\nvoid main() { fragColor = vec4(1.0); }\n", "app/plain.frag"}};
    try {
        prism::gl::composeProgram(prism::shaders::kCatalog, stages, "misspelled");
        FAIL() << "a_positon, which the runtime never provides, linked silently";
    } catch (const CompositionError& e) {
        ASSERT_FALSE(e.diagnostics.empty()) << e.what();
        EXPECT_NE(e.diagnostics.front().find("app/misspelled.vert:1:9: error: vertex attribute 'a_positon' is not in "
                                             "the binding contract (modules/contract.json)"),
                  std::string::npos)
            << e.what();
    }
}

// With the source tree recorded beside a catalogue, a contract error names the contract
// files as absolute paths (this hand-written catalogue records none itself).
TEST_F(ComposeGl, ContractErrorNamesTheSourceTreesContractFiles) {
    const std::string_view contracts[] = {"modules/contract.json"};
    const cat::SourceTree tree{"test", "", {}, contracts, {}};
    const ComposeStage stages[] = {
        {cat::Stage::Vertex, {0}, "void main() { gl_Position = misspelledPosition(); }\n", "app/misspelled.vert"},
        {cat::Stage::Fragment, {}, "out vec4 fragColor;\nvoid main() { fragColor = vec4(1.0); }\n", "app/plain.frag"}};
    try {
        prism::gl::composeProgram(kMisspelledCatalog, tree, stages, "misspelled");
        FAIL() << "a_positon, which the runtime never provides, linked silently";
    } catch (const CompositionError& e) {
        ASSERT_FALSE(e.diagnostics.empty()) << e.what();
        EXPECT_NE(e.diagnostics.front().find("not in the binding contract (modules/contract.json)"), std::string::npos)
            << e.what();
    }
}

// A varying declared vec3 in one stage and vec4 in the next names both stages.
TEST_F(ComposeGl, VaryingTypeMismatchNamesBothStages) {
    const ComposeStage stages[] = {{cat::Stage::Vertex,
                                    {},
                                    "in vec2 a_position;\nout vec3 v_tint;\n"
                                    "void main() { v_tint = vec3(1.0); gl_Position = vec4(a_position, 0.0, 1.0); }\n",
                                    "app/tint.vert"},
                                   {cat::Stage::Fragment,
                                    {},
                                    "in vec4 v_tint;\nout vec4 fragColor;\nvoid main() { fragColor = v_tint; }\n",
                                    "app/tint.frag"}};
    try {
        prism::gl::composeProgram(kCatalog, stages, "tint");
        FAIL() << "a vec3/vec4 varying mismatch composed";
    } catch (const CompositionError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("app/tint.frag:1:"), std::string::npos) << what;
        EXPECT_NE(what.find("v_tint"), std::string::npos) << what;
        EXPECT_NE(what.find("vert output"), std::string::npos) << what;
        EXPECT_NE(what.find("vec3"), std::string::npos) << what;
        EXPECT_NE(what.find("vec4"), std::string::npos) << what;
    }
}

}  // namespace

namespace {

// Composition with no generated catalogue: modules and the contract read at run time by the
// tool's own stages. tint.glsl includes halve.glsl, which must come first.
const char* kLibraryContract = R"({"attributes": [{"name": "a_position", "type": "vec2", "location": 0}],
  "uniforms": [{"name": "u_gain", "type": "float"}]})";

TEST_F(ComposeGl, ModuleLibraryFromStringsComposesAndRenders) {
    const auto library = prism::gl::ModuleLibrary::fromStrings(
        {{"lib/halve.glsl", "// Provides halve().\nfloat halve(float x) { return 0.5 * x; }\n"},
         {"lib/tint.glsl",
          "// Provides tint().\n#include \"halve.glsl\"\nuniform float u_gain;\n"
          "vec4 tint() { return vec4(halve(u_gain), 1.0, 0.0, 1.0); }\n"}},
        kLibraryContract);
    EXPECT_EQ(library.catalog().modules[library.id("tint")].description, "Provides tint().");
    const ComposeStage stages[] = {{cat::Stage::Vertex, {}, kVertexSource, "app/lib.vert"},
                                   {cat::Stage::Fragment,
                                    {library.id("tint")},
                                    "out vec4 fragColor;\nvoid main() { fragColor = tint(); }\n",
                                    "app/lib.frag"}};
    prism::gl::Program program = prism::gl::composeProgram(library, stages, "library");
    program.set("u_gain", 1.0f);
    prism::gl::Framebuffer fb(prism::test::kSize, prism::test::kSize);
    prism::test::drawTriangle(fb, program);
    EXPECT_EQ(fb.readImage8().at(prism::test::kSize / 2, prism::test::kSize / 2),
              (prism::image::Rgba8{128, 255, 0, 255}));
}

TEST_F(ComposeGl, ModuleLibraryUniformOutsideTheContractIsAnError) {
    const auto library = prism::gl::ModuleLibrary::fromStrings(
        {{"lib/gain.glsl", "// gain\nuniform float u_gian;\nfloat gain() { return u_gian; }\n"}}, kLibraryContract);
    const ComposeStage stages[] = {{cat::Stage::Vertex, {}, kVertexSource, "app/lib.vert"},
                                   {cat::Stage::Fragment,
                                    {library.id("gain")},
                                    "out vec4 fragColor;\nvoid main() { fragColor = vec4(gain()); }\n",
                                    "app/lib.frag"}};
    try {
        prism::gl::composeProgram(library, stages, "gain");
        FAIL() << "u_gian, which the runtime never provides, composed";
    } catch (const CompositionError& e) {
        EXPECT_NE(std::string(e.what()).find("lib/gain.glsl:2:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("did you mean 'u_gain'"), std::string::npos) << e.what();
    }
}

TEST(ModuleLibrary, ErrorsNameTheFileAndLine) {
    try {
        prism::gl::ModuleLibrary::fromStrings({{"lib/a.glsl", "// a\n\n#include \"missing.glsl\"\n"}},
                                              kLibraryContract);
        FAIL() << "a missing include was accepted";
    } catch (const CompositionError& e) {
        EXPECT_NE(std::string(e.what()).find("lib/a.glsl:3:"), std::string::npos) << e.what();
    }
    try {
        prism::gl::ModuleLibrary::fromStrings({}, "{\"attributes\": [}");
        FAIL() << "malformed contract JSON was accepted";
    } catch (const CompositionError& e) {
        EXPECT_NE(std::string(e.what()).find("<contract>.json:1:"), std::string::npos) << e.what();
    }
    const auto library = prism::gl::ModuleLibrary::fromStrings({{"lib/tint.glsl", "// t\n"}}, kLibraryContract);
    try {
        library.id("tnit");
        FAIL() << "an unknown module name was accepted";
    } catch (const CompositionError& e) {
        EXPECT_NE(std::string(e.what()).find("did you mean 'tint'"), std::string::npos) << e.what();
    }
}

// Module ids are the build step's: the path under the include directory, mangled (they
// once were the file's stem, so toon/quantize.glsl was "quantize").
TEST(ModuleLibrary, IdsAreTheBuildSteps) {
    const std::string includeDirs[] = {"modules"};
    const auto library = prism::gl::ModuleLibrary::fromStrings(
        {{"modules/toon/quantize.glsl", "// q\nfloat quantize(float x) { return floor(x); }\n"},
         {"modules/plain.glsl", "// p\n"}},
        kLibraryContract, "#version 330 core", includeDirs);
    EXPECT_EQ(library.catalog().modules[library.id("toon__quantize")].path, "modules/toon/quantize.glsl");
    EXPECT_EQ(library.catalog().modules[library.id("plain")].path, "modules/plain.glsl");
    EXPECT_THROW(library.id("quantize"), CompositionError);
}

// Without include directories each file's folder is its root: two util.glsl are one id.
TEST(ModuleLibrary, TwoFilesWithOneIdAreAnErrorNamingBoth) {
    try {
        prism::gl::ModuleLibrary::fromStrings({{"a/util.glsl", "// a\n"}, {"b/util.glsl", "// b\n"}}, kLibraryContract);
        FAIL() << "a/util.glsl and b/util.glsl both loaded as 'util'";
    } catch (const CompositionError& e) {
        ASSERT_EQ(e.diagnostics.size(), 1u) << e.what();
        EXPECT_EQ(e.diagnostics.front().rfind("b/util.glsl: error: module id 'util' is also a/util.glsl's", 0), 0u)
            << e.what();
    }
}

// A cycle is the build step's error: at the #include that closes it, with the chain and
// the guard hint (it once was "module dependency cycle: cyc_a -> cyc_b -> cyc_a").
TEST(ModuleLibrary, IncludeCycleIsTheBuildStepsError) {
    try {
        prism::gl::ModuleLibrary::fromStrings(
            {{"lib/cyc_a.glsl", "#include \"cyc_b.glsl\"\n"}, {"lib/cyc_b.glsl", "// b\n#include \"cyc_a.glsl\"\n"}},
            kLibraryContract);
        FAIL() << "an include cycle loaded";
    } catch (const CompositionError& e) {
        ASSERT_FALSE(e.diagnostics.empty()) << e.what();
        EXPECT_EQ(e.diagnostics.front().rfind("lib/cyc_b.glsl:2:10: error: include cycle: lib/cyc_a.glsl -> "
                                              "lib/cyc_b.glsl -> lib/cyc_a.glsl; add an include guard",
                                              0),
                  0u)
            << e.what();
    }
}

TEST_F(ComposeGl, ModuleLibraryFromPrismsOwnModuleFiles) {
    const std::string modules = PRISM_SOURCE_DIR "/modules/";
    const std::string files[] = {modules + "version.glsl", modules + "math_utils.glsl", modules + "transforms.glsl"};
    const std::string contracts[] = {modules + "contract.json"};
    const auto library = prism::gl::ModuleLibrary::fromFiles(files, contracts);
    EXPECT_EQ(library.catalog().modules.size(), 3u);
    EXPECT_FALSE(library.catalog().contractUniforms.empty());
    EXPECT_NE(library.catalog().modules[library.id("transforms")].description.find("u_"), std::string_view::npos);
}

}  // namespace
