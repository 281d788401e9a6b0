// The built-in label font and contact-sheet layout (no GL).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "prism/image/contact_sheet.hpp"

namespace {

constexpr prism::image::Rgba8 kInk{255, 255, 0, 255};
constexpr prism::image::Rgba8 kPaper{0, 0, 0, 255};

TEST(DrawText, GlyphPixelsAtScaleOne) {
    prism::image::Image8 img(20, 10, kPaper);
    prism::image::drawText(img, 2, 1, "T", 1, kInk);
    for (int x = 2; x < 7; ++x) EXPECT_EQ(img.at(x, 1), kInk) << x;  // the T's bar
    for (int y = 2; y < 8; ++y) EXPECT_EQ(img.at(4, y), kInk) << y;  // its stem
    EXPECT_EQ(img.at(3, 2), kPaper);
    EXPECT_EQ(img.at(2, 0), kPaper);
    EXPECT_EQ(img.at(4, 8), kPaper);
}

TEST(DrawText, ScaleMakesBlocksAndTextIsClipped) {
    prism::image::Image8 img(12, 16, kPaper);
    prism::image::drawText(img, 0, 0, "T", 2, kInk);
    EXPECT_EQ(img.at(0, 0), kInk);
    EXPECT_EQ(img.at(1, 1), kInk);
    EXPECT_EQ(img.at(9, 1), kInk);
    EXPECT_EQ(img.at(4, 13), kInk);  // stem, row 6 of the glyph at scale 2
    EXPECT_EQ(img.at(3, 13), kPaper);
    EXPECT_NO_THROW(prism::image::drawText(img, 8, 12, "WWW", 3, kInk));  // mostly outside
    EXPECT_NO_THROW(prism::image::drawText(img, -30, -30, "A", 1, kInk));
}

TEST(DrawText, LowerCaseAndUnknownCharacters) {
    prism::image::Image8 upper(12, 8, kPaper), lower(12, 8, kPaper), unknown(12, 8, kPaper), question(12, 8, kPaper);
    prism::image::drawText(upper, 0, 0, "AZ", 1, kInk);
    prism::image::drawText(lower, 0, 0, "az", 1, kInk);
    prism::image::drawText(unknown, 0, 0, "@", 1, kInk);
    prism::image::drawText(question, 0, 0, "?", 1, kInk);
    EXPECT_EQ(upper, lower);
    EXPECT_EQ(unknown, question);
    EXPECT_NE(upper, prism::image::Image8(12, 8, kPaper));
}

TEST(DrawText, Metrics) {
    EXPECT_EQ(prism::image::textWidth("AB"), 11);
    EXPECT_EQ(prism::image::textWidth("AB", 2), 22);
    EXPECT_EQ(prism::image::textWidth("ABC\nA"), 17);
    EXPECT_EQ(prism::image::textHeight("A"), 7);
    EXPECT_EQ(prism::image::textHeight("A\nB"), 15);
    EXPECT_EQ(prism::image::textWidth(""), 0);
}

TEST(ContactSheet, LayoutAndLabels) {
    const std::vector<prism::image::Image8> images = {prism::image::Image8(10, 8, {255, 0, 0, 255}),
                                                      prism::image::Image8(10, 8, {0, 255, 0, 255}),
                                                      prism::image::Image8(10, 8, {0, 0, 255, 255})};
    const std::vector<std::string> labels = {"A", "B"};
    prism::image::ContactSheetStyle style;
    style.labelScale = 1;
    const prism::image::Image8 sheet = prism::image::composeContactSheet(images, labels, 2, style);
    // pad 4; cells 10x8; label strip 7 + pad.
    EXPECT_EQ(sheet.width, 4 + 2 * (10 + 4));
    EXPECT_EQ(sheet.height, 4 + 2 * (8 + 4 + 7 + 4));
    EXPECT_EQ(sheet.at(4, 4), (prism::image::Rgba8{255, 0, 0, 255}));       // image 0 top-left
    EXPECT_EQ(sheet.at(18, 4), (prism::image::Rgba8{0, 255, 0, 255}));      // image 1
    EXPECT_EQ(sheet.at(4, 4 + 23), (prism::image::Rgba8{0, 0, 255, 255}));  // image 2, second row
    EXPECT_EQ(sheet.at(0, 0), style.background);
    EXPECT_EQ(sheet.at(4 + 2, 4 + 8 + 4), style.labelColour);      // top of the 'A'
    EXPECT_EQ(sheet.at(4 + 2, 4 + 23 + 8 + 4), style.background);  // image 2 has no label
    EXPECT_THROW(prism::image::composeContactSheet(images, labels, 0), std::invalid_argument);
    const std::vector<std::string> tooMany = {"a", "b", "c", "d"};
    EXPECT_THROW(prism::image::composeContactSheet(images, tooMany, 2), std::invalid_argument);
}

TEST(ContactSheet, LongLabelIsShortenedToItsCell) {
    const std::vector<prism::image::Image8> images = {prism::image::Image8(20, 4, {255, 255, 255, 255}),
                                                      prism::image::Image8(20, 4, {255, 255, 255, 255})};
    const std::vector<std::string> labels = {"A VERY LONG LABEL", "X"};
    const prism::image::Image8 sheet = prism::image::composeContactSheet(images, labels, 2);
    // Nothing of label 0 may spill into cell 1's column range (x >= 4 + 24).
    prism::image::Image8 onlySecond = prism::image::composeContactSheet(images, std::vector<std::string>{"", "X"}, 2);
    for (int y = 0; y < sheet.height; ++y)
        for (int x = 4 + 20; x < sheet.width; ++x) ASSERT_EQ(sheet.at(x, y), onlySecond.at(x, y)) << x << "," << y;
}

// The default style (used by prism-gallery's contact sheet) draws labels whose glyphs
// are at least 12 pixels tall: measured on the sheet, from the first to the last row
// of the label strip that holds label-coloured pixels.
TEST(ContactSheet, DefaultLabelsAreAtLeast12PixelsTall) {
    const std::vector<prism::image::Image8> images = {prism::image::Image8(64, 16, {0, 0, 0, 255})};
    const std::vector<std::string> labels = {"PHONG / TORUS"};
    const prism::image::ContactSheetStyle style;
    const prism::image::Image8 sheet = prism::image::composeContactSheet(images, labels, 1, style);
    int top = -1, bottom = -1;
    for (int y = style.padding + 16; y < sheet.height; ++y)
        for (int x = 0; x < sheet.width; ++x)
            if (sheet.at(x, y) == style.labelColour) {
                if (top < 0) top = y;
                bottom = y;
            }
    ASSERT_GE(top, 0) << "no label pixels";
    EXPECT_GE(bottom - top + 1, 12);
}

// A two-line label makes the strip two lines tall, and each line is shortened on its own.
TEST(ContactSheet, MultiLineLabelsGetATallerStrip) {
    const std::vector<prism::image::Image8> images = {prism::image::Image8(24, 8, {0, 0, 0, 255}),
                                                      prism::image::Image8(24, 8, {0, 0, 0, 255})};
    prism::image::ContactSheetStyle style;
    style.labelScale = 1;
    const std::vector<std::string> oneLine = {"A", "B"}, twoLines = {"A\nTWO", "B"};
    const auto flat = prism::image::composeContactSheet(images, oneLine, 2, style);
    const auto tall = prism::image::composeContactSheet(images, twoLines, 2, style);
    EXPECT_EQ(tall.height - flat.height, prism::image::textHeight("A\nB") - prism::image::textHeight("A"));
    const int secondLineY = style.padding + 8 + style.padding + 8;  // glyph rows 7 + 1 spacing below the first
    bool inked = false;
    for (int x = style.padding; x < style.padding + 24; ++x) inked |= tall.at(x, secondLineY) == style.labelColour;
    EXPECT_TRUE(inked) << "the second line was not drawn";
    const std::vector<std::string> longLines = {"AB\nVERY LONG LINE", "B"};
    const auto cut = prism::image::composeContactSheet(images, longLines, 2, style);
    for (int y = 0; y < cut.height; ++y)  // nothing spills into the gap before the second cell
        for (int x = style.padding + 24; x < style.padding + 24 + style.padding; ++x)
            EXPECT_NE(cut.at(x, y), style.labelColour) << x << "," << y;
}

}  // namespace
