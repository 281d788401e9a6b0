// The ES 3.00 minimum-limits check of a linked program (es300_limits.hpp).
#include "es300_limits.hpp"

#include <glslang/Include/PoolAlloc.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ShaderLang.h>

#include <regex>

#include "stage_interface.hpp"

namespace prism::shaderc {

int packedRows(const std::vector<PackedShape>& shapes) {
    int full = 0, threes = 0, twos = 0, ones = 0;
    for (const auto& s : shapes) {
        const int rows = s.rows * std::max(1, s.count);
        if (s.columns >= 3) (s.columns == 4 ? full : threes) += rows;
        if (s.columns == 2) twos += rows;
        if (s.columns == 1) ones += rows;
    }
    const int free = threes + (twos % 2 == 1 ? 2 : 0);  // the spare columns scalars may fill
    const int scalarsLeft = std::max(0, ones - free);
    return full + threes + (twos + 1) / 2 + (scalarsLeft + 3) / 4;
}

PackedShape shapeOfGlslType(const std::string& type, int arraySize) {
    static const std::regex matrix(R"(d?mat([234])(?:x([234]))?)");
    static const std::regex vector(R"([diub]?vec([234]))");
    static const std::regex scalar(R"(float|double|int|uint|bool)");
    const int count = std::max(1, arraySize);
    std::smatch m;
    if (std::regex_match(type, m, matrix))
        return {std::stoi(m[1]), m[2].matched ? std::stoi(m[2]) : std::stoi(m[1]), count};
    if (std::regex_match(type, m, vector)) return {1, std::stoi(m[1]), count};
    if (std::regex_match(type, scalar)) return {1, 1, count};
    return {1, 4, count};
}

namespace {

struct StageUniforms {
    int vectors = 0, textureUnits = 0;
};

// The active uniforms of one stage, from a program of that stage alone: glslang 12's
// per-uniform stage mask of a whole program marks a vertex-only uniform as a fragment one
// too, so it cannot split the counts.
StageUniforms measureStage(glslang::TShader& shader) {
    StageUniforms counts;
    // link() points this thread's pool allocator at the program's own pool, which dies
    // with it: the caller's pool is put back on the way out.
    struct RestorePool {
        glslang::TPoolAllocator& pool = glslang::GetThreadPoolAllocator();
        ~RestorePool() { glslang::SetThreadPoolAllocator(&pool); }
    } restore;
    glslang::TProgram alone;
    alone.addShader(&shader);
    if (!alone.link(EShMsgDefault) || !alone.buildReflection(EShReflectionDefault)) return counts;
    std::vector<PackedShape> shapes;
    for (int i = 0; i < alone.getNumUniformVariables(); ++i) {
        const auto& u = alone.getUniform(i);
        const auto* t = u.getType();
        if (t == nullptr) continue;
        if (t->getBasicType() == glslang::EbtSampler) {
            counts.textureUnits += std::max(1, u.size);
            continue;
        }
        shapes.push_back(t->isMatrix() ? PackedShape{t->getMatrixCols(), t->getMatrixRows(), u.size}
                                       : PackedShape{1, std::max(1, t->getVectorSize()), u.size});
    }
    counts.vectors = packedRows(shapes);
    return counts;
}

Es300Usage measure(const std::vector<glslang::TShader*>& shaders) {
    Es300Usage usage;
    for (auto* shader : shaders) {
        const auto counts = measureStage(*shader);
        if (shader->getStage() == EShLangFragment) {
            usage.fragmentUniformVectors = counts.vectors;
            usage.fragmentTextureUnits = counts.textureUnits;
            continue;
        }
        usage.vertexUniformVectors = counts.vectors;
        usage.vertexTextureUnits = counts.textureUnits;
        std::vector<PackedShape> varyings;
        for (const auto& v : extractStageInterface(catalog::Stage::Vertex, *shader).variables)
            if (v.storage == StorageKind::Out) varyings.push_back(shapeOfGlslType(v.type, v.arraySize));
        usage.varyingVectors = packedRows(varyings);
    }
    return usage;
}

}  // namespace

std::vector<Diagnostic> limitWarnings(const std::string& program, const Es300StagePaths& paths, const Es300Usage& usage,
                                      const Es300Limits& limits) {
    struct Row {
        const char* what;
        int count, limit;
        const std::string& path;
    };
    const Row rows[] = {
        {"vertex uniform vectors (GL_MAX_VERTEX_UNIFORM_VECTORS)", usage.vertexUniformVectors,
         limits.vertexUniformVectors, paths.vertex},
        {"fragment uniform vectors (GL_MAX_FRAGMENT_UNIFORM_VECTORS)", usage.fragmentUniformVectors,
         limits.fragmentUniformVectors, paths.fragment},
        {"varying vectors (GL_MAX_VARYING_VECTORS)", usage.varyingVectors, limits.varyingVectors, paths.vertex},
        {"vertex texture units (GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS)", usage.vertexTextureUnits, limits.textureUnits,
         paths.vertex},
        {"fragment texture units (GL_MAX_TEXTURE_IMAGE_UNITS)", usage.fragmentTextureUnits, limits.textureUnits,
         paths.fragment},
    };
    std::vector<Diagnostic> out;
    for (const auto& row : rows) {
        if (row.count <= row.limit) continue;
        Diagnostic d = makeError(row.path, 0, 0,
                                 "es300: program " + program + " uses " + std::to_string(row.count) + " " + row.what +
                                     ", over the ES 3.00 minimum of " + std::to_string(row.limit) +
                                     " that a device may give; it may fail to link on phones (docs/targets.md)");
        d.severity = Severity::Warning;
        out.push_back(std::move(d));
    }
    return out;
}

LinkedProgramCheck es300LimitsCheck(const std::string& program, const Es300StagePaths& paths) {
    return [program, paths](glslang::TProgram&, const std::vector<glslang::TShader*>& shaders) {
        return limitWarnings(program, paths, measure(shaders));
    };
}

}  // namespace prism::shaderc
