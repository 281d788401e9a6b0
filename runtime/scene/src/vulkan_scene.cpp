// A scene as a Vulkan frame, refusing the systems that have no Vulkan path (see
// prism/scene/vulkan_scene.hpp).
#include "prism/scene/vulkan_scene.hpp"

#include "prism/render/shader_meshes.hpp"
#include "prism/scene/scene_loader.hpp"

namespace prism::scene {
namespace {

// The first system of `scene` that only GL draws, as "what (JSON key)"; empty when none.
std::string glOnlySystem(const Scene& scene) {
    if (scene.stochastic) return "the stochastic soft shadows (\"stochastic\"), drawn on the CPU";
    if (scene.water) return "the water system (\"water\"), a GL compute simulation";
    if (scene.rain) return "the rain system (\"rain\"), GL particles";
    if (scene.fog && scene.fogBillboards && *scene.fogBillboards > 0.0f)
        return "the rain system's fog billboards (\"fog\": {\"billboards\"})";
    for (const auto& object : scene.objects)
        if (object.shader == "diffraction")
            return "the diffraction system (an object with \"shader\": \"diffraction\", at " +
                   (object.diffractionPointer.empty() ? std::string("/objects") : object.diffractionPointer) + ")";
    return {};
}

}  // namespace

render::VulkanFrame vulkanFrameOf(const Scene& scene) {
    if (const std::string system = glOnlySystem(scene); !system.empty())
        throw SceneError(scene.file + ": " + system +
                         " has no Vulkan path; render this scene with --backend egl or osmesa");
    render::VulkanFrame frame;
    frame.camera = scene.camera;
    frame.lights = scene.lights;
    frame.fog = scene.fog;
    frame.width = scene.width;
    frame.height = scene.height;
    frame.background = scene.fog ? glm::vec4(scene.fog->color, 1.0f) : scene.background;
    for (const auto& object : scene.objects)
        frame.draws.push_back({object.shader, object.variantOverrides,
                               render::meshForShader(object.shader, render::namedMesh(object.mesh, object.subdivision)),
                               object.world, object.material});
    return frame;
}

}  // namespace prism::scene
