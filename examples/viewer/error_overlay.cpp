// Draws the viewer's error strip (see error_overlay.hpp).
#include "error_overlay.hpp"

#include <algorithm>
#include <vector>

#include "prism/gl/gl.hpp"
#include "prism/image/contact_sheet.hpp"

namespace prism::viewer {
namespace {

constexpr int kPadding = 4;

std::vector<std::string> wrap(const std::string& text, std::size_t columns) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start <= text.size()) {
        auto end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        do {
            lines.push_back(line.substr(0, columns));
            line.erase(0, std::min(columns, line.size()));
        } while (!line.empty());
        start = end + 1;
    }
    while (!lines.empty() && lines.back().empty()) lines.pop_back();
    return lines;
}

}  // namespace

image::Image8 overlayImage(const std::string& text, int width, int maxLines) {
    width = std::max(width, 16);
    const int scale = width >= 600 ? 2 : 1;
    const int advance = std::max(1, image::textWidth("MM", scale) - image::textWidth("M", scale));
    const auto columns = static_cast<std::size_t>(std::max(1, (width - 2 * kPadding) / advance));
    auto lines = wrap(text, columns);
    if (lines.size() > static_cast<std::size_t>(maxLines)) {
        lines.resize(static_cast<std::size_t>(maxLines));
        auto& last = lines.back();
        last = last.substr(0, columns >= 2 ? columns - 2 : 0) + "..";
    }
    std::string joined;
    for (const auto& l : lines) joined += (joined.empty() ? "" : "\n") + l;
    const int height = image::textHeight(joined.empty() ? " " : joined, scale) + 2 * kPadding;
    image::Image8 strip(width, height, {110, 16, 16, 255});
    image::drawText(strip, kPadding, kPadding, joined, scale, {255, 236, 200, 255});
    return strip;
}

void ErrorOverlay::setText(std::string text) {
    if (text == text_) return;
    text_ = std::move(text);
    uploadedWidth_ = -1;  // re-upload at the next draw
}

void ErrorOverlay::draw(int framebufferWidth, int framebufferHeight) {
    if (text_.empty() || framebufferWidth <= 0 || framebufferHeight <= 0) return;
    if (!texture_) {
        texture_ = gl::Texture::create();
        framebuffer_ = gl::FramebufferObject::create();
    }
    if (uploadedWidth_ != framebufferWidth) {
        const auto strip = overlayImage(text_, framebufferWidth);
        glBindTexture(GL_TEXTURE_2D, texture_.id());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, strip.width, strip.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     strip.data.data());
        glBindTexture(GL_TEXTURE_2D, 0);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
        glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_.id(), 0);
        uploadedWidth_ = framebufferWidth;
        stripHeight_ = strip.height;
    }
    // Image row 0 is the top: blit with the destination's y flipped, onto the window's top.
    const int h = std::min(stripHeight_, framebufferHeight);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, uploadedWidth_, h, 0, framebufferHeight, uploadedWidth_, framebufferHeight - h,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace prism::viewer
