// Pipeline statistics of one draw (GL_ARB_pipeline_statistics_query): vertex-shader invocations,
// geometry-shader primitives, primitives entering clipping, fragment-shader invocations.
#pragma once

#include <cstdint>
#include <functional>

namespace prism::rain::bench {

struct PipelineStatistics {
    std::uint64_t vertexInvocations = 0;
    std::uint64_t geometryPrimitives = 0;  // emitted by the geometry stage (0 without one)
    std::uint64_t clippingPrimitives = 0;  // primitives entering clipping: what reaches rasterisation setup
    std::uint64_t fragmentInvocations = 0;
};

// Whether the current context lists GL_ARB_pipeline_statistics_query (or is GL 4.6).
bool pipelineStatisticsAvailable();

// Runs `draw` inside the four queries and returns their results (all 0 when unavailable).
PipelineStatistics measurePipelineStatistics(const std::function<void()>& draw);

}  // namespace prism::rain::bench
