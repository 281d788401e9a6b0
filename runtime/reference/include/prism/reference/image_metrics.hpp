// Error metrics of a rendered RGBA8 image against the exact-sphere reference
// (prism/reference/sphere_reference.hpp), in 8-bit units (prism_bench_tradeoffs, the viewer).
//
// Usage (snippet: examples/snippets/reference_image_metrics.cpp):
//
//     #include "prism/reference/image_metrics.hpp"
//     prism::reference::Metrics m = prism::reference::compareWithReference(render, reference);
//     // m.union_.mean, m.union_.max: |render - reference| over R, G, B of pixels either covers
//     // m.interior.max: where both cover; m.renderOnly + m.referenceOnly: silhouette mismatch
//
// Coverage is read from alpha: the bench clears to alpha 0 and every lit shader writes
// alpha 1, and the reference sets alpha 255 where its ray hits. Colour differences use
// R, G and B only (alpha is the coverage flag, not a colour).
//
// Highlight: the luma-weighted centroid of the covered pixels whose luma (Rec. 709:
// 0.2126 R + 0.7152 G + 0.0722 B, 8-bit units) lies within kHighlightBand of the image's
// brightest covered pixel; weight = luma - (max luma - kHighlightBand). For the full
// model that is the key light's specular highlight; for the diffuse model it is the
// brightest diffuse spot (where the normal faces the key light). Centroids are in
// pixel units with (0, 0) the top-left corner of the image.
#pragma once

#include <glm/vec2.hpp>

#include <array>
#include <cstddef>

#include "prism/image/image.hpp"

namespace prism::reference {

inline constexpr double kHighlightBand = 8.0;

struct ErrorStats {
    std::size_t pixels = 0;
    double mean = 0.0;  // mean absolute channel difference (R, G, B), 8-bit units
    int max = 0;        // largest absolute channel difference
    // Pixels whose largest channel difference is <= 0, 1, 2, 3 units.
    std::array<std::size_t, 4> within{};
    double shareWithin(int units) const {
        return pixels ? static_cast<double>(within[static_cast<std::size_t>(units)]) / static_cast<double>(pixels)
                      : 0.0;
    }
};

struct Metrics {
    ErrorStats union_;              // pixels covered by the render or the reference (or both)
    ErrorStats interior;            // pixels covered by both
    std::size_t renderOnly = 0;     // covered by the render only (mesh outside the sphere)
    std::size_t referenceOnly = 0;  // covered by the reference only (mesh inside the sphere)
    bool highlightFound = false;
    glm::dvec2 highlightRender{0.0}, highlightReference{0.0};
    double highlightError = 0.0;  // distance between the centroids, pixels
};

bool covered(const image::Image8& image, int x, int y);
double luma(const image::Image8& image, int x, int y);

// false when nothing is covered.
bool highlightCentroid(const image::Image8& image, glm::dvec2& centroid);

// Both images must have the same size (std::invalid_argument otherwise).
Metrics compareWithReference(const image::Image8& render, const image::Image8& reference);

}  // namespace prism::reference
