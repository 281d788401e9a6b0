// Off-screen render targets: a colour texture (RGBA8 or RGBA32F) plus a 24-bit depth
// buffer, with readback into CPU images whose row 0 is the TOP row.
//
// Usage (snippet: examples/snippets/gl_framebuffer.cpp):
//
//     #include "prism/gl/framebuffer.hpp"
//     prism::gl::Framebuffer fb(256, 256);  // RGBA8 + depth24
//     fb.bind();                            // binds and sets the viewport
//     fb.clear({0.1f, 0.2f, 0.3f, 1.0f});   // colour and depth
//     // ... draw ...
//     prism::image::Image8 shot = fb.readImage8();  // top row first
//
//     prism::gl::Framebuffer hdr(64, 64, prism::gl::ColorFormat::Rgba32F);
//     prism::image::ImageF values = hdr.readImageF();  // unclamped floats
//
// Needs a current context (see prism/gl/gl_context.hpp) for its whole life; the GL
// objects are deleted in the destructor. Move-only. Construction throws
// prism::gl::GlError when the driver reports the framebuffer incomplete.
#pragma once

#include <array>

#include "prism/gl/handles.hpp"
#include "prism/image/image.hpp"

namespace prism::gl {

enum class ColorFormat { Rgba8, Rgba32F };

class Framebuffer {
  public:
    Framebuffer(int width, int height, ColorFormat format = ColorFormat::Rgba8);
    Framebuffer(Framebuffer&& other) noexcept = default;
    Framebuffer& operator=(Framebuffer&& other) noexcept = default;
    Framebuffer(const Framebuffer&) = delete;
    Framebuffer& operator=(const Framebuffer&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    ColorFormat format() const { return format_; }
    unsigned id() const { return framebuffer_.id(); }
    unsigned colorTexture() const { return color_.id(); }  // sample it in a later pass

    // Binds for drawing and reading and sets the viewport to the whole target.
    void bind() const;
    // Binds the context's default framebuffer (a window's back buffer, or none).
    static void bindDefault();

    // Binds, then clears colour to `rgba` and depth to `depth`.
    void clear(std::array<float, 4> rgba, float depth = 1.0f) const;

    // Reads the colour attachment; rows are flipped so that row 0 is the top.
    // readImage8 of an RGBA32F target clamps to [0, 1]; readImageF of RGBA8 gives v/255.
    image::Image8 readImage8() const;
    image::ImageF readImageF() const;

  private:
    int width_ = 0, height_ = 0;
    ColorFormat format_ = ColorFormat::Rgba8;
    FramebufferObject framebuffer_;
    Texture color_;
    Renderbuffer depth_;
};

}  // namespace prism::gl
