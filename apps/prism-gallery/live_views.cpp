// The live views' record (see live_views.hpp).
#include "live_views.hpp"

#include <fstream>
#include <stdexcept>

#include "prism/gl/gl.hpp"

namespace {

using Json = nlohmann::ordered_json;

// Components of a uniform of GL type `type`, and whether glGetUniformiv reads it.
std::pair<int, bool> componentsOf(GLenum type) {
    switch (type) {
        case GL_FLOAT: return {1, false};
        case GL_FLOAT_VEC2: return {2, false};
        case GL_FLOAT_VEC3: return {3, false};
        case GL_FLOAT_VEC4: return {4, false};
        case GL_FLOAT_MAT3: return {9, false};
        case GL_FLOAT_MAT4: return {16, false};
        case GL_INT_VEC2: return {2, true};
        case GL_INT_VEC3: return {3, true};
        case GL_INT_VEC4: return {4, true};
        default: return {1, true};  // int, bool, samplers
    }
}

// Every active uniform of `program` (array elements one by one, "u_lightColor[1]") and its value.
Json uniformValues(unsigned program) {
    GLint count = 0;
    glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    Json values = Json::object();
    for (GLint i = 0; i < count; ++i) {
        char name[256];
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(program, static_cast<GLuint>(i), sizeof name, nullptr, &size, &type, name);
        std::string base(name);
        if (base.starts_with("gl_")) continue;
        if (base.ends_with("[0]")) base.resize(base.size() - 3);
        const auto [components, integer] = componentsOf(type);
        for (GLint e = 0; e < size; ++e) {
            const std::string element = size > 1 ? base + "[" + std::to_string(e) + "]" : base;
            const GLint location = glGetUniformLocation(program, element.c_str());
            Json value = Json::array();
            float f[16];
            GLint n[16];
            if (integer)
                glGetUniformiv(program, location, n);
            else
                glGetUniformfv(program, location, f);
            for (int c = 0; c < components; ++c) value.push_back(integer ? Json(n[c]) : Json(f[c]));
            values[element] = std::move(value);
        }
    }
    return values;
}

Json meshJson(const prism::geometry::Mesh& m) {
    Json positions = Json::array(), normals = Json::array();
    for (const auto& p : m.positions) positions.insert(positions.end(), {p.x, p.y, p.z});
    for (const auto& n : m.normals) normals.insert(normals.end(), {n.x, n.y, n.z});
    return {{"positions", std::move(positions)}, {"normals", std::move(normals)}, {"indices", m.indices}};
}

bool sameMesh(const prism::geometry::Mesh& a, const prism::geometry::Mesh& b) {
    return a.positions == b.positions && a.normals == b.normals && a.indices == b.indices;
}

}  // namespace

std::string LiveViews::meshKey(const std::string& meshName, const prism::geometry::Mesh& mesh) {
    int sameName = 0;
    for (const auto& [key, stored] : meshes_) {
        if (key != meshName && !key.starts_with(meshName + ".")) continue;
        if (sameMesh(stored, mesh)) return key;
        ++sameName;
    }
    const std::string key = sameName == 0 ? meshName : meshName + "." + std::to_string(sameName);
    meshes_.emplace_back(key, mesh);
    return key;
}

void LiveViews::add(const std::string& file, const std::string& meshName, prism::render::ProgramCache& cache,
                    const prism::render::RenderJob& job) {
    const auto variant = prism::render::variantForJob(cache, job);
    Json defines = Json::object();
    for (const auto& [axis, value] : variant) defines[axis] = value;
    const auto& bg = job.background;
    views_.push_back({{"png", file},
                      {"shader", job.shader},
                      {"defines", std::move(defines)},
                      {"mesh", meshKey(meshName, job.mesh)},
                      {"width", job.width},
                      {"height", job.height},
                      {"background", {bg.r, bg.g, bg.b, bg.a}},
                      {"uniforms", uniformValues(cache.get(job.shader, variant).id())}});
}

void LiveViews::write(const std::filesystem::path& path) const {
    Json meshes = Json::object();
    for (const auto& [key, mesh] : meshes_) meshes[key] = meshJson(mesh);
    std::ofstream out(path);
    out << Json{{"meshes", std::move(meshes)}, {"views", views_}}.dump() << "\n";
    if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}
