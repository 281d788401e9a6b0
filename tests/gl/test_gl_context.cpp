// Context creation on each backend, backend names, the PRISM_GL_BACKEND override and
// the errors for unusable requests.
#include <cstdlib>

#include "gl_test_support.hpp"

namespace {

using prism::gl::Backend;
using prism::gl::ContextError;

// Sets or unsets an environment variable for the scope of one test.
class ScopedEnv {
  public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old, hadOld_ = true;
        if (value)
            setenv(name, value, 1);
        else
            unsetenv(name);
    }
    ~ScopedEnv() {
        if (hadOld_)
            setenv(name_, old_.c_str(), 1);
        else
            unsetenv(name_);
    }

  private:
    const char* name_;
    std::string old_;
    bool hadOld_ = false;
};

void expectUsableCoreContext(const prism::gl::Context& ctx, Backend backend) {
    EXPECT_EQ(ctx.backend(), backend);
    EXPECT_TRUE(ctx.isCurrent());
    EXPECT_GE(ctx.info().major * 10 + ctx.info().minor, 33) << ctx.info().version;
    EXPECT_FALSE(ctx.info().renderer.empty());
    GLint profile = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT) << "profile mask " << profile;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(ContextNames, ParseAndPrint) {
    EXPECT_EQ(prism::gl::parseBackend("egl"), Backend::Egl);
    EXPECT_EQ(prism::gl::parseBackend("OSMesa"), Backend::OsMesa);
    EXPECT_EQ(prism::gl::parseBackend("glfw"), Backend::Glfw);
    EXPECT_EQ(prism::gl::parseBackend("Vulkan"), Backend::Vulkan);  // prism-render draws it through prism::vk
    EXPECT_EQ(prism::gl::parseBackend("metal"), std::nullopt);
    EXPECT_EQ(prism::gl::parseBackend(""), std::nullopt);
    for (Backend b : {Backend::Egl, Backend::OsMesa, Backend::Glfw, Backend::Vulkan})
        EXPECT_EQ(prism::gl::parseBackend(prism::gl::backendName(b)), b);
}

// Vulkan is a name a program reads to draw through prism::vk; it makes no GL context.
TEST(ContextNames, VulkanMakesNoGlContextAndSaysWhereItDraws) {
    try {
        prism::gl::createContext(Backend::Vulkan);
        FAIL() << "a GL context was made for the vulkan backend";
    } catch (const ContextError& e) {
        EXPECT_NE(std::string(e.what()).find("prism-render --backend vulkan"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(prism::gl::isBackendCompiledIn(Backend::Vulkan));
}

TEST(ContextNames, EnvironmentOverride) {
    {
        ScopedEnv env("PRISM_GL_BACKEND", nullptr);
        EXPECT_EQ(prism::gl::backendFromEnvironment(), std::nullopt);
    }
    {
        ScopedEnv env("PRISM_GL_BACKEND", "osmesa");
        EXPECT_EQ(prism::gl::backendFromEnvironment(), Backend::OsMesa);
    }
    {
        ScopedEnv env("PRISM_GL_BACKEND", "directx");
        try {
            prism::gl::backendFromEnvironment();
            FAIL() << "a bad PRISM_GL_BACKEND was accepted";
        } catch (const ContextError& e) {
            EXPECT_NE(std::string(e.what()).find("PRISM_GL_BACKEND='directx'"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("egl, osmesa, glfw or vulkan"), std::string::npos) << e.what();
        }
    }
}

TEST(EglContext, CreatesCurrentCoreContext) {
    ASSERT_TRUE(prism::gl::isBackendCompiledIn(Backend::Egl));
    auto ctx = prism::gl::createContext(Backend::Egl);
    expectUsableCoreContext(*ctx, Backend::Egl);
    EXPECT_EQ(ctx->drawableWidth(), 0);
}

// The device platform (EGL_EXT_platform_device) is what NVIDIA's EGL offers instead of
// Mesa's surfaceless one; Mesa lists a software device, so it is exercised here too.
TEST(EglContext, DevicePlatformRendersWhenAskedFor) {
    ScopedEnv env("PRISM_EGL_PLATFORM", "device");
    auto ctx = prism::gl::createContext(Backend::Egl);
    expectUsableCoreContext(*ctx, Backend::Egl);
    prism::gl::Framebuffer fb(4, 4);
    fb.clear({1.f, 0.f, 0.f, 1.f});
    EXPECT_EQ(fb.readImage8().at(1, 1), (prism::image::Rgba8{255, 0, 0, 255}));
}

TEST(EglContext, UnknownPlatformIsAnErrorNamingIt) {
    ScopedEnv env("PRISM_EGL_PLATFORM", "wayland");
    try {
        auto ctx = prism::gl::createContext(Backend::Egl);
        FAIL() << "a bad PRISM_EGL_PLATFORM was accepted";
    } catch (const ContextError& e) {
        EXPECT_NE(std::string(e.what()).find("PRISM_EGL_PLATFORM='wayland'"), std::string::npos) << e.what();
    }
}

TEST(OsMesaContext, CreatesCurrentCoreContext) {
    ASSERT_TRUE(prism::gl::isBackendCompiledIn(Backend::OsMesa));
    auto ctx = prism::gl::createContext(Backend::OsMesa, {.width = 32, .height = 16});
    expectUsableCoreContext(*ctx, Backend::OsMesa);
    EXPECT_EQ(ctx->drawableWidth(), 32);
    EXPECT_EQ(ctx->drawableHeight(), 16);
}

TEST(DefaultContext, IsEglUnlessOverridden) {
    {
        ScopedEnv env("PRISM_GL_BACKEND", nullptr);
        EXPECT_EQ(prism::gl::createContext()->backend(), Backend::Egl);
    }
    {
        ScopedEnv env("PRISM_GL_BACKEND", "osmesa");
        EXPECT_EQ(prism::gl::createContext()->backend(), Backend::OsMesa);
    }
}

TEST(ContextErrors, OldVersionIsRefusedWithReason) {
    try {
        prism::gl::createContext(Backend::Egl, {.majorVersion = 2, .minorVersion = 1});
        FAIL() << "GL 2.1 was accepted";
    } catch (const ContextError& e) {
        EXPECT_NE(std::string(e.what()).find("3.3+ core"), std::string::npos) << e.what();
    }
}

TEST(ContextErrors, UnsupportedVersionNamesTheBackend) {
    // llvmpipe stops at 4.5; 9.9 must fail with a message naming the backend.
    for (Backend b : {Backend::Egl, Backend::OsMesa}) {
        try {
            prism::gl::createContext(b, {.majorVersion = 9, .minorVersion = 9});
            ADD_FAILURE() << "GL 9.9 was accepted by " << prism::gl::backendName(b);
        } catch (const ContextError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(b == Backend::Egl ? "EGL" : "OSMesa"), std::string::npos) << what;
            EXPECT_NE(what.find("9.9"), std::string::npos) << what;
        }
    }
}

TEST(ContextSwitching, TwoBackendsInOneProcessEachRenderAfterMakeCurrent) {
    auto egl = prism::gl::createContext(Backend::Egl);
    auto osmesa = prism::gl::createContext(Backend::OsMesa);
    EXPECT_TRUE(osmesa->isCurrent());
    for (auto* ctx : {egl.get(), osmesa.get(), egl.get()}) {
        ctx->makeCurrent();
        prism::gl::Framebuffer fb(4, 4);
        fb.clear({0.f, 1.f, 0.f, 1.f});
        EXPECT_EQ(fb.readImage8().at(2, 2), (prism::image::Rgba8{0, 255, 0, 255}))
            << prism::gl::backendName(ctx->backend());
    }
}

TEST(ContextLifetime, EglCanBeCreatedAgainAfterTheLastOneIsDestroyed) {
    for (int round = 0; round < 3; ++round) {
        auto ctx = prism::gl::createContext(Backend::Egl);  // the display is terminated in between
        prism::gl::Framebuffer fb(4, 4);
        fb.clear({0.f, 0.f, 1.f, 1.f});
        EXPECT_EQ(fb.readImage8().at(0, 0), (prism::image::Rgba8{0, 0, 255, 255})) << "round " << round;
    }
}

// Without an X display the GLFW backend must say how to get one; with one (ctest
// runs this again under xvfb-run) it must give a working window context.
TEST(GlfwContext, WindowContextOrClearErrorWithoutDisplay) {
    if (!prism::gl::isBackendCompiledIn(Backend::Glfw)) GTEST_SKIP() << "built without GLFW";
    const char* display = std::getenv("DISPLAY");
    const bool requireDisplay = std::getenv("PRISM_REQUIRE_DISPLAY") != nullptr;
    if (!display || !*display) {
        ASSERT_FALSE(requireDisplay) << "PRISM_REQUIRE_DISPLAY is set but DISPLAY is not";
        try {
            prism::gl::createContext(Backend::Glfw);
            FAIL() << "GLFW created a window without a display";
        } catch (const ContextError& e) {
            EXPECT_NE(std::string(e.what()).find("xvfb-run"), std::string::npos) << e.what();
        }
        return;
    }
    auto ctx = prism::gl::createContext(Backend::Glfw, {.width = 40, .height = 30, .windowVisible = false});
    expectUsableCoreContext(*ctx, Backend::Glfw);
    EXPECT_NE(ctx->nativeWindow(), nullptr);
    EXPECT_EQ(ctx->drawableWidth(), 40);
    EXPECT_EQ(ctx->drawableHeight(), 30);
    prism::gl::Framebuffer fb(8, 8);
    fb.clear({1.f, 0.f, 0.f, 1.f});
    EXPECT_EQ(fb.readImage8().at(4, 4), (prism::image::Rgba8{255, 0, 0, 255}));
    ctx->swapBuffers();
}

}  // namespace
