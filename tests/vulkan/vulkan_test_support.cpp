// Shared pieces of the Vulkan tier (see vulkan_test_support.hpp).
#include "vulkan_test_support.hpp"

#include <algorithm>
#include <iomanip>
#include <memory>
#include <sstream>

#include "prism/gl/framebuffer.hpp"
#include "prism/gl/gl.hpp"
#include "prism/render/gpu_mesh.hpp"
#include "prism/shaders.hpp"
#include "prism/test/gl_test.hpp"

namespace prism::vulkan_test {

Agreement agreementOf(const image::Image8& vulkan, const image::Image8& gl) {
    const image::ImageComparison cmp = image::compareImages(vulkan, gl, 2);
    Agreement a;
    a.sizeMatches = cmp.sizeMatches;
    if (!cmp.sizeMatches) return a;
    a.shareWithin2 = 1.0 - cmp.shareOver;
    a.mean = cmp.meanAbsError;
    a.max = cmp.maxChannelDiff;
    a.diff = cmp.diff;
    return a;
}

bool agrees(const Agreement& a, const AgreementThresholds& t) {
    return a.sizeMatches && a.shareWithin2 >= t.minShareWithin2 && a.mean <= t.maxMean && a.max <= t.maxMax;
}

std::ostream& operator<<(std::ostream& os, const Agreement& a) {
    if (!a.sizeMatches) return os << "sizes differ";
    return os << std::fixed << std::setprecision(4) << "within 2/255: " << 100.0 * a.shareWithin2 << " %, mean "
              << a.mean << "/255, max " << a.max << "/255";
}

std::string describe(const Agreement& a, const AgreementThresholds& t) {
    std::ostringstream s;
    s << a << " (allowed: within 2/255 >= " << 100.0 * t.minShareWithin2 << " %, mean <= " << t.maxMean
      << ", max <= " << t.maxMax << ")";
    return s.str();
}

image::Image8 renderFrameGl(const render::VulkanFrame& frame, bool cullBackFaces) {
    auto& cache = test::GlTest::suiteResource<render::ProgramCache>(shaders::kCatalog);
    gl::Framebuffer fb(frame.width, frame.height, gl::ColorFormat::Rgba8);
    fb.clear({frame.background.r, frame.background.g, frame.background.b, frame.background.a});
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    if (cullBackFaces) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glFrontFace(GL_CCW);
    }
    for (const auto& draw : frame.draws) {
        render::GpuMesh mesh(draw.mesh, shaders::kCatalog.contractAttributes);
        render::drawJob(cache, render::jobOf(frame, draw), mesh);
    }
    glDisable(GL_CULL_FACE);
    glFinish();
    return fb.readImage8();
}

AgreementThresholds thresholdsFor(const AgreementThresholds& t, const std::string& vulkanDevice,
                                  const std::string& referenceRasteriser) {
    const auto family = [](const std::string& name) { return name.substr(0, name.find(' ')); };
    if (family(vulkanDevice) == family(referenceRasteriser)) return t;
    const AgreementThresholds& across = kAcrossRasterisersThresholds;
    return {std::min(t.minShareWithin2, across.minShareWithin2), std::max(t.maxMean, across.maxMean),
            std::max(t.maxMax, across.maxMax)};
}

render::VulkanRenderer& validatedRenderer() {
    static auto renderer =
        std::make_unique<render::VulkanRenderer>(shaders::kCatalog, render::VulkanRenderOptions{.device = {true}});
    return *renderer;
}

void expectNoValidationMessages(const render::VulkanRenderer& renderer) {
    const auto messages = renderer.device().validationMessages();
    std::string all;
    for (const auto& m : messages) all += "\n  " + m;
    EXPECT_TRUE(renderer.device().validating());
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation messages:" << all;
}

std::vector<CatalogueCase> catalogueCases() {
    std::vector<CatalogueCase> cases;
    for (const auto& entry : render::galleryEntries(shaders::kCatalog))
        for (const auto& mesh : render::kGalleryMeshes) cases.push_back({entry, mesh});
    return cases;
}

}  // namespace prism::vulkan_test
