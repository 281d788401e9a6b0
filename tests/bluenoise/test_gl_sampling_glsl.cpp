// GLSL vs C++: modules/bluenoise/sampling.glsl, run in a fragment shader on llvmpipe,
// returns the same 32-bit samples as prism/bluenoise/samplers.hpp for every pixel of a
// 37x23 target (larger than the 16x12 tables, so they tile), four samplers (the stack 11x7x5), several
// dimensions and frames 0, 1, 7, 10^6 and 2^32-1.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "prism/bluenoise/samplers.hpp"
#include "prism/bluenoise/void_and_cluster.hpp"
#include "prism/gl/gl.hpp"
#include "prism/test/gl_test.hpp"

namespace bn = prism::bluenoise;

namespace {

std::string readModule() {
    std::ifstream in(PRISM_BLUENOISE_SAMPLING_GLSL);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

GLuint compile(GLenum stage, const std::string& source) {
    const GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        ADD_FAILURE() << log;
    }
    return shader;
}

GLuint uintTexture(int w, int h, const std::vector<std::uint32_t>& values) {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32UI, w, h, 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                 values.empty() ? nullptr : values.data());
    return tex;
}

}  // namespace

class SamplingGlsl : public prism::test::GlTest {};

TEST_F(SamplingGlsl, MatchesCppBitForBit) {
    const std::string vert =
        "#version 330 core\n"
        "void main() { vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2); gl_Position = vec4(p * 2.0 - 1.0, 0.0, "
        "1.0); }\n";
    const std::string frag = "#version 330 core\n" + readModule() +
                             "uniform uint u_frame;\nuniform uint u_dim;\nout uvec4 o_bits;\n"
                             "void main() { o_bits = uvec4(prismBlueNoiseSampleBits(uvec2(gl_FragCoord.xy), u_frame, "
                             "u_dim), 0u, 0u, 0u); }\n";
    const GLuint program = glCreateProgram();
    glAttachShader(program, compile(GL_VERTEX_SHADER, vert));
    glAttachShader(program, compile(GL_FRAGMENT_SHADER, frag));
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    ASSERT_TRUE(linked);
    glUseProgram(program);

    bn::VoidAndClusterOptions options;
    options.width = 16;
    options.height = 12;
    bn::SamplerTables tables = bn::SamplerTables::fromMask(bn::generateVoidAndCluster(options));
    tables.seedWidth = 13, tables.seedHeight = 9;  // a seed table of another size
    tables.seeds.resize(13 * 9);
    for (std::size_t i = 0; i < tables.seeds.size(); ++i)
        tables.seeds[i] = bn::pcgHash(static_cast<std::uint32_t>(i) * 77u);
    tables.setStack(bn::generateSpatiotemporal({.width = 11, .height = 7}, 5));  // a stack of yet another size

    glActiveTexture(GL_TEXTURE0);
    uintTexture(tables.maskWidth, tables.maskHeight, tables.mask);
    glActiveTexture(GL_TEXTURE1);
    uintTexture(tables.seedWidth, tables.seedHeight, tables.seeds);
    glUniform1i(glGetUniformLocation(program, "u_blueNoiseMask"), 0);
    glUniform1i(glGetUniformLocation(program, "u_blueNoiseSeeds"), 1);
    glActiveTexture(GL_TEXTURE3);
    uintTexture(tables.stackWidth, tables.stackHeight * tables.stackDepth, tables.stack);
    glUniform1i(glGetUniformLocation(program, "u_blueNoiseStack"), 3);
    glUniform1i(glGetUniformLocation(program, "u_blueNoiseStackDepth"), tables.stackDepth);

    const int w = 37, h = 23;
    glActiveTexture(GL_TEXTURE2);
    const GLuint target = uintTexture(w, h, {});
    GLuint fbo = 0, vao = 0;
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
    ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glViewport(0, 0, w, h);

    int checked = 0;
    for (bn::SamplerKind kind :
         {bn::SamplerKind::White, bn::SamplerKind::BlueNoise, bn::SamplerKind::Sorted, bn::SamplerKind::Stack})
        for (std::uint32_t frame : {0u, 1u, 7u, 1000000u, 0xFFFFFFFFu})
            for (std::uint32_t dim : {0u, 1u, 5u}) {
                glUniform1i(glGetUniformLocation(program, "u_blueNoiseSampler"), static_cast<GLint>(kind));
                glUniform1ui(glGetUniformLocation(program, "u_frame"), frame);
                glUniform1ui(glGetUniformLocation(program, "u_dim"), dim);
                glDrawArrays(GL_TRIANGLES, 0, 3);
                std::vector<std::uint32_t> gpu(static_cast<std::size_t>(w * h));
                glReadPixels(0, 0, w, h, GL_RED_INTEGER, GL_UNSIGNED_INT, gpu.data());
                ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
                int mismatches = 0;
                for (int y = 0; y < h; ++y)
                    for (int x = 0; x < w; ++x) {
                        const std::uint32_t cpu = bn::sample(kind, tables, static_cast<std::uint32_t>(x),
                                                             static_cast<std::uint32_t>(y), frame, dim);
                        if (gpu[static_cast<std::size_t>(y * w + x)] != cpu && mismatches++ < 3)
                            ADD_FAILURE() << "sampler " << static_cast<int>(kind) << " frame " << frame << " dim "
                                          << dim << " pixel (" << x << ", " << y << "): GLSL "
                                          << gpu[static_cast<std::size_t>(y * w + x)] << " C++ " << cpu;
                        ++checked;
                    }
            }
    EXPECT_EQ(checked, 4 * 5 * 3 * w * h);
}
