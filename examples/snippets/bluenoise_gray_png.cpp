// The usage example of prism/bluenoise/gray_png.hpp, compiled and run by tests/snippets.
#include <fstream>
#include <sstream>

// [snippet]
#include "prism/bluenoise/gray_png.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::bluenoise::GrayImage image{4, 4, 16, std::vector<std::uint16_t>(16, 40000)};
    prism::bluenoise::writeGrayPng("out/mask.png", image);  // temp file + rename
    prism::bluenoise::GrayImage back = prism::bluenoise::readGrayPng("out/mask.png");
    prism::bluenoise::writeFileAtomically("out/spectrum.svg", "<svg/>");
    // [/snippet]
    std::ifstream in("out/spectrum.svg");
    std::stringstream text;
    text << in.rdbuf();
    return back.width == 4 && back.height == 4 && back.bits == 16 && back.values == image.values &&
                   text.str() == "<svg/>"
               ? 0
               : 1;
}
