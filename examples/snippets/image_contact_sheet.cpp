// The usage example of prism/image/contact_sheet.hpp, compiled and run by tests/snippets.
// [snippet]
#include "prism/image/contact_sheet.hpp"
#include "prism/image/png_io.hpp"
// [/snippet]

int main() {
    // [snippet]
    prism::image::Image8 img(140, 20, {40, 40, 40, 255});
    prism::image::drawText(img, 2, 2, "phong FOG=1", 2, {255, 255, 0, 255});  // scale 2, yellow

    std::vector<prism::image::Image8> shots = {img, img, img};
    std::vector<std::string> names = {"unicolor", "phong", "gouraud"};
    prism::image::Image8 sheet = prism::image::composeContactSheet(shots, names, 2);  // 2 columns
    prism::image::writePng("out/sheet.png", sheet);
    // [/snippet]
    return sheet.width > 2 * img.width && sheet.height > 2 * img.height ? 0 : 1;
}
