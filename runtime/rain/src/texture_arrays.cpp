// Uploading the rain system's 8-bit texture arrays (see texture_arrays.hpp).
#include "texture_arrays.hpp"

#include "prism/gl/gl.hpp"

namespace prism::rain {

gl::Texture uploadTextureArray8(int width, int height, int layers, int channels, const std::uint8_t* texels,
                                bool repeat) {
    const bool rgba = channels == 4;
    gl::Texture texture = gl::Texture::create();
    glBindTexture(GL_TEXTURE_2D_ARRAY, texture.id());
    GLint alignment = 4;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, rgba ? GL_RGBA8 : GL_R8, width, height, layers, 0, rgba ? GL_RGBA : GL_RED,
                 GL_UNSIGNED_BYTE, texels);
    glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    const GLint wrap = repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, wrap);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, wrap);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    gl::throwIfGlError("rain: uploading a texture array");
    return texture;
}

}  // namespace prism::rain
