// The sampling scene's error against its high-sample reference (sampling_reference.hpp).
#include "sampling_reference.hpp"

#include <cstdio>

#include "prism/bluenoise/soft_shadows.hpp"
#include "prism/scene/stochastic.hpp"

namespace prism::viewer {

struct SamplingReference::Cache {
    std::string key;
    bluenoise::Reference reference;
};

SamplingReference::SamplingReference() : cache_(std::make_unique<Cache>()) {}
SamplingReference::~SamplingReference() = default;

std::string SamplingReference::measure(const scene::StochasticSettings& settings) {
    const auto& light = settings.light;
    std::string key;
    for (double v : {light.extent, light.lightHeight, light.lightHalfLength, light.lightHalfWidth, light.radiance})
        key += std::to_string(v) + ",";
    for (const auto& s : light.spheres)
        key += std::to_string(s.x) + "," + std::to_string(s.y) + "," + std::to_string(s.z) + "," +
               std::to_string(s.radius) + ";";
    if (key != cache_->key) {
        cache_->reference = bluenoise::renderReference(light, kSamplingReferenceSize, kSamplingReferenceSize,
                                                       kSamplingReferenceSamples);
        cache_->key = key;
        ++referencesRendered_;
    }
    const bluenoise::RealImage estimate =
        scene::renderStochasticValues(settings, kSamplingReferenceSize, kSamplingReferenceSize);
    const bluenoise::ErrorStats e = bluenoise::compareToReference(estimate, cache_->reference);
    char text[200];
    std::snprintf(text, sizeof text,
                  "vs %d-sample reference (%dx%d): RMS %.1f, blurred RMS %.1f in 8-bit units over %d penumbra px",
                  kSamplingReferenceSamples, kSamplingReferenceSize, kSamplingReferenceSize, e.rms * 255.0,
                  e.blurredRms * 255.0, e.pixels);
    return text;
}

}  // namespace prism::viewer
