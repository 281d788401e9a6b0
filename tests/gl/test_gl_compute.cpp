// The one compute wrapper (prism/gl/compute.hpp): a dispatch reaches every invocation
// exactly once, past the 65535 groups of x too, and every dispatch, and only a real one,
// is counted. The storage buffer is a prism::gl::Buffer given its size at creation.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "gl_test_support.hpp"
#include "prism/test/gl_test.hpp"
#include "prism/gl/compute.hpp"
#include "prism/gl/handles.hpp"

namespace {

// One invocation per group; hits[linear group index] += 1 for indices below u_count.
prism::gl::ProgramSources countingShader() {
    return {.label = "count hits",
            .stages = {{.stage = prism::catalog::Stage::Compute,
                        .source = "#version 430 core\n"
                                  "layout(local_size_x = 1) in;\n"
                                  "layout(std430, binding = 0) buffer Hits { uint hits[]; };\n"
                                  "uniform uint u_count;\n"
                                  "void main() {\n"
                                  "    uint i = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;\n"
                                  "    if (i < u_count) atomicAdd(hits[i], 1u);\n"
                                  "}\n",
                        .files = {}}},
            .attributes = {},
            .uniforms = std::nullopt};
}

class Compute : public prism::test::GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        prism::gl::requireCompute("the compute tests");
        program_.emplace(countingShader());
        program_->use();
    }

    // A zeroed storage buffer of `count` counters at binding 0.
    void bindHits(std::uint32_t count) {
        const std::vector<std::uint32_t> zeros(count, 0u);
        hits_ = prism::gl::Buffer::create(count * sizeof(std::uint32_t), GL_DYNAMIC_COPY, zeros.data());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, hits_.id());
    }

    std::vector<std::uint32_t> readHits() {
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<std::uint32_t> out(hits_.bytes() / sizeof(std::uint32_t));
        glBindBuffer(GL_COPY_READ_BUFFER, hits_.id());
        glGetBufferSubData(GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(hits_.bytes()), out.data());
        glBindBuffer(GL_COPY_READ_BUFFER, 0);
        prism::gl::throwIfGlError("reading the hits back");
        return out;
    }

    std::optional<prism::gl::Program> program_;
    prism::gl::Buffer hits_;
};

TEST_F(Compute, InvocationsPastTheXLimitEachRunOnce) {
    constexpr std::uint32_t kCount = 70000;  // groups of 1: 65535 in x, 2 rows in y
    ASSERT_EQ(prism::gl::computeGroups(kCount, 1), (std::array<std::uint32_t, 2>{65535, 2}));
    bindHits(kCount);
    program_->set("u_count", kCount);  // the shader skips the rest of the last row
    const std::uint64_t before = prism::gl::computeDispatches();
    prism::gl::dispatchInvocations(kCount, 1);
    EXPECT_EQ(prism::gl::computeDispatches() - before, 1u);
    const std::vector<std::uint32_t> hits = readHits();
    std::uint32_t once = 0;
    for (std::uint32_t i = 0; i < kCount; ++i) once += hits[i] == 1u ? 1u : 0u;
    EXPECT_EQ(once, kCount) << "invocations that ran other than once";
}

TEST_F(Compute, GroupsRunAsAskedAndOnlyRealDispatchesCount) {
    bindHits(8);
    program_->set("u_count", 8u);
    const std::uint64_t before = prism::gl::computeDispatches();
    prism::gl::dispatchInvocations(0, 64);  // nothing to do
    prism::gl::dispatchGroups(0, 4);
    EXPECT_EQ(prism::gl::computeDispatches(), before) << "an empty dispatch was counted";
    prism::gl::dispatchGroups(3, 2);  // linear indices 0..5
    EXPECT_EQ(prism::gl::computeDispatches() - before, 1u);
    EXPECT_EQ(readHits(), (std::vector<std::uint32_t>{1, 1, 1, 1, 1, 1, 0, 0}));
}

}  // namespace
