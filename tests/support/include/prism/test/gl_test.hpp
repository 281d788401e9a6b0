// The one base of every GL-tier test (tests/README.md). A suite derived from GlTest gets
// one GL 4.3 core context (Mesa llvmpipe through EGL surfaceless unless PRISM_GL_BACKEND
// says otherwise), created when the suite starts and made current before each test. A
// test without it FAILS, never skips: a GL tier that silently skipped would hide a broken
// headless setup. 4.3 for everyone, because rain and water need its compute shaders.
//
// Objects that need the context and are costly to rebuild per test (program caches) come
// from suiteResource<T>(): made on first use, deleted before the context, newest first.
// A suite that must run on one backend whatever PRISM_GL_BACKEND says derives from
// GlTestOn<backend> instead (a typed suite over backends runs its tests on each).
//
//     #include "prism/test/gl_test.hpp"
//
//     class Draws : public prism::test::GlTest {};
//
//     TEST_F(Draws, WithTheSuitesPrograms) {
//         auto& cache = suiteResource<prism::render::ProgramCache>(prism::shaders::kCatalog);
//         EXPECT_FALSE(context().info().version.empty());
//     }
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>
#include <typeindex>
#include <typeinfo>
#include <utility>
#include <vector>

#include "prism/gl/gl_context.hpp"

namespace prism::test {

class GlTest : public ::testing::Test {
  public:
    static void SetUpTestSuite();
    static void TearDownTestSuite();

    // The suite's context; throws std::logic_error outside a running GlTest suite.
    static gl::Context& context();

    // The suite's one T, built from `args` on first use (later calls ignore them).
    template <class T, class... Args>
    static T& suiteResource(Args&&... args) {
        for (auto& [type, object] : resources())
            if (type == typeid(T)) return *static_cast<T*>(object.get());
        context();  // no resource outlives, or exists without, the context
        auto object = std::make_shared<T>(std::forward<Args>(args)...);
        resources().emplace_back(typeid(T), object);
        return *object;
    }

  protected:
    void SetUp() override;

    // Makes the suite's context on `backend`, or the default one (PRISM_GL_BACKEND) if none.
    static void setUpSuiteOn(std::optional<gl::Backend> backend);

  private:
    static std::vector<std::pair<std::type_index, std::shared_ptr<void>>>& resources();
};

// GlTest on a fixed backend.
template <gl::Backend B>
class GlTestOn : public GlTest {
  public:
    static void SetUpTestSuite() { setUpSuiteOn(B); }
};

}  // namespace prism::test
