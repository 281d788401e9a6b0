// Run-time composition: dependency order (a diamond pulled in once), source layout,
// errors mapped to module files, and rendering with the composed program.
#include <algorithm>

#include "gl_test_support.hpp"
#include "prism/gl/compose.hpp"

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
        EXPECT_NE(std::string(e.what()).find("loop_a -> loop_b -> loop_a"), std::string::npos) << e.what();
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

TEST(ComposeLayout, UserVersionLineIsBlankedAndIncludeRefused) {
    const ComposeStage withVersion{cat::Stage::Fragment, {}, "#version 450\nvoid f() {}\n", "u.frag"};
    const auto text = prism::gl::composeStage(kCatalog, withVersion);
    EXPECT_EQ(occurrences(text.source, "#version"), 1u);
    EXPECT_NE(text.source.find("#line 1 0\n\nvoid f() {}\n"), std::string::npos) << text.source;

    const ComposeStage withInclude{cat::Stage::Fragment, {}, "void f() {}\n  #include \"lights.glsl\"\n", "u.frag"};
    try {
        prism::gl::composeStage(kCatalog, withInclude);
        FAIL() << "#include in user code was accepted";
    } catch (const CompositionError& e) {
        EXPECT_NE(std::string(e.what()).find("u.frag:2: #include"), std::string::npos) << e.what();
    }
}

class ComposeGl : public ::testing::Test {
  protected:
    void SetUp() override { ctx_ = prism::gl::createContext(prism::gl::Backend::Egl); }
    std::unique_ptr<prism::gl::Context> ctx_;
};

TEST_F(ComposeGl, ComposedDiamondRenders) {
    const ComposeStage stages[] = {{cat::Stage::Vertex, {}, kVertexSource, ""},
                                   {cat::Stage::Fragment, {3}, kFragmentSource, ""}};
    prism::gl::Program program = prism::gl::composeProgram(kCatalog, stages, "diamond");
    EXPECT_EQ(glGetAttribLocation(program.id(), "a_position"), 0);  // contract binding applied
    prism::gl::Framebuffer fb(prism::test::kSize, prism::test::kSize);
    prism::test::drawTriangle(fb, program);
    EXPECT_EQ(fb.readImage8().at(prism::test::kSize / 2, prism::test::kSize / 2), (prism::image::Rgba8{64, 128, 0, 255}));
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
        } catch (const prism::gl::ShaderBuildError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("modules/faulty.glsl:3:"), std::string::npos) << catalog->versionDirective << "\n"
                                                                              << what;
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
    } catch (const prism::gl::ShaderBuildError& e) {
        EXPECT_NE(std::string(e.what()).find("app/mine.frag:3:"), std::string::npos) << e.what();
    }
}

}  // namespace
