// Conversions between the CPU image types and the non-finite pixel count.
#include "prism/image/image.hpp"

#include <cmath>

namespace prism::image {

std::size_t countNonFinite(const ImageF& image) {
    std::size_t bad = 0;
    for (std::size_t i = 0; i < image.data.size(); i += ImageF::kChannels) {
        bool finite = true;
        for (std::size_t c = 0; c < ImageF::kChannels; ++c) finite = finite && std::isfinite(image.data[i + c]);
        if (!finite) ++bad;
    }
    return bad;
}

Image8 toImage8(const ImageF& image) {
    Image8 out(image.width, image.height);
    for (std::size_t i = 0; i < image.data.size(); ++i) {
        float v = image.data[i];
        if (std::isnan(v)) v = 0.0f;
        v = std::fmin(std::fmax(v, 0.0f), 1.0f);
        out.data[i] = static_cast<std::uint8_t>(std::lround(v * 255.0f));
    }
    return out;
}

ImageF toImageF(const Image8& image) {
    ImageF out(image.width, image.height);
    for (std::size_t i = 0; i < image.data.size(); ++i) out.data[i] = static_cast<float>(image.data[i]) / 255.0f;
    return out;
}

}  // namespace prism::image
