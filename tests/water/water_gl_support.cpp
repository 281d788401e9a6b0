// One GL 4.3 context per process for the water GL tests (see water_gl_support.hpp).
#include "water_gl_support.hpp"

#include <memory>
#include <string>

namespace prism::water::test {
namespace {

struct State {
    std::unique_ptr<gl::Context> context;
    std::string error;
    bool tried = false;
};

State& state() {
    static State s;
    return s;
}

class Environment : public ::testing::Environment {
  public:
    void TearDown() override { state().context.reset(); }
};

[[maybe_unused]] const ::testing::Environment* const kEnvironment =
    ::testing::AddGlobalTestEnvironment(new Environment);

}  // namespace

gl::Context* glContext() {
    State& s = state();
    if (!s.tried) {
        s.tried = true;
        try {
            s.context = gl::createContext({.majorVersion = 4, .minorVersion = 3});
        } catch (const std::exception& e) {
            s.error = e.what();
        }
    }
    return s.context.get();
}

const std::string& glContextError() {
    return state().error;
}

void WaterGlTest::SetUp() {
    ASSERT_NE(glContext(), nullptr) << "cannot create the GL 4.3 context the water GL tests need: " << glContextError();
    glContext()->makeCurrent();
}

}  // namespace prism::water::test
