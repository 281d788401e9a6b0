// A scene as a Vulkan frame, refusing the systems that have no Vulkan path (see
// prism/scene/vulkan_scene.hpp).
#include "prism/scene/vulkan_scene.hpp"

#include <algorithm>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <utility>

#include "prism/bluenoise/vk_soft_shadows.hpp"
#include "prism/diffraction/diffraction_vk.hpp"
#include "prism/diffraction_shaders.hpp"
#include "prism/render/shader_meshes.hpp"
#include "prism/scene/diffraction_object.hpp"
#include "prism/scene/scene_loader.hpp"
#include "prism/scene/stochastic.hpp"

namespace prism::scene {
namespace {

// The first system of `scene` that only GL draws, as "what (JSON key)"; empty when none.
std::string glOnlySystem(const Scene& scene) {
    if (scene.water) return "the water system (\"water\"), a GL compute simulation";
    if (scene.rain) return "the rain system (\"rain\"), GL particles";
    if (scene.fog && scene.fogBillboards && *scene.fogBillboards > 0.0f)
        return "the rain system's fog billboards (\"fog\": {\"billboards\"})";
    return {};
}

// The tables of one material, built once per frame however many objects use it.
using BuiltTables =
    std::vector<std::pair<diffraction::DiffractionMaterial, std::shared_ptr<diffraction::VulkanDiffractionTables>>>;

// A diffraction object: the diffraction catalogue's program for its material's path, drawn from
// the tables SceneRenderer's GL path builds too (buildDiffractionTables).
render::VulkanDraw diffractionDraw(const Scene& scene, const SceneObject& object, BuiltTables& built) {
    render::VulkanDraw draw{"diffraction",
                            object.variantOverrides,
                            render::meshForShader("diffraction", render::namedMesh(object.mesh, object.subdivision)),
                            object.world,
                            object.material,
                            &diffraction_shaders::kCatalog,
                            nullptr};
    if (!object.diffraction) (void)buildDiffractionTables(scene, object);  // throws, naming the object
    const diffraction::DiffractionMaterial& m = *object.diffraction;
    auto same = std::find_if(built.begin(), built.end(), [&](const auto& b) { return b.first == m; });
    if (same == built.end()) {
        DiffractionObjectTables tables = buildDiffractionTables(scene, object);
        built.emplace_back(m, std::make_shared<diffraction::VulkanDiffractionTables>(std::move(tables.tables),
                                                                                     m.tangent, m.radialTangent));
        same = std::prev(built.end());
    }
    draw.variant.emplace_back("DIFFRACTION_PATH", same->second->uniforms().variant());  // the material decides it
    draw.extras = same->second;
    return draw;
}

}  // namespace

render::VulkanFrame vulkanFrameOf(const Scene& scene) {
    if (scene.stochastic)
        throw std::invalid_argument(scene.file +
                                    ": a \"stochastic\" scene is no frame of draws; "
                                    "draw it with renderStochasticVulkan");
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
    BuiltTables built;
    for (const auto& object : scene.objects) {
        if (object.shader == "diffraction") {
            frame.draws.push_back(diffractionDraw(scene, object, built));
            continue;
        }
        frame.draws.push_back({object.shader, object.variantOverrides,
                               render::meshForShader(object.shader, render::namedMesh(object.mesh, object.subdivision)),
                               object.world, object.material, nullptr, nullptr});
    }
    return frame;
}

image::Image8 renderStochasticVulkan(const StochasticSettings& settings, int width, int height,
                                     const vk::Device& device, vk::ClipConvention clip) {
    StochasticRun run = prepareStochastic(settings, width, height);
    bluenoise::VulkanSoftShadows gpu(device, width, height, clip);
    return toGreyImage(gpu.render(settings.light, run.setup, run.options));
}

}  // namespace prism::scene
