// Framebuffer objects with a colour texture and depth renderbuffer, and readback.
#include "prism/gl/framebuffer.hpp"

#include <string>
#include <utility>

#include "prism/gl/gl.hpp"

namespace prism::gl {
namespace {

std::string statusName(GLenum status) {
    switch (status) {
        case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
        case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
        case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
        default: return "status " + std::to_string(status);
    }
}

std::string sizeText(int w, int h) {
    return std::to_string(w) + "x" + std::to_string(h);
}

// Reads the whole colour attachment bottom-up (GL order) into `data`.
template <class T>
void readPixels(const Framebuffer& fb, GLenum type, std::vector<T>& data) {
    fb.bind();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, fb.width(), fb.height(), GL_RGBA, type, data.data());
    throwIfGlError("reading back a " + sizeText(fb.width(), fb.height()) + " framebuffer");
}

}  // namespace

Framebuffer::Framebuffer(int width, int height, ColorFormat format) : width_(width), height_(height), format_(format) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
    if (width < 1 || height < 1 || width > maxSize || height > maxSize)
        throw GlError("prism: framebuffer size " + sizeText(width, height) + " is outside 1.." +
                      std::to_string(maxSize) + " (GL_MAX_RENDERBUFFER_SIZE)");

    framebuffer_ = FramebufferObject::create();
    color_ = Texture::create();
    depth_ = Renderbuffer::create();

    glBindTexture(GL_TEXTURE_2D, color_.id());
    if (format == ColorFormat::Rgba8)
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    else
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);

    glBindRenderbuffer(GL_RENDERBUFFER, depth_.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);

    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_.id(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {  // the handles delete what was made
        throw GlError("prism: " + sizeText(width, height) + " framebuffer is incomplete: " + statusName(status));
    }
    throwIfGlError("creating a " + sizeText(width, height) + " framebuffer");
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, width_, height_);
}

void Framebuffer::bindDefault() {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Framebuffer::clear(std::array<float, 4> rgba, float depth) const {
    bind();
    glClearColor(rgba[0], rgba[1], rgba[2], rgba[3]);
    glClearDepth(static_cast<double>(depth));
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

image::Image8 Framebuffer::readImage8() const {
    image::Image8 bottomUp(width_, height_);
    readPixels(*this, GL_UNSIGNED_BYTE, bottomUp.data);
    return image::flippedVertically(bottomUp);
}

image::ImageF Framebuffer::readImageF() const {
    image::ImageF bottomUp(width_, height_);
    readPixels(*this, GL_FLOAT, bottomUp.data);
    return image::flippedVertically(bottomUp);
}

}  // namespace prism::gl
