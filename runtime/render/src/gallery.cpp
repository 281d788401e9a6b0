// The gallery's entries and jobs (see prism/render/gallery.hpp).
#include "prism/render/gallery.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include "prism/render/shader_meshes.hpp"

namespace prism::render {
namespace {

bool wantsFog(const GalleryEntry& e) {
    for (const auto& [name, value] : e.variant)
        if (name == "FOG" && value == "1") return true;
    return false;
}

}  // namespace

std::vector<GalleryEntry> galleryEntries(const catalog::Catalog& catalog) {
    std::vector<GalleryEntry> entries;
    for (const auto& s : catalog.shaders) {
        const std::string name(s.name);
        entries.push_back({name, {}, name, name});
        for (const auto& axis : s.axes) {
            const bool boolean = axis.values.size() == 2 && axis.values[0] == "0" && axis.values[1] == "1";
            if (!boolean) continue;  // light counts follow the scene
            const std::string a(axis.name);
            entries.push_back({name, {{a, "1"}}, name + "." + a + "-1", name + " " + a + "=1"});
        }
    }
    return entries;
}

RenderJob galleryJob(const GalleryEntry& entry, const std::string& mesh, int size) {
    RenderJob job;
    job.shader = entry.shader;
    job.variant = entry.variant;
    job.mesh = meshForShader(entry.shader, namedMesh(mesh, 3));
    job.width = job.height = size;
    job.world = glm::rotate(glm::mat4(1.0f), glm::radians(20.0f), glm::vec3(1, 0, 0)) *
                glm::rotate(glm::mat4(1.0f), glm::radians(-30.0f), glm::vec3(0, 1, 0));
    job.material.color = {0.85f, 0.42f, 0.25f, 1.0f};
    job.material.shininess = 48.0f;
    job.material.specular = 0.6f;
    if (wantsFog(entry)) job.fog = view::Fog{};
    return job;
}

}  // namespace prism::render
