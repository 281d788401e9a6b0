// Labelled contact sheets of rendered images, with a tiny built-in 5x7 bitmap font.
//
// Usage (snippet: examples/snippets/image_contact_sheet.cpp):
//
//     #include "prism/image/contact_sheet.hpp"
//     #include "prism/image/png_io.hpp"
//     prism::image::Image8 img(140, 20, {40, 40, 40, 255});
//     prism::image::drawText(img, 2, 2, "phong FOG=1", 2, {255, 255, 0, 255});  // scale 2, yellow
//
//     std::vector<prism::image::Image8> shots = {img, img, img};
//     std::vector<std::string> names = {"unicolor", "phong", "gouraud"};
//     prism::image::Image8 sheet = prism::image::composeContactSheet(shots, names, 2);  // 2 columns
//     prism::image::writePng("out/sheet.png", sheet);
//
// The font covers A-Z (lower case drawn as upper case), 0-9 and  - _ . : / ( ) = , + % [ ] ?
// and space; any other character draws as '?'. '\n' starts a new line. Text is clipped
// at the image border. On a sheet every cell is as large as the largest image; the
// label sits in a strip under its image (as tall as the tallest label: a label may have
// several lines) and each line is shortened with ".." when too long.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "prism/image/image.hpp"

namespace prism::image {

// Pixel size of `text` drawn at `scale` (the widest line, and all lines).
int textWidth(std::string_view text, int scale = 1);
int textHeight(std::string_view text, int scale = 1);

// Draws `text` with its top-left corner at (x, y); each font pixel becomes scale x scale.
void drawText(Image8& image, int x, int y, std::string_view text, int scale = 1, Rgba8 colour = {255, 255, 255, 255});

struct ContactSheetStyle {
    Rgba8 background{24, 24, 24, 255};
    Rgba8 labelColour{235, 235, 235, 255};
    int padding = 4;     // pixels around every cell and between image and label
    int labelScale = 2;  // font scale of the labels: 2 draws 14 px capitals (legible; issue 15)
};

// Lays `images` out row by row in `columns` columns, each with labels[i] under it
// (labels may be fewer than images; missing ones are blank). Throws
// std::invalid_argument for columns < 1 or more labels than images.
Image8 composeContactSheet(std::span<const Image8> images, std::span<const std::string> labels, int columns,
                           const ContactSheetStyle& style = {});

}  // namespace prism::image
