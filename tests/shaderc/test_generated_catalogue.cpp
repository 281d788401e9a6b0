// The project's own generated catalogue (prism/shaders.hpp, built by the CMake step):
// it compiles, its name lookups are constexpr, and its embedded GLSL is driver-safe with
// line tables that name the modules.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <sstream>

#include "prism/shaders.hpp"
#include "tool_runner.hpp"

namespace shaders = prism::shaders;
using prism::catalog::joinChunks;

static_assert(shaders::kShaderCount >= 5);
static_assert(shaders::shaderIdFromName("phong") == shaders::ShaderId::phong);
static_assert(!shaders::shaderIdFromName("no_such_shader"));
static_assert(shaders::name(shaders::ModuleId::lights) == "lights");
static_assert(shaders::modulePath(shaders::ModuleId::lights) == "modules/lights.glsl");

TEST(GeneratedCatalogue, EveryStageStartsWithVersionAndHasNoIncludeExtensions) {
    for (const auto& s : shaders::kCatalog.shaders)
        for (const auto& v : s.variants)
            for (const auto& st : v.stages) {
                auto text = joinChunks(st.chunks);
                EXPECT_EQ(text.rfind("#version 330 core\n", 0), 0u) << s.name;
                EXPECT_EQ(text.find("#include"), std::string::npos) << s.name;
                EXPECT_EQ(text.find("GL_GOOGLE"), std::string::npos) << s.name;
                ASSERT_FALSE(st.files.empty());
                EXPECT_EQ(st.files[0].number, 0u);
                EXPECT_EQ(st.files[0].path.rfind("shader_sources/", 0), 0u) << st.files[0].path;
            }
}

TEST(GeneratedCatalogue, PhongHasTheBlinnVariantAndReflection) {
    const auto& phong = shaders::shaderInfo(shaders::ShaderId::phong);
    ASSERT_EQ(phong.axes.size(), 4u);
    EXPECT_EQ(phong.axes[0].name, "BLINN");
    EXPECT_EQ(phong.axes[1].name, "FOG");
    EXPECT_EQ(phong.axes[2].name, "DIRECTIONAL_LIGHTS");
    EXPECT_EQ(phong.axes[3].name, "POINT_LIGHTS");
    EXPECT_EQ(phong.variants.size(), 2u * 2u * 5u * 3u);
    const auto* blinn =
        prism::catalog::findVariant(phong, {{"BLINN", "1"}, {"DIRECTIONAL_LIGHTS", "2"}, {"POINT_LIGHTS", "1"}});
    ASSERT_NE(blinn, nullptr);
    EXPECT_EQ(blinn->name, "BLINN=1,FOG=0,DIRECTIONAL_LIGHTS=2,POINT_LIGHTS=1");
    EXPECT_NE(joinChunks(blinn->stages[1].chunks).find("#define BLINN 1"), std::string::npos);
    EXPECT_THROW(prism::catalog::findVariant(phong, {{"NOPE", "1"}}), prism::catalog::VariantLookupError);
    auto hasUniform = [&](std::string_view n) {
        return std::any_of(blinn->uniforms.begin(), blinn->uniforms.end(), [&](const auto& u) { return u.name == n; });
    };
    EXPECT_TRUE(hasUniform("u_shininess"));
    EXPECT_TRUE(hasUniform("u_normal"));
    EXPECT_FALSE(hasUniform("u_fogDensity"));  // FOG=0: no fog code, no fog uniforms
    const auto* foggy = prism::catalog::findVariant(phong, {{"BLINN", "1"}, {"FOG", "1"}, {"DIRECTIONAL_LIGHTS", "1"}});
    ASSERT_NE(foggy, nullptr);
    EXPECT_TRUE(std::any_of(foggy->uniforms.begin(), foggy->uniforms.end(),
                            [](const auto& u) { return u.name == "u_fogDensity"; }));
    ASSERT_EQ(blinn->attributes.size(), 2u);
    EXPECT_EQ(blinn->attributes[0].name, "a_position");
    EXPECT_EQ(blinn->attributes[0].location, 0);
}

TEST(GeneratedCatalogue, LightCountsBoundTheLoopsAndDropUnusedLights) {
    const auto& phong = shaders::shaderInfo(shaders::ShaderId::phong);
    const auto* one = prism::catalog::findVariant(phong, {{"DIRECTIONAL_LIGHTS", "1"}, {"POINT_LIGHTS", "0"}});
    ASSERT_NE(one, nullptr);
    const auto text = joinChunks(one->stages[1].chunks);
    EXPECT_NE(text.find("#define DIRECTIONAL_LIGHTS 1\n"), std::string::npos);
    for (const auto& u : one->uniforms) {
        EXPECT_NE(u.name, "u_pointLightColor") << "no point lights, no point-light uniforms";
        if (u.name == "u_lightDirection") {
            EXPECT_EQ(u.arraySize, 1);
        }
    }
}

TEST(GeneratedCatalogue, UnicolorUsesNoLightingModules) {
    const auto& s = shaders::shaderInfo(shaders::ShaderId::unicolor);
    for (auto m : s.modules) EXPECT_NE(static_cast<shaders::ModuleId>(m), shaders::ModuleId::lights);
}

TEST(GeneratedCatalogue, ModulesCarryDescriptionsAndDependencies) {
    const auto& lighting = shaders::moduleInfo(shaders::ModuleId::lighting);
    EXPECT_NE(lighting.description.find("shade()"), std::string_view::npos);
    std::vector<std::string_view> deps;
    for (auto d : lighting.dependencies) deps.push_back(shaders::name(static_cast<shaders::ModuleId>(d)));
    EXPECT_EQ(deps, (std::vector<std::string_view>{"lights", "material", "specular"}));
    auto text = joinChunks(lighting.chunks);
    EXPECT_EQ(text.find("#include"), std::string::npos);
}

TEST(GeneratedCatalogue, LineTablesMapSourceNumbersToModules) {
    const auto* v = prism::catalog::findVariant(shaders::shaderInfo(shaders::ShaderId::gouraud), {});
    ASSERT_NE(v, nullptr);
    const auto& vert = v->stages[0];
    auto text = joinChunks(vert.chunks);
    std::regex line(R"(#line \d+ (\d+))");
    for (std::sregex_iterator it(text.begin(), text.end(), line), end; it != end; ++it) {
        auto n = static_cast<std::uint32_t>(std::stoul((*it)[1]));
        EXPECT_NE(prism::catalog::findSourceFile(vert, n), nullptr) << n;
    }
    bool mentionsLights = false;
    for (const auto& f : vert.files) mentionsLights = mentionsLights || f.path == "modules/lights.glsl";
    EXPECT_TRUE(mentionsLights);
}

// The contract files the build step read, as it embeds paths (relative to the base dir), so
// that run-time contract errors can name them without the source tree.
TEST(GeneratedCatalogue, NamesItsContractFiles) {
    ASSERT_EQ(prism::shaders::kCatalog.contractFiles.size(), 1u);
    EXPECT_EQ(prism::shaders::kCatalog.contractFiles[0].path, "modules/contract.json");
    EXPECT_EQ(prism::shaders::kCatalog.contractFiles[0].searchDir, 0u);
}

// The one contract lookup the runtime uses (catalog::attributeLocation): the locations
// modules/contract.json declares, and a clear error for a name the runtime never provides.
TEST(GeneratedCatalogue, AttributeLocationsComeFromTheContract) {
    EXPECT_EQ(prism::catalog::attributeLocation(prism::shaders::kCatalog, "a_position"), 0);
    EXPECT_EQ(prism::catalog::attributeLocation(prism::shaders::kCatalog, "a_normal"), 1);
    try {
        prism::catalog::attributeLocation(prism::shaders::kCatalog, "a_normall");
        FAIL() << "a misspelled attribute got a location";
    } catch (const std::out_of_range& e) {
        EXPECT_NE(std::string(e.what()).find("'a_normall'"), std::string::npos) << e.what();
    }
}

// The data file stores each text piece once and a stage as a list of pieces (issue 10,
// item 2). Differential check: every stage the runtime assembles equals the flattened
// text prism-shaderc writes with --emit-glsl, which never goes through the pool.
TEST(GeneratedCatalogue, AssembledStagesEqualTheEmittedGlsl) {
    prism::test::ScratchDir dir("assembled");
    const std::string src = PRISM_SOURCE_DIR;
    auto run = prism::test::runShaderc("--emit-glsl glsl --base-dir " + src + " -I " + src + "/modules --contract " +
                                           src + "/modules/contract.json " + src + "/shader_sources",
                                       dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    int compared = 0;
    for (const auto& s : shaders::kCatalog.shaders)
        for (const auto& v : s.variants) {
            std::string base = std::string(s.name);
            if (s.variants.size() > 1 || !v.defines.empty()) {
                std::string suffix;
                for (const auto& d : v.defines)
                    suffix += (suffix.empty() ? "" : "_") + std::string(d.name) + "-" + std::string(d.value);
                base += "." + suffix;
            }
            for (const auto& st : v.stages) {
                const auto file = dir.path() / "glsl" / (base + "." + std::string(prism::catalog::stageName(st.stage)));
                ASSERT_TRUE(std::filesystem::exists(file)) << file;
                EXPECT_TRUE(joinChunks(st.chunks) == prism::test::readFile(file)) << file;
                ++compared;
            }
        }
    EXPECT_GT(compared, 100);
}

// A module's own text, assembled from shared pieces, is its file with the #include
// lines blanked (line numbers kept); a #version line stays (version.glsl's).
TEST(GeneratedCatalogue, ModuleTextIsItsFileWithIncludesBlanked) {
    const auto text = joinChunks(shaders::moduleInfo(shaders::ModuleId::lighting).chunks);
    std::istringstream file(prism::test::readFile(std::string(PRISM_SOURCE_DIR) + "/modules/lighting.glsl"));
    std::istringstream assembled(text);
    int lines = 0;
    for (std::string want, got; std::getline(file, want); ++lines) {
        ASSERT_TRUE(std::getline(assembled, got)) << "line " << lines + 1;
        if (want.rfind("#include", 0) == 0 || want.rfind("#pragma once", 0) == 0)
            EXPECT_EQ(got.find_first_not_of(" \t"), std::string::npos) << want;
        else
            EXPECT_EQ(got, want);
    }
    EXPECT_GT(lines, 10);
    EXPECT_NE(joinChunks(shaders::moduleInfo(shaders::ModuleId::version).chunks).find("\n#version 330 core\n"),
              std::string::npos);
}

// Issue 22, item 4: a misspelled axis or value is an error that names it and lists the
// known ones (before, findVariant returned nullptr and the docs' first snippet
// dereferenced it).
namespace {
// The message findVariant throws for `wanted`; "" when it throws nothing.
std::string lookupError(std::initializer_list<prism::catalog::Define> wanted) {
    try {
        prism::catalog::findVariant(shaders::shaderInfo(shaders::ShaderId::phong), wanted);
    } catch (const prism::catalog::VariantLookupError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(GeneratedCatalogue, UnknownVariantAxisNamesItAndListsTheAxes) {
    EXPECT_EQ(lookupError({{"DIRECTIONAL_LIGHT", "1"}}),
              "shader 'phong' has no variant axis 'DIRECTIONAL_LIGHT' (did you mean 'DIRECTIONAL_LIGHTS'?); its axes: "
              "BLINN, FOG, DIRECTIONAL_LIGHTS, POINT_LIGHTS");
}

TEST(GeneratedCatalogue, UnknownVariantValueNamesItAndListsTheValues) {
    EXPECT_EQ(lookupError({{"FOG", "2"}}), "variant axis 'FOG' of shader 'phong' has no value '2'; its values: 0, 1");
    EXPECT_EQ(lookupError({{"FOG", "1"}}), "");  // a declared value is no error
    // Pairs of strings go through the same check.
    const std::vector<std::pair<std::string, std::string>> pairs{{"BLINN", "yes"}};
    EXPECT_THROW(prism::catalog::findVariant(shaders::shaderInfo(shaders::ShaderId::phong), pairs),
                 prism::catalog::VariantLookupError);
}
