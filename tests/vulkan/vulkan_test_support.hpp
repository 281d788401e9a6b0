// Shared pieces of the Vulkan tier (tests/vulkan): the agreement measure and its thresholds
// (docs/vulkan.md), the same frame drawn through GL for comparison, the suite's Vulkan
// renderer with the validation layer on, and the catalogue cases of the gallery.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "prism/image/image_compare.hpp"
#include "prism/render/gallery.hpp"
#include "prism/render/vulkan_render.hpp"

namespace prism::vulkan_test {

// How far a Vulkan render is from a GL one: the share of pixels whose every channel is
// within 2/255, the mean absolute error over all channels (8-bit units) and the largest
// channel difference.
struct Agreement {
    double shareWithin2 = 0.0;
    double mean = 0.0;
    int max = 0;
    bool sizeMatches = false;
    image::Image8 diff;
};
Agreement agreementOf(const image::Image8& vulkan, const image::Image8& gl);

// The thresholds of the tier, set just above the differences measured on lavapipe against
// llvmpipe (docs/vulkan.md states them and the command that measured them).
struct AgreementThresholds {
    double minShareWithin2;
    double maxMean;
    int maxMax;
};
// Measured on lavapipe vs llvmpipe (Mesa 22.3.6): the 44 gallery cases at 128 px, the six
// sphere goldens and the three classic scenes at 256x192 have every pixel within 2/255, a
// mean <= 0.0001/255 and a max of 1/255 (docs/vulkan.md). Allowed: 99.99 % within 2/255 (at
// most one pixel of a 128x128 image), mean 0.005/255, max 2/255.
inline constexpr AgreementThresholds kAgreementThresholds{0.9999, 0.005, 2};
// The diffraction scenes at 256x192 (docs/vulkan.md): the grating and the small CD measured
// identical or within 1/255; the snake has one pixel of 49152 at 7/255, every other within
// 2/255, mean 0.0001/255. Allowed: 99.99 % within 2/255 (4 pixels), mean 0.005/255, max 8/255.
inline constexpr AgreementThresholds kDiffractionThresholds{0.9999, 0.005, 8};
// Across rasterisers (a GPU's Vulkan against llvmpipe's GL or the llvmpipe goldens; docs/gpu.md,
// "Vulkan"): measured on an NVIDIA H200 (driver 580.159.04) with scripts/gpu-vulkan-agreement.sh,
// 62 comparisons: at least 99.9959 % of pixels within 2/255 and a mean of at most 0.0182/255,
// but the rasterisers cover a silhouette pixel or two differently, so those differ by up to
// the full contrast (71/255 in four_lights, 57/255 in the diffraction snake). So the share and
// the mean are bounded (99.99 %: 1 pixel of a 128x128 image, 4 of 256x192; mean 0.025/255),
// and the maximum is not.
inline constexpr AgreementThresholds kAcrossRasterisersThresholds{0.9999, 0.025, 255};
// Where the compared image comes from: a live GL render in this process, or a golden PNG
// (rendered on llvmpipe).
enum class Reference { LiveGl, LlvmpipeGolden };
// `t` when the Vulkan device and the reference's rasteriser are one implementation family
// (the first word of the device name and GL_RENDERER: "llvmpipe" for lavapipe and llvmpipe,
// "NVIDIA" for NVIDIA's Vulkan and GL drivers); else the looser of `t` and
// kAcrossRasterisersThresholds in each bound.
AgreementThresholds thresholdsFor(const AgreementThresholds& t, const std::string& vulkanDevice,
                                  const std::string& referenceRasteriser);
bool agrees(const Agreement& a, const AgreementThresholds& t);
std::string describe(const Agreement& a, const AgreementThresholds& t);
std::ostream& operator<<(std::ostream& os, const Agreement& a);

// `frame` drawn through GL with the suite's program cache: each draw as drawJob() draws a
// RenderJob, into one framebuffer cleared to the frame's background (needs a GlTest).
// cullBackFaces enables GL_CULL_FACE (back faces, counter-clockwise front), as
// VulkanRenderOptions::cull = VK_CULL_MODE_BACK_BIT does.
image::Image8 renderFrameGl(const render::VulkanFrame& frame, bool cullBackFaces = false);

// A renderer with VK_LAYER_KHRONOS_validation on, for the running test program.
render::VulkanRenderer& validatedRenderer();
// Fails the test when `renderer`'s device has recorded any validation message, listing them.
void expectNoValidationMessages(const render::VulkanRenderer& renderer);

// One gallery image (prism/render/gallery.hpp): a catalogue shader, one of its variants and a
// gallery mesh.
struct CatalogueCase {
    render::GalleryEntry entry;
    std::string mesh;
    std::string label() const { return entry.label + " / " + mesh; }  // "phong BLINN=1 / torus"
    render::RenderJob job(int size) const { return render::galleryJob(entry, mesh, size); }
};
// Every classic catalogue shader x variant x gallery mesh (sphere, torus, cube, trefoil).
std::vector<CatalogueCase> catalogueCases();

}  // namespace prism::vulkan_test
