// The catalogue prism_add_shaders(... PROGRAMS ...) generates (tests/shaderc/CMakeLists.txt):
// a tessellation folder's four stages, and declared programs whose names are not C++
// identifiers, with usable enumerators and name() giving the declared text back.
#include <gtest/gtest.h>

#include <vector>

#include "prism/test_programs.hpp"

namespace tp = prism::test_programs;
using prism::catalog::Stage;

// Compile-time: the mangled enumerators exist, and name() returns what was declared.
static_assert(tp::name(tp::ShaderId::_626c75722d68) == "blur-h");
static_assert(tp::name(tp::ShaderId::_31366269745f73746f72616765) == "16bit_storage");
static_assert(tp::shaderIdFromName("terrain") == tp::ShaderId::terrain);

namespace {

std::vector<Stage> stagesOf(tp::ShaderId id) {
    std::vector<Stage> stages;
    for (const auto& s : tp::shaderInfo(id).variants[0].stages) stages.push_back(s.stage);
    return stages;
}

}  // namespace

TEST(GeneratedPrograms, TessellationFolderRecordsAllFourStagesInPipelineOrder) {
    EXPECT_EQ(stagesOf(tp::ShaderId::terrain),
              (std::vector<Stage>{Stage::Vertex, Stage::TessControl, Stage::TessEvaluation, Stage::Fragment}));
}

TEST(GeneratedPrograms, DeclaredProgramsShareTheVertexStageInPipelineOrder) {
    const auto blur = tp::shaderIdFromName("blur-h");
    ASSERT_TRUE(blur.has_value());
    EXPECT_EQ(stagesOf(*blur), (std::vector<Stage>{Stage::Vertex, Stage::Fragment}));
    const auto& a = tp::shaderInfo(*blur).variants[0].stages[0];
    const auto& b = tp::shaderInfo(tp::ShaderId::_31366269745f73746f72616765).variants[0].stages[0];
    EXPECT_EQ(prism::catalog::joinChunks(a.chunks), prism::catalog::joinChunks(b.chunks));
    EXPECT_EQ(a.files[0].path, "tests/shaderc/fixtures/programs/shared/fullscreen.vert");
}
