// Shows a CPU image (row 0 on top) in the window: uploaded once into a texture, then
// blitted onto the default framebuffer every frame. The scene view uses it for the
// SceneRenderer's frame, which is rendered again only when a parameter changes.
//
//     ImageBlit blit;
//     blit.upload(image);
//     blit.draw(0, framebufferWidth, framebufferHeight);  // scaled to that rectangle
//     blit.drawUnscaled(0, 0, framebufferHeight);        // or pixel for pixel at the top left
#pragma once

#include "prism/gl/handles.hpp"
#include "prism/image/image.hpp"

namespace prism::viewer {

class ImageBlit {
  public:
    void upload(const image::Image8& image);
    void draw(int left, int width, int height) const;  // onto that rectangle of the window
    // Pixel for pixel, the image's top-left corner `top` rows below the window's top and
    // `left` columns right of its left side; rows below the window's bottom are cut.
    void drawUnscaled(int left, int top, int windowHeight) const;
    bool empty() const { return width_ == 0; }

  private:
    int width_ = 0, height_ = 0;
    gl::Texture texture_;
    gl::FramebufferObject framebuffer_;
};

}  // namespace prism::viewer
