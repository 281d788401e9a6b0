// GL object ownership (prism/gl/handles.hpp): every object a Framebuffer or Program makes
// is counted while alive and deleted with its owner, including after moves and failures;
// a buffer given storage at creation holds that data and knows its size.
#include <array>
#include <cstdint>
#include <limits>
#include <string>

#include "gl_test_support.hpp"
#include "prism/test/gl_test.hpp"
#include "prism/gl/framebuffer.hpp"
#include "prism/gl/handles.hpp"

namespace {

using prism::gl::ObjectKind;

std::uint64_t live(ObjectKind kind) {
    return prism::gl::objectCounts().live(kind);
}

class Handles : public prism::test::GlTest {};

// The solid shader of the test catalogue, as raw stage sources.
prism::gl::ProgramSources solidSources() {
    const auto& variant = prism::test::kShaders[0].variants[0];
    prism::gl::ProgramSources sources;
    sources.label = "solid";
    for (const auto& stage : variant.stages)
        sources.stages.push_back({stage.stage, prism::catalog::joinChunks(stage.chunks), {}});
    return sources;
}

TEST_F(Handles, CreateCountsAndScopeEndDeletes) {
    const auto buffersBefore = live(ObjectKind::Buffer);
    {
        prism::gl::Buffer a = prism::gl::Buffer::create();
        EXPECT_NE(a.id(), 0u);
        EXPECT_EQ(live(ObjectKind::Buffer), buffersBefore + 1);
        prism::gl::Buffer b = std::move(a);  // the moved-from handle owns nothing
        EXPECT_EQ(a.id(), 0u);
        EXPECT_EQ(live(ObjectKind::Buffer), buffersBefore + 1);
        b.reset();
        EXPECT_EQ(live(ObjectKind::Buffer), buffersBefore);
        b = prism::gl::Buffer::create();
    }
    EXPECT_EQ(live(ObjectKind::Buffer), buffersBefore);
}

TEST_F(Handles, BufferWithStorageHoldsItsDataAndSize) {
    const std::array<std::uint32_t, 4> data = {7, 11, 13, 17};
    const auto buffersBefore = live(ObjectKind::Buffer);
    {
        prism::gl::Buffer a = prism::gl::Buffer::create(sizeof data, GL_STATIC_DRAW, data.data());
        EXPECT_EQ(a.bytes(), sizeof data);
        std::array<std::uint32_t, 4> read{};
        GLint64 size = 0;
        glBindBuffer(GL_COPY_READ_BUFFER, a.id());
        glGetBufferParameteri64v(GL_COPY_READ_BUFFER, GL_BUFFER_SIZE, &size);
        glGetBufferSubData(GL_COPY_READ_BUFFER, 0, sizeof read, read.data());
        glBindBuffer(GL_COPY_READ_BUFFER, 0);
        EXPECT_EQ(size, static_cast<GLint64>(sizeof data));
        EXPECT_EQ(read, data);
        prism::gl::Buffer b = std::move(a);  // the size moves with the name
        EXPECT_EQ(a.bytes(), 0u);
        EXPECT_EQ(b.bytes(), sizeof data);
        a = prism::gl::Buffer::create(64, GL_DYNAMIC_DRAW);
        b = std::move(a);
        EXPECT_EQ(b.bytes(), 64u);
        EXPECT_EQ(a.bytes(), 0u);
        EXPECT_EQ(live(ObjectKind::Buffer), buffersBefore + 1) << "the buffer replaced by a move was not deleted";
        EXPECT_EQ(prism::gl::Buffer::create().bytes(), 0u) << "a bare name has no storage yet";
    }
    EXPECT_EQ(live(ObjectKind::Buffer), buffersBefore);
}

TEST_F(Handles, ABufferGLCannotAllocateIsAnErrorNamingItsSize) {
    const auto buffersBefore = live(ObjectKind::Buffer);
    const std::size_t huge = std::numeric_limits<std::size_t>::max();  // a negative GLsizeiptr
    try {
        (void)prism::gl::Buffer::create(huge, GL_DYNAMIC_DRAW);
        FAIL() << "no error for a buffer of " << huge << " bytes";
    } catch (const prism::gl::GlError& e) {
        EXPECT_NE(std::string(e.what()).find(std::to_string(huge) + " bytes"), std::string::npos) << e.what();
    }
    EXPECT_EQ(live(ObjectKind::Buffer), buffersBefore) << "the failed buffer's name leaked";
}

TEST_F(Handles, FramebufferAndProgramOwnTheirObjects) {
    const auto before = prism::gl::objectCounts();
    {
        prism::gl::Framebuffer fb(16, 16);
        prism::gl::Framebuffer moved = std::move(fb);
        EXPECT_EQ(live(ObjectKind::Framebuffer), before.live(ObjectKind::Framebuffer) + 1);
        EXPECT_EQ(live(ObjectKind::Texture), before.live(ObjectKind::Texture) + 1);
        EXPECT_EQ(live(ObjectKind::Renderbuffer), before.live(ObjectKind::Renderbuffer) + 1);
        prism::gl::Program program(solidSources());
        EXPECT_EQ(live(ObjectKind::Program), before.live(ObjectKind::Program) + 1);
        EXPECT_EQ(live(ObjectKind::Shader), before.live(ObjectKind::Shader)) << "shaders are deleted after linking";
    }
    const auto after = prism::gl::objectCounts();
    for (int k = 0; k < static_cast<int>(ObjectKind::Count); ++k)
        EXPECT_EQ(after.liveByKind[k], before.liveByKind[k]) << "kind " << k << " leaked";
}

TEST_F(Handles, AFailedCompileLeaksNothing) {
    const auto before = prism::gl::objectCounts();
    auto sources = solidSources();
    sources.stages.back().source += "this is not GLSL\n";
    EXPECT_THROW(prism::gl::Program program(sources), prism::gl::ShaderBuildError);
    const auto after = prism::gl::objectCounts();
    EXPECT_EQ(after.live(ObjectKind::Shader), before.live(ObjectKind::Shader));
    EXPECT_EQ(after.live(ObjectKind::Program), before.live(ObjectKind::Program));
    EXPECT_GT(after.created(ObjectKind::Shader), before.created(ObjectKind::Shader));
}

}  // namespace
