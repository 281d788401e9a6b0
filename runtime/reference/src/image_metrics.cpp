// Error metrics of a render against the sphere reference (see image_metrics.hpp).
#include "prism/reference/image_metrics.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace prism::reference {
namespace {

struct Accumulator {
    std::size_t pixels = 0;
    double sum = 0.0;
    int max = 0;
    std::array<std::size_t, 4> within{};

    void add(const image::Image8& a, const image::Image8& b, int x, int y) {
        const std::size_t o = a.offset(x, y);
        int pixelMax = 0;
        for (std::size_t c = 0; c < 3; ++c) {
            const int d = std::abs(static_cast<int>(a.data[o + c]) - static_cast<int>(b.data[o + c]));
            sum += d;
            pixelMax = std::max(pixelMax, d);
        }
        max = std::max(max, pixelMax);
        for (int u = pixelMax; u < 4; ++u) ++within[static_cast<std::size_t>(u)];
        ++pixels;
    }

    ErrorStats stats() const {
        ErrorStats s;
        s.pixels = pixels;
        s.mean = pixels ? sum / (3.0 * static_cast<double>(pixels)) : 0.0;
        s.max = max;
        s.within = within;
        return s;
    }
};

}  // namespace

bool covered(const image::Image8& image, int x, int y) {
    return image.data[image.offset(x, y) + 3] == 255;
}

double luma(const image::Image8& image, int x, int y) {
    const std::size_t o = image.offset(x, y);
    return 0.2126 * image.data[o] + 0.7152 * image.data[o + 1] + 0.0722 * image.data[o + 2];
}

bool highlightCentroid(const image::Image8& image, glm::dvec2& centroid) {
    double maxLuma = -1.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (covered(image, x, y)) maxLuma = std::max(maxLuma, luma(image, x, y));
    if (maxLuma < 0.0) return false;
    const double floor = maxLuma - kHighlightBand;
    glm::dvec2 sum(0.0);
    double weight = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (!covered(image, x, y)) continue;
            const double w = luma(image, x, y) - floor;
            if (w <= 0.0) continue;
            sum += w * glm::dvec2(x + 0.5, y + 0.5);
            weight += w;
        }
    centroid = sum / weight;
    return true;
}

Metrics compareWithReference(const image::Image8& render, const image::Image8& reference) {
    if (render.width != reference.width || render.height != reference.height)
        throw std::invalid_argument("compareWithReference: the images differ in size");
    Accumulator all, both;
    Metrics m;
    for (int y = 0; y < render.height; ++y)
        for (int x = 0; x < render.width; ++x) {
            const bool inRender = covered(render, x, y), inReference = covered(reference, x, y);
            if (!inRender && !inReference) continue;
            all.add(render, reference, x, y);
            if (inRender && inReference) both.add(render, reference, x, y);
            if (inRender && !inReference) ++m.renderOnly;
            if (!inRender && inReference) ++m.referenceOnly;
        }
    m.union_ = all.stats();
    m.interior = both.stats();
    m.highlightFound =
        highlightCentroid(render, m.highlightRender) && highlightCentroid(reference, m.highlightReference);
    if (m.highlightFound) m.highlightError = glm::distance(m.highlightRender, m.highlightReference);
    return m;
}

}  // namespace prism::reference
