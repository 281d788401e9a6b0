// The glslang language of each catalogue stage kind: what the validator compiles a stage
// as, and what the include preprocessor reads a file as (so a stage's predefined macros
// and built-ins are the compiler's).
//
//   glslang::TShader shader(glslangStage(catalog::Stage::TessControl));  // EShLangTessControl
#pragma once

#include <glslang/Public/ShaderLang.h>

#include <prism/catalog/shader_catalog.hpp>

namespace prism::shaderc {

constexpr EShLanguage glslangStage(catalog::Stage s) {
    switch (s) {
        case catalog::Stage::Vertex: return EShLangVertex;
        case catalog::Stage::Geometry: return EShLangGeometry;
        case catalog::Stage::Fragment: return EShLangFragment;
        case catalog::Stage::Compute: return EShLangCompute;
        case catalog::Stage::TessControl: return EShLangTessControl;
        case catalog::Stage::TessEvaluation: return EShLangTessEvaluation;
        case catalog::Stage::Mesh: return EShLangMesh;
        case catalog::Stage::Task: return EShLangTask;
        case catalog::Stage::RayGen: return EShLangRayGen;
        case catalog::Stage::Intersect: return EShLangIntersect;
        case catalog::Stage::AnyHit: return EShLangAnyHit;
        case catalog::Stage::ClosestHit: return EShLangClosestHit;
        case catalog::Stage::Miss: return EShLangMiss;
        case catalog::Stage::Callable: return EShLangCallable;
    }
    return EShLangVertex;
}

}  // namespace prism::shaderc
