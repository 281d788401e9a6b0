// Capturing, restoring and comparing the GL state of a draw (see prism/gl/draw_state.hpp).
#include "prism/gl/draw_state.hpp"

#include <sstream>

#include "prism/gl/gl.hpp"

namespace prism::gl {
namespace {

constexpr std::array<GLenum, 8> kCapabilities = {
    GL_BLEND,        GL_DEPTH_TEST,         GL_CULL_FACE,           GL_SCISSOR_TEST,
    GL_STENCIL_TEST, GL_PROGRAM_POINT_SIZE, GL_POLYGON_OFFSET_FILL, GL_TEXTURE_CUBE_MAP_SEAMLESS};
constexpr std::array<const char*, 8> kCapabilityNames = {
    "blend",        "depth test",         "cull face",           "scissor test",
    "stencil test", "program point size", "polygon offset fill", "seamless cube map"};
constexpr std::array<GLenum, 6> kBlendQueries = {GL_BLEND_SRC_RGB,   GL_BLEND_DST_RGB,      GL_BLEND_SRC_ALPHA,
                                                 GL_BLEND_DST_ALPHA, GL_BLEND_EQUATION_RGB, GL_BLEND_EQUATION_ALPHA};
constexpr std::array<GLenum, 8> kBufferTargets = {GL_ARRAY_BUFFER,      GL_SHADER_STORAGE_BUFFER, GL_UNIFORM_BUFFER,
                                                  GL_PIXEL_PACK_BUFFER, GL_PIXEL_UNPACK_BUFFER,   GL_COPY_READ_BUFFER,
                                                  GL_COPY_WRITE_BUFFER, GL_DRAW_INDIRECT_BUFFER};
constexpr std::array<GLenum, 8> kBufferQueries = {GL_ARRAY_BUFFER_BINDING,        GL_SHADER_STORAGE_BUFFER_BINDING,
                                                  GL_UNIFORM_BUFFER_BINDING,      GL_PIXEL_PACK_BUFFER_BINDING,
                                                  GL_PIXEL_UNPACK_BUFFER_BINDING, GL_COPY_READ_BUFFER_BINDING,
                                                  GL_COPY_WRITE_BUFFER_BINDING,   GL_DRAW_INDIRECT_BUFFER_BINDING};
constexpr std::array<GLenum, DrawState::kTextureTargets> kTextureTargets = {
    GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_3D, GL_TEXTURE_BUFFER};
constexpr std::array<GLenum, DrawState::kTextureTargets> kTextureQueries = {
    GL_TEXTURE_BINDING_2D, GL_TEXTURE_BINDING_2D_ARRAY, GL_TEXTURE_BINDING_CUBE_MAP, GL_TEXTURE_BINDING_3D,
    GL_TEXTURE_BINDING_BUFFER};
constexpr std::array<const char*, DrawState::kTextureTargets> kTextureNames = {"2D", "2D array", "cube map", "3D",
                                                                               "buffer"};

int get(GLenum what) {
    GLint v = 0;
    glGetIntegerv(what, &v);
    return v;
}

int getIndexed(GLenum what, int index) {
    GLint v = 0;
    glGetIntegeri_v(what, static_cast<GLuint>(index), &v);
    return v;
}

void captureTextures(DrawState& s) {
    s.activeTexture = get(GL_ACTIVE_TEXTURE);
    for (int u = 0; u < DrawState::kTextureUnits; ++u) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + u));
        for (int t = 0; t < DrawState::kTextureTargets; ++t) s.textures[u][t] = get(kTextureQueries[t]);
        s.samplers[u] = get(GL_SAMPLER_BINDING);
    }
    glActiveTexture(static_cast<GLenum>(s.activeTexture));
}

void restoreTextures(const DrawState& s) {
    for (int u = 0; u < DrawState::kTextureUnits; ++u) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + u));
        for (int t = 0; t < DrawState::kTextureTargets; ++t)
            glBindTexture(kTextureTargets[t], static_cast<GLuint>(s.textures[u][t]));
        glBindSampler(static_cast<GLuint>(u), static_cast<GLuint>(s.samplers[u]));
    }
    glActiveTexture(static_cast<GLenum>(s.activeTexture));
}

void setCapability(GLenum cap, int on) {
    if (on)
        glEnable(cap);
    else
        glDisable(cap);
}

template <class Array>
void compare(std::ostringstream& out, const char* what, const Array& a, const Array& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i] != b[i]) out << what << "[" << i << "]: " << a[i] << " -> " << b[i] << "; ";
}

void compare(std::ostringstream& out, const char* what, int a, int b) {
    if (a != b) out << what << ": " << a << " -> " << b << "; ";
}

}  // namespace

DrawState DrawState::capture() {
    DrawState s;
    for (std::size_t i = 0; i < kCapabilities.size(); ++i) s.enabled[i] = glIsEnabled(kCapabilities[i]) ? 1 : 0;
    for (std::size_t i = 0; i < kBlendQueries.size(); ++i) s.blend[i] = get(kBlendQueries[i]);
    GLboolean mask[4] = {};
    glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    for (int i = 0; i < 4; ++i) s.colorMask[i] = mask[i];
    GLboolean depthMask = GL_FALSE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
    s.depthMask = depthMask;
    s.depthFunc = get(GL_DEPTH_FUNC);
    s.program = get(GL_CURRENT_PROGRAM);
    s.vertexArray = get(GL_VERTEX_ARRAY_BINDING);
    if (s.vertexArray != 0) {
        s.elementBuffer = get(GL_ELEMENT_ARRAY_BUFFER_BINDING);
        for (int a = 0; a < kAttributes; ++a) {
            GLint on = 0;
            glGetVertexAttribiv(static_cast<GLuint>(a), GL_VERTEX_ATTRIB_ARRAY_ENABLED, &on);
            s.attributeEnabled[a] = on;
        }
    }
    for (std::size_t i = 0; i < kBufferQueries.size(); ++i) s.buffers[i] = get(kBufferQueries[i]);
    for (int i = 0; i < kIndexedBuffers; ++i) {
        s.storageBuffers[i] = getIndexed(GL_SHADER_STORAGE_BUFFER_BINDING, i);
        s.uniformBuffers[i] = getIndexed(GL_UNIFORM_BUFFER_BINDING, i);
    }
    captureTextures(s);
    s.drawFramebuffer = get(GL_DRAW_FRAMEBUFFER_BINDING);
    s.readFramebuffer = get(GL_READ_FRAMEBUFFER_BINDING);
    glGetIntegerv(GL_VIEWPORT, s.viewport.data());
    s.unpackAlignment = get(GL_UNPACK_ALIGNMENT);
    s.packAlignment = get(GL_PACK_ALIGNMENT);
    return s;
}

void DrawState::restore() const {
    for (std::size_t i = 0; i < kCapabilities.size(); ++i) setCapability(kCapabilities[i], enabled[i]);
    glBlendFuncSeparate(static_cast<GLenum>(blend[0]), static_cast<GLenum>(blend[1]), static_cast<GLenum>(blend[2]),
                        static_cast<GLenum>(blend[3]));
    glBlendEquationSeparate(static_cast<GLenum>(blend[4]), static_cast<GLenum>(blend[5]));
    glColorMask(colorMask[0] != 0, colorMask[1] != 0, colorMask[2] != 0, colorMask[3] != 0);
    glDepthMask(depthMask != 0);
    glDepthFunc(static_cast<GLenum>(depthFunc));
    glUseProgram(static_cast<GLuint>(program));
    glBindVertexArray(static_cast<GLuint>(vertexArray));
    if (vertexArray != 0) {
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLuint>(elementBuffer));
        for (int a = 0; a < kAttributes; ++a)
            if (attributeEnabled[a])
                glEnableVertexAttribArray(static_cast<GLuint>(a));
            else
                glDisableVertexAttribArray(static_cast<GLuint>(a));
    }
    for (std::size_t i = 0; i < kBufferTargets.size(); ++i)
        glBindBuffer(kBufferTargets[i], static_cast<GLuint>(buffers[i]));
    for (int i = 0; i < kIndexedBuffers; ++i) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(i), static_cast<GLuint>(storageBuffers[i]));
        glBindBufferBase(GL_UNIFORM_BUFFER, static_cast<GLuint>(i), static_cast<GLuint>(uniformBuffers[i]));
    }
    // glBindBufferBase also sets the generic binding: put those back after it.
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(buffers[1]));
    glBindBuffer(GL_UNIFORM_BUFFER, static_cast<GLuint>(buffers[2]));
    restoreTextures(*this);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFramebuffer));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment);
    glPixelStorei(GL_PACK_ALIGNMENT, packAlignment);
}

std::string describeChanges(const DrawState& a, const DrawState& b) {
    std::ostringstream out;
    for (std::size_t i = 0; i < kCapabilities.size(); ++i)
        compare(out, kCapabilityNames[i], a.enabled[i], b.enabled[i]);
    compare(out, "blend src/dst rgb, src/dst alpha, equation rgb/alpha", a.blend, b.blend);
    compare(out, "colour mask", a.colorMask, b.colorMask);
    compare(out, "depth mask", a.depthMask, b.depthMask);
    compare(out, "depth func", a.depthFunc, b.depthFunc);
    compare(out, "program", a.program, b.program);
    compare(out, "vertex array", a.vertexArray, b.vertexArray);
    compare(out, "element buffer", a.elementBuffer, b.elementBuffer);
    compare(out, "attribute array enabled", a.attributeEnabled, b.attributeEnabled);
    compare(out, "buffer (array, storage, uniform, pack, unpack, copy read/write, indirect)", a.buffers, b.buffers);
    compare(out, "storage buffer binding", a.storageBuffers, b.storageBuffers);
    compare(out, "uniform buffer binding", a.uniformBuffers, b.uniformBuffers);
    compare(out, "active texture unit", a.activeTexture - GL_TEXTURE0, b.activeTexture - GL_TEXTURE0);
    for (int u = 0; u < DrawState::kTextureUnits; ++u)
        for (int t = 0; t < DrawState::kTextureTargets; ++t)
            if (a.textures[u][t] != b.textures[u][t])
                out << "texture unit " << u << " " << kTextureNames[t] << ": " << a.textures[u][t] << " -> "
                    << b.textures[u][t] << "; ";
    compare(out, "sampler on unit", a.samplers, b.samplers);
    compare(out, "draw framebuffer", a.drawFramebuffer, b.drawFramebuffer);
    compare(out, "read framebuffer", a.readFramebuffer, b.readFramebuffer);
    compare(out, "viewport", a.viewport, b.viewport);
    compare(out, "unpack alignment", a.unpackAlignment, b.unpackAlignment);
    compare(out, "pack alignment", a.packAlignment, b.packAlignment);
    return out.str();
}

}  // namespace prism::gl
