// GlTest (prism/test/gl_test.hpp): the suite's context and the objects that live with it.
#include "prism/test/gl_test.hpp"

#include <stdexcept>

namespace prism::test {
namespace {

struct SuiteContext {
    std::unique_ptr<gl::Context> context;
    std::string error;  // why createContext failed
};

SuiteContext& suite() {
    static SuiteContext s;
    return s;
}

}  // namespace

std::vector<std::pair<std::type_index, std::shared_ptr<void>>>& GlTest::resources() {
    static std::vector<std::pair<std::type_index, std::shared_ptr<void>>> r;
    return r;
}

void GlTest::SetUpTestSuite() {
    setUpSuiteOn(std::nullopt);
}

void GlTest::setUpSuiteOn(std::optional<gl::Backend> backend) {
    suite().error.clear();
    const gl::ContextOptions options{.majorVersion = 4, .minorVersion = 3};
    try {
        suite().context = backend ? gl::createContext(*backend, options) : gl::createContext(options);
    } catch (const std::exception& e) {
        suite().error = e.what();
    }
}

void GlTest::TearDownTestSuite() {
    while (!resources().empty()) resources().pop_back();  // GL objects go before their context
    suite().context.reset();
}

gl::Context& GlTest::context() {
    if (!suite().context) throw std::logic_error("no GL context for this suite: " + suite().error);
    return *suite().context;
}

void GlTest::SetUp() {
    ASSERT_NE(suite().context, nullptr) << "no GL 4.3 context: " << suite().error;
    suite().context->makeCurrent();
}

}  // namespace prism::test
