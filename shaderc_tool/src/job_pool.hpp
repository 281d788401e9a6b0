// Runs the independent jobs of one prism-shaderc stage (variant resolution, stage parsing,
// program validation) on up to -j threads, this one included.
//
//   runPool(programs.size(), options.jobs, [&](std::size_t i) { results[i] = validate(programs[i]); });
#pragma once

#include <cstddef>
#include <functional>

namespace prism::shaderc {

// Calls job(i) once for every i in [0, count), on min(max(jobs, 1), count) threads.
void runPool(std::size_t count, int jobs, const std::function<void(std::size_t)>& job);

}  // namespace prism::shaderc
