// The API differences, handled once in prism/vk/clip_convention.hpp, against GL: triangles
// whose orientation (clip-space y, read-back rows), winding (culling), depth test and depth
// range must come out as GL draws them. Each injected fault of the convention fails here.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "prism/image/png_io.hpp"
#include "prism/shaders.hpp"
#include "prism/test/gl_test.hpp"
#include "vulkan_test_support.hpp"

namespace prism::vulkan_test {
namespace {

constexpr int kSize = 96;
const image::Rgba8 kRed{255, 0, 0, 255}, kGreen{0, 255, 0, 255}, kBlack{0, 0, 0, 255};

render::VulkanDraw triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 color) {
    render::VulkanDraw d;
    d.shader = "unicolor";
    d.mesh.positions = {a, b, c};
    d.mesh.indices = {0, 1, 2};
    d.material.color = glm::vec4(color, 1.0f);
    return d;
}

// Every triangle lies 2.6 to 3.6 units from the eye and the near plane is at 2, so under
// Vulkan's own 0..1 depth range (z < 0 clipped) all of them would vanish.
render::VulkanFrame clipFrame() {
    render::VulkanFrame frame;
    frame.camera.eye = {0.0f, 0.0f, 3.2f};
    frame.camera.target = {0.0f, 0.0f, 0.0f};
    frame.camera.fovYDegrees = 45.0f;
    frame.camera.nearPlane = 2.0f;
    frame.camera.farPlane = 50.0f;
    frame.width = frame.height = kSize;
    frame.background = {0.0f, 0.0f, 0.0f, 1.0f};
    // Upper left, counter-clockwise: the near green one first, then the far red one over it.
    frame.draws.push_back(triangle({-1.0f, 0.5f, 0.3f}, {-0.3f, 0.5f, 0.3f}, {-0.65f, 1.2f, 0.3f}, {0, 1, 0}));
    frame.draws.push_back(triangle({-1.2f, 0.2f, -0.4f}, {-0.2f, 0.2f, -0.4f}, {-0.7f, 1.1f, -0.4f}, {1, 0, 0}));
    // Upper right, clockwise: a back face, culled.
    frame.draws.push_back(triangle({0.3f, 0.2f, 0.0f}, {0.7f, 1.1f, 0.0f}, {1.2f, 0.2f, 0.0f}, {0, 0, 1}));
    return frame;
}

// The pixel (x, y from the top) that world point `p` lands on.
std::pair<int, int> pixelOf(const render::VulkanFrame& frame, glm::vec3 p) {
    const glm::vec3 w =
        glm::project(p, frame.camera.view(), frame.camera.projection(1.0f), glm::vec4(0, 0, kSize, kSize));
    return {static_cast<int>(w.x), kSize - 1 - static_cast<int>(w.y)};
}

// What GL draws, checked on its own so that a Vulkan image equal to it is right too.
void expectGlConventions(const render::VulkanFrame& frame, const image::Image8& image, const std::string& who) {
    const auto [ox, oy] = pixelOf(frame, {-0.65f, 0.6f, 0.3f});   // inside both upper-left triangles
    const auto [fx, fy] = pixelOf(frame, {-1.1f, 0.25f, -0.4f});  // the far one only
    const auto [cx, cy] = pixelOf(frame, {0.75f, 0.5f, 0.0f});    // inside the back face
    EXPECT_EQ(image.at(ox, oy), kGreen) << who << ": the nearer triangle wins the depth test";
    EXPECT_EQ(image.at(fx, fy), kRed) << who << ": the far triangle shows where nothing covers it";
    EXPECT_EQ(image.at(cx, cy), kBlack) << who << ": the clockwise triangle is a culled back face";
    EXPECT_EQ(image.at(kSize / 4, 3 * kSize / 4), kBlack) << who << ": nothing in the lower half";
    EXPECT_LT(oy, kSize / 2) << "the triangles lie in the upper half, row 0 at the top";
}

class VulkanClipConvention : public test::GlTest {};

TEST_F(VulkanClipConvention, TrianglesMatchGlInOrientationWindingDepthAndRange) {
    const render::VulkanFrame frame = clipFrame();
    const image::Image8 gl = renderFrameGl(frame, true);
    render::VulkanRenderer vulkan(shaders::kCatalog, {.device = {true}, .cull = VK_CULL_MODE_BACK_BIT});
    const image::Image8 vk = vulkan.render(frame);
    expectGlConventions(frame, gl, "GL");
    expectGlConventions(frame, vk, "Vulkan");
    const Agreement a = agreementOf(vk, gl);
    EXPECT_EQ(a.max, 0) << a;  // constant colours: the same pixels, exactly
    expectNoValidationMessages(vulkan);
}

// Each fault of the convention changes the picture; the agreement check above catches it.
TEST_F(VulkanClipConvention, EachInjectedFaultBreaksTheAgreement) {
    const render::VulkanFrame frame = clipFrame();
    const image::Image8 gl = renderFrameGl(frame, true);
    struct Fault {
        const char* name;
        vk::ClipConvention clip;
    };
    for (const Fault& f : {Fault{"no y flip", {.flipY = false}}, Fault{"Vulkan's depth range", {.glDepth = false}}}) {
        render::VulkanRenderer vulkan(shaders::kCatalog,
                                      {.device = {true}, .cull = VK_CULL_MODE_BACK_BIT, .clip = f.clip});
        const Agreement a = agreementOf(vulkan.render(frame), gl);
        EXPECT_GT(a.max, 0) << f.name << " went unnoticed";
        expectNoValidationMessages(vulkan);
    }
}

}  // namespace
}  // namespace prism::vulkan_test
