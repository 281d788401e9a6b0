// Draws the viewer's error strip (see error_overlay.hpp).
#include "error_overlay.hpp"

#include <algorithm>
#include <vector>

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
    if (uploadedWidth_ != framebufferWidth) {
        strip_.upload(overlayImage(text_, framebufferWidth));
        uploadedWidth_ = framebufferWidth;
    }
    strip_.drawUnscaled(0, 0, framebufferHeight);  // onto the window's top
}

}  // namespace prism::viewer
