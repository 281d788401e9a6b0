// A tiny built-in 5x7 bitmap font for labels on contact sheets (internal).
#pragma once

#include <array>
#include <cstdint>

namespace prism::font {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 7;
inline constexpr int kAdvance = 6;  // glyph width + one column of spacing

// Rows top to bottom; bit 4 is the leftmost column. Lower-case letters map to upper
// case; characters without a glyph draw as '?'.
std::array<std::uint8_t, kGlyphHeight> glyph(char c);

// Whether `c` has its own glyph (after mapping lower case to upper case).
bool hasGlyph(char c);

}  // namespace prism::font
