// The live accuracy readout of a sampling scene ("stochastic" soft shadows, docs/bluenoise.md):
// the scene's current sampler, spp and frames estimated at kSamplingReferenceSize² and
// compared with the 1024-sample stratified reference of prism/bluenoise/soft_shadows.hpp,
// which is rendered ONCE per light and spheres. RMS error over the penumbra pixels, plain
// and after a 1-pixel Gaussian blur (what the eye sees; blue noise lowers it), in 8-bit units.
//
//     SamplingReference check;
//     std::string text = check.measure(*scene.stochastic);  // "vs 1024-sample reference ...: RMS 41.2, blurred 9.8"
#pragma once

#include <memory>
#include <string>

#include "prism/scene/scene.hpp"

namespace prism::viewer {

inline constexpr int kSamplingReferenceSize = 128;  // pixels, square
inline constexpr int kSamplingReferenceSamples = 1024;

class SamplingReference {
  public:
    SamplingReference();
    ~SamplingReference();
    std::string measure(const scene::StochasticSettings& settings);
    int referencesRendered() const { return referencesRendered_; }

  private:
    struct Cache;
    std::unique_ptr<Cache> cache_;
    int referencesRendered_ = 0;
};

}  // namespace prism::viewer
