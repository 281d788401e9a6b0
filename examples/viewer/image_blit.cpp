// Texture upload and blit of a CPU image onto the window (image_blit.hpp).
#include "image_blit.hpp"

#include <algorithm>

#include "prism/gl/gl.hpp"

namespace prism::viewer {

void ImageBlit::upload(const image::Image8& image) {
    if (!texture_) {
        texture_ = gl::Texture::create();
        framebuffer_ = gl::FramebufferObject::create();
    }
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 image.data.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_.id(), 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    width_ = image.width;
    height_ = image.height;
}

void ImageBlit::draw(int left, int width, int height) const {
    if (empty()) return;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    // Image row 0 is the top, GL's row 0 the bottom: flip y in the destination.
    glBlitFramebuffer(0, 0, width_, height_, left, height, left + width, 0, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ImageBlit::drawUnscaled(int left, int top, int windowHeight) const {
    const int rows = std::min(height_, windowHeight - top);
    if (empty() || rows <= 0) return;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    // Texture row r is image row r (the top); window row 0 is the bottom.
    glBlitFramebuffer(0, 0, width_, rows, left, windowHeight - top, left + width_, windowHeight - top - rows,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace prism::viewer
