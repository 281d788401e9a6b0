// prism-render --backend vulkan: a catalogue render, the choice through PRISM_GL_BACKEND as
// through --backend, a classic scene, the soft shadows, and scenes whose systems have no Vulkan
// path refused (exit 2) by name (the diffraction scenes are drawn by test_vk_agreement.cpp).
#include <gtest/gtest.h>

#include <filesystem>

#include "prism/test/run_command.hpp"

namespace {

namespace fs = std::filesystem;

std::string outPng(const std::string& name) {
    fs::create_directories(PRISM_VULKAN_OUT "/cli");
    const fs::path p = fs::path(PRISM_VULKAN_OUT "/cli") / name;
    fs::remove(p);
    return p.string();
}

std::string scene(const std::string& name) {
    return std::string(PRISM_SCENES_DIR) + "/" + name + ".json";
}

TEST(VulkanRenderCli, DrawsACatalogueShaderThroughVulkan) {
    const std::string out = outPng("phong-torus.png");
    const auto r = prism::test::runCommand({PRISM_RENDER_EXECUTABLE, "--backend", "vulkan", "--shader", "phong",
                                            "--mesh", "torus", "--size", "64x64", "--out", out});
    EXPECT_EQ(r.exitCode, 0) << r;
    EXPECT_NE(r.out.find("(vulkan on "), std::string::npos) << r;
    EXPECT_TRUE(fs::exists(out));
}

// createContext's environment variable chooses Vulkan the same way as --backend.
TEST(VulkanRenderCli, TheEnvironmentVariableChoosesVulkanToo) {
    const std::string out = outPng("env.png");
    const auto r = prism::test::runCommand({"/usr/bin/env", "PRISM_GL_BACKEND=vulkan", PRISM_RENDER_EXECUTABLE,
                                            "--shader", "flat", "--size", "32x32", "--out", out});
    EXPECT_EQ(r.exitCode, 0) << r;
    EXPECT_NE(r.out.find("(vulkan on "), std::string::npos) << r;
}

TEST(VulkanRenderCli, AClassicSceneDrawsThroughVulkan) {
    const std::string out = outPng("four_lights.png");
    const auto r = prism::test::runCommand({PRISM_RENDER_EXECUTABLE, "--backend", "vulkan", "--scene",
                                            scene("four_lights"), "--size", "64x48", "--out", out});
    EXPECT_EQ(r.exitCode, 0) << r;
    EXPECT_NE(r.out.find("3 draws, 2 pipelines"), std::string::npos) << r;
}

// The soft shadows go through Vulkan with --backend vulkan, and a GL backend is still refused.
TEST(VulkanRenderCli, TheSoftShadowSceneDrawsThroughVulkanOnly) {
    const std::string out = outPng("soft_shadows.png");
    const auto r = prism::test::runCommand({PRISM_RENDER_EXECUTABLE, "--backend", "vulkan", "--scene",
                                            scene("soft_shadows"), "--frames", "2", "--out", out});
    EXPECT_EQ(r.exitCode, 0) << r;
    EXPECT_NE(r.out.find("through vulkan, bluenoise, 1 spp, mean of frames 0..1"), std::string::npos) << r;
    EXPECT_TRUE(fs::exists(out));
    const std::string refused = outPng("soft_shadows_egl.png");
    const auto egl = prism::test::runCommand(
        {PRISM_RENDER_EXECUTABLE, "--backend", "egl", "--scene", scene("soft_shadows"), "--out", refused});
    EXPECT_EQ(egl.exitCode, 2) << egl;
    EXPECT_NE(egl.err.find("or through --backend vulkan"), std::string::npos) << egl;
    EXPECT_FALSE(fs::exists(refused));
}

// Each scene's system without a Vulkan path is named; nothing is written.
TEST(VulkanRenderCli, ScenesWithAGlOnlySystemExit2NamingIt) {
    const std::pair<const char*, const char*> cases[] = {
        {"fog", "fog billboards"},
        {"rain", "the rain system"},
        {"water", "the water system"},
    };
    for (const auto& [name, system] : cases) {
        const std::string out = outPng(std::string(name) + ".png");
        const auto r = prism::test::runCommand(
            {PRISM_RENDER_EXECUTABLE, "--backend", "vulkan", "--scene", scene(name), "--out", out});
        EXPECT_EQ(r.exitCode, 2) << r;
        EXPECT_NE(r.err.find(system), std::string::npos) << r;
        EXPECT_FALSE(fs::exists(out)) << name;
    }
}

TEST(VulkanRenderCli, RefusesWhatVulkanDoesNotDo) {
    const auto finite = prism::test::runCommand(
        {PRISM_RENDER_EXECUTABLE, "--backend", "vulkan", "--shader", "phong", "--check-finite"});
    EXPECT_EQ(finite.exitCode, 2) << finite;
    EXPECT_NE(finite.err.find("--check-finite"), std::string::npos) << finite;
    const auto unknown = prism::test::runCommand(
        {PRISM_RENDER_EXECUTABLE, "--backend", "metal", "--shader", "phong", "--out", outPng("metal.png")});
    EXPECT_EQ(unknown.exitCode, 2) << unknown;
    EXPECT_NE(unknown.err.find("expected egl, osmesa or vulkan"), std::string::npos) << unknown;
}

}  // namespace
