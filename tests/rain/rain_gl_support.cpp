// The rain GL tier's context environment (see rain_gl_support.hpp).
#include "rain_gl_support.hpp"

#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string_view>

namespace prism::rain::test {
namespace {

struct GlState {
    std::unique_ptr<gl::Context> context;
    std::unique_ptr<RainPrograms> programs;
    std::string error;
};

GlState& state() {
    static GlState s;
    return s;
}

class Environment : public ::testing::Environment {
  public:
    void SetUp() override {
        try {
            state().context = gl::createContext(gl::ContextOptions{.majorVersion = 4, .minorVersion = 3});
            state().programs = std::make_unique<RainPrograms>();
        } catch (const std::exception& e) {
            state().error = e.what();
        }
    }
    void TearDown() override {
        state().programs.reset();  // programs need the context: delete them first
        state().context.reset();
    }
};

[[maybe_unused]] const ::testing::Environment* const kEnvironment =
    ::testing::AddGlobalTestEnvironment(new Environment);

}  // namespace

gl::Context* context() {
    return state().context.get();
}
const std::string& contextError() {
    return state().error;
}

RainPrograms& programs() {
    if (!state().programs) throw std::logic_error("no GL context: " + state().error);
    return *state().programs;
}

void RainGlTest::SetUp() {
    ASSERT_NE(context(), nullptr) << "no GL 4.3 context: " << contextError();
    context()->makeCurrent();
}

bool envFlag(const char* name) {
    const char* v = std::getenv(name);
    if (!v) return false;
    const std::string_view s(v);
    return !(s.empty() || s == "0" || s == "false");
}

}  // namespace prism::rain::test
