// The viewer's error overlay: a strip at the top of the window with the first line(s) of
// a diagnostic, drawn with prism::image's bitmap font into an image and blitted onto the
// default framebuffer (ImageBlit) (no shader involved, so it shows even when every program is broken).
//
//     ErrorOverlay overlay;
//     overlay.setText("modules/lights.glsl:12:5: error: 'foo' : undeclared identifier");
//     overlay.draw(framebufferWidth, framebufferHeight);  // after the scene, before swapBuffers
//     overlay.setText("");                                 // hides it
#pragma once

#include <string>

#include "image_blit.hpp"
#include "prism/image/image.hpp"

namespace prism::viewer {

// The strip as a CPU image `width` pixels wide: `text` wrapped to the width, at most
// `maxLines` lines (the last ends with ".." when cut), light text on dark red.
image::Image8 overlayImage(const std::string& text, int width, int maxLines = 4);

class ErrorOverlay {
  public:
    void setText(std::string text);
    const std::string& text() const { return text_; }
    void draw(int framebufferWidth, int framebufferHeight);  // needs the window's context current

  private:
    std::string text_;
    int uploadedWidth_ = -1;  // the strip is laid out for this window width
    ImageBlit strip_;
};

}  // namespace prism::viewer
