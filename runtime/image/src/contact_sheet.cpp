// Text drawing with the built-in font and the contact-sheet layout.
#include "prism/image/contact_sheet.hpp"

#include <algorithm>
#include <stdexcept>

#include "bitmap_font.hpp"

namespace prism::image {
namespace {

void fillRect(Image8& image, int x0, int y0, int w, int h, const Rgba8& colour) {
    const int x1 = std::min(image.width, x0 + w), y1 = std::min(image.height, y0 + h);
    for (int y = std::max(0, y0); y < y1; ++y)
        for (int x = std::max(0, x0); x < x1; ++x) {
            const std::size_t o = image.offset(x, y);
            for (std::size_t c = 0; c < 4; ++c) image.data[o + c] = colour[c];
        }
}

void blit(Image8& dst, const Image8& src, int x0, int y0) {
    for (int y = 0; y < src.height; ++y)
        for (int x = 0; x < src.width; ++x)
            if (dst.contains(x0 + x, y0 + y)) {
                const std::size_t s = src.offset(x, y), d = dst.offset(x0 + x, y0 + y);
                for (std::size_t c = 0; c < 4; ++c) dst.data[d + c] = src.data[s + c];
            }
}

// `text` shortened with ".." so that it is at most `maxWidth` pixels wide at `scale`.
std::string fittedLine(std::string_view text, int maxWidth, int scale) {
    if (textWidth(text, scale) <= maxWidth) return std::string(text);
    const int advance = font::kAdvance * scale;
    const int fits = (maxWidth + scale) / advance;  // the last glyph needs no spacing column
    if (fits <= 2) return std::string(text.substr(0, static_cast<std::size_t>(std::max(fits, 0))));
    return std::string(text.substr(0, static_cast<std::size_t>(fits - 2))) + "..";
}

// Every line of `text` shortened on its own.
std::string fitted(std::string_view text, int maxWidth, int scale) {
    std::string out;
    for (std::size_t start = 0;;) {
        const std::size_t end = text.find('\n', start);
        out += fittedLine(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start),
                          maxWidth, scale);
        if (end == std::string_view::npos) return out;
        out += '\n';
        start = end + 1;
    }
}

}  // namespace

int textWidth(std::string_view text, int scale) {
    int widest = 0, current = 0;
    for (char c : text) {
        if (c == '\n') {
            widest = std::max(widest, current);
            current = 0;
        } else {
            ++current;
        }
    }
    widest = std::max(widest, current);
    return widest == 0 ? 0 : (widest * font::kAdvance - 1) * std::max(scale, 1);
}

int textHeight(std::string_view text, int scale) {
    if (text.empty()) return 0;
    const int lines = 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
    return (lines * (font::kGlyphHeight + 1) - 1) * std::max(scale, 1);
}

void drawText(Image8& image, int x, int y, std::string_view text, int scale, Rgba8 colour) {
    scale = std::max(scale, 1);
    int penX = x, penY = y;
    for (char c : text) {
        if (c == '\n') {
            penX = x;
            penY += (font::kGlyphHeight + 1) * scale;
            continue;
        }
        const auto rows = font::glyph(c);
        for (int r = 0; r < font::kGlyphHeight; ++r)
            for (int col = 0; col < font::kGlyphWidth; ++col)
                if (rows[static_cast<std::size_t>(r)] & (1u << (font::kGlyphWidth - 1 - col)))
                    fillRect(image, penX + col * scale, penY + r * scale, scale, scale, colour);
        penX += font::kAdvance * scale;
    }
}

Image8 composeContactSheet(std::span<const Image8> images, std::span<const std::string> labels, int columns,
                           const ContactSheetStyle& style) {
    if (columns < 1) throw std::invalid_argument("composeContactSheet: columns must be at least 1");
    if (labels.size() > images.size())
        throw std::invalid_argument("composeContactSheet: " + std::to_string(labels.size()) + " labels for " +
                                    std::to_string(images.size()) + " images");
    const int pad = std::max(style.padding, 0);
    const int scale = std::max(style.labelScale, 1);
    int cellW = 0, cellH = 0;
    for (const auto& img : images) {
        cellW = std::max(cellW, img.width);
        cellH = std::max(cellH, img.height);
    }
    int labelH = font::kGlyphHeight * scale;  // the strip is as tall as the tallest label
    for (const auto& label : labels) labelH = std::max(labelH, textHeight(label, scale));
    const int count = static_cast<int>(images.size());
    const int cols = std::max(1, std::min(columns, count));
    const int rows = (count + cols - 1) / cols;
    const int stepX = cellW + pad, stepY = cellH + pad + labelH + pad;
    Image8 sheet(pad + cols * stepX, pad + rows * stepY, style.background);
    for (int i = 0; i < count; ++i) {
        const int x = pad + (i % cols) * stepX, y = pad + (i / cols) * stepY;
        const Image8& img = images[static_cast<std::size_t>(i)];
        blit(sheet, img, x + (cellW - img.width) / 2, y + (cellH - img.height) / 2);
        if (static_cast<std::size_t>(i) < labels.size())
            drawText(sheet, x, y + cellH + pad, fitted(labels[static_cast<std::size_t>(i)], cellW, scale), scale,
                     style.labelColour);
    }
    return sheet;
}

}  // namespace prism::image
