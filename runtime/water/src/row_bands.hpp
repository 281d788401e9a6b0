// A small persistent thread pool that runs one function over the rows of a grid, split
// into as many contiguous bands as it has threads (the caller's thread takes the first
// band). Used by the CPU water step: every pass reads the previous pass's arrays and
// writes only its own rows, so the bands need no locks and the result does not depend
// on the thread count. Internal to prism_water.
//
//     prism::water::detail::RowBands bands(2);
//     bands.run(512, [&](int z0, int z1) { for (int z = z0; z < z1; ++z) processRow(z); });
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace prism::water::detail {

class RowBands {
  public:
    // threads >= 1; threads - 1 workers are started.
    explicit RowBands(int threads);
    ~RowBands();
    RowBands(const RowBands&) = delete;
    RowBands& operator=(const RowBands&) = delete;

    int threads() const { return static_cast<int>(workers_.size()) + 1; }
    // Calls task(z0, z1) for the bands of [0, rows) and returns when all are done. The
    // bands are the same for the same rows and thread count. Each task runs with
    // denormals flushed to zero (as the step does on the caller's thread).
    void run(int rows, const std::function<void(int, int)>& task);

  private:
    void work(int index);
    static void band(int rows, int parts, int index, int& z0, int& z1);

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable start_, done_;
    const std::function<void(int, int)>* task_ = nullptr;
    int rows_ = 0;
    std::uint64_t generation_ = 0;
    int pending_ = 0;
    bool stop_ = false;
};

// The thread count for a requested number (0 = the hardware's) on a grid of `cells`:
// small grids run on one thread, where waking workers costs more than it saves.
int threadsFor(int requested, std::size_t cells);

}  // namespace prism::water::detail
