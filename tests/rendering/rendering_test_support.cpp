// The rendering tier's shared helpers (see rendering_test_support.hpp).
#include "rendering_test_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "prism/render/shader_meshes.hpp"
#include "prism/shaders.hpp"
#include "prism/test/gl_test.hpp"

namespace prism::rendering_test {
const std::vector<ShaderSpec>& catalogueShaders() {
    static const std::vector<ShaderSpec> specs = {
        {"unicolor", "unicolor", {}, false, false}, {"flat", "flat", {}, true, false},
        {"smooth", "smooth", {}, true, false},      {"gouraud", "gouraud", {}, true, true},
        {"phong", "phong", {}, true, true},         {"phong-blinn", "phong", {{"BLINN", "1"}}, true, true},
    };
    return specs;
}

const ShaderSpec& shaderSpec(const std::string& label) {
    for (const auto& s : catalogueShaders())
        if (s.label == label) return s;
    throw std::invalid_argument("no catalogue shader labelled '" + label + "'");
}

glm::vec3 brightestAllowed(const ShaderSpec& spec, const view::Lights& lights, const view::Material& material) {
    if (!spec.lit) return glm::vec3(material.color);
    view::Material m = material;
    if (!spec.specular) m.specular = 0.0f;
    return view::maxRadiance(lights, m);
}

render::ProgramCache& programCache() {
    return test::GlTest::suiteResource<render::ProgramCache>(shaders::kCatalog);
}

render::RenderJob jobFor(const ShaderSpec& spec, const geometry::Mesh& mesh, int width, int height) {
    render::RenderJob job;
    job.shader = spec.shader;
    job.variant = spec.variant;
    job.mesh = render::meshForShader(spec.shader, mesh);
    job.width = width;
    job.height = height;
    return job;
}

std::size_t coveredPixels(const image::ImageF& image, const glm::vec4& background, float tolerance) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < image.data.size(); i += 4)
        for (int c = 0; c < 3; ++c)
            if (!(std::abs(image.data[i + static_cast<std::size_t>(c)] - background[c]) <= tolerance)) {
                ++n;
                break;
            }
    return n;
}

std::size_t coveredPixels(const image::Image8& image, const glm::vec4& background, int tolerance) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < image.data.size(); i += 4)
        for (int c = 0; c < 3; ++c) {
            const int bg = static_cast<int>(std::lround(std::clamp(background[c], 0.0f, 1.0f) * 255.0f));
            if (std::abs(static_cast<int>(image.data[i + static_cast<std::size_t>(c)]) - bg) > tolerance) {
                ++n;
                break;
            }
        }
    return n;
}

PixelInspection inspectPixels(const image::ImageF& image, const glm::vec3& bound, float epsilon) {
    PixelInspection r;
    const auto where = [](int x, int y, int c, float v) {
        return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") channel " + std::to_string(c) + " = " +
               std::to_string(v);
    };
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const image::RgbaF p = image.at(x, y);
            bool finite = true, over = false, negative = false;
            for (int c = 0; c < 4; ++c) {
                const float v = p[static_cast<std::size_t>(c)];
                const float limit = (c < 3 ? bound[c] : 1.0f) + epsilon;
                if (!std::isfinite(v)) {
                    finite = false;
                } else if (v > limit && !over) {
                    over = true;
                    if (r.overBright == 0) r.firstOverBright = where(x, y, c, v) + " > " + std::to_string(limit);
                } else if (v < -1e-6f && !negative) {
                    negative = true;
                    if (r.negative == 0) r.firstNegative = where(x, y, c, v);
                }
            }
            r.nonFinite += finite ? 0 : 1;
            r.overBright += over ? 1 : 0;
            r.negative += negative ? 1 : 0;
        }
    return r;
}

}  // namespace prism::rendering_test
