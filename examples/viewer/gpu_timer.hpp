// Frame time for the overlay: GPU time from GL_TIME_ELAPSED queries (two in flight, so
// reading one never stalls) where the driver has timer queries and a real GPU, else CPU
// wall time from begin() to end() after glFinish (always on llvmpipe, whose queries miss
// the deferred rasterisation; PRISM_VIEWER_CPU_TIMER=1 forces it).
//
//     FrameTimer timer;
//     timer.begin();  ... draw ...  timer.end();
//     double ms = timer.lastMs();  bool gpu = timer.gpuTimed();
#pragma once

#include <array>
#include <chrono>

#include "prism/gl/handles.hpp"

namespace prism::viewer {

class FrameTimer {
  public:
    FrameTimer();
    void begin();
    void end();
    double lastMs() const { return lastMs_; }
    bool gpuTimed() const { return gpu_; }

  private:
    bool gpu_ = false;
    std::array<gl::Query, 2> queries_;
    std::array<bool, 2> pending_{};
    int current_ = 0;
    double lastMs_ = 0.0;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace prism::viewer
