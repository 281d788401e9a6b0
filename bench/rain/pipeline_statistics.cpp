// GL_ARB_pipeline_statistics_query around one draw (the GL 4.5 loader has no names for its targets).
#include "pipeline_statistics.hpp"

#include <cstring>
#include <string>

#include "prism/gl/gl.hpp"

namespace prism::rain::bench {
namespace {

constexpr GLenum kVertexShaderInvocations = 0x82F0;          // GL_VERTEX_SHADER_INVOCATIONS_ARB
constexpr GLenum kGeometryShaderPrimitivesEmitted = 0x82F3;  // GL_GEOMETRY_SHADER_PRIMITIVES_EMITTED_ARB
constexpr GLenum kFragmentShaderInvocations = 0x82F4;        // GL_FRAGMENT_SHADER_INVOCATIONS_ARB
constexpr GLenum kClippingInputPrimitives = 0x82F6;          // GL_CLIPPING_INPUT_PRIMITIVES_ARB

}  // namespace

bool pipelineStatisticsAvailable() {
    GLint major = 0;
    GLint minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (major > 4 || (major == 4 && minor >= 6)) return true;
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const auto* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
        if (name && std::strcmp(name, "GL_ARB_pipeline_statistics_query") == 0) return true;
    }
    return false;
}

PipelineStatistics measurePipelineStatistics(const std::function<void()>& draw) {
    PipelineStatistics s;
    if (!pipelineStatisticsAvailable()) {
        draw();
        return s;
    }
    const GLenum targets[] = {kVertexShaderInvocations, kGeometryShaderPrimitivesEmitted, kClippingInputPrimitives,
                              kFragmentShaderInvocations};
    GLuint queries[4] = {};
    glGenQueries(4, queries);
    // One query per target may be active at a time, and all four may be active together.
    for (int q = 0; q < 4; ++q) glBeginQuery(targets[q], queries[q]);
    draw();
    for (int q = 0; q < 4; ++q) glEndQuery(targets[q]);
    std::uint64_t values[4] = {};
    for (int q = 0; q < 4; ++q) {
        GLuint64 v = 0;
        glGetQueryObjectui64v(queries[q], GL_QUERY_RESULT, &v);
        values[q] = v;
    }
    glDeleteQueries(4, queries);
    s.vertexInvocations = values[0];
    s.geometryPrimitives = values[1];
    s.clippingPrimitives = values[2];
    s.fragmentInvocations = values[3];
    return s;
}

}  // namespace prism::rain::bench
