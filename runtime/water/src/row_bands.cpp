// The row-band thread pool of the CPU water step (see row_bands.hpp).
#include "row_bands.hpp"

#include <algorithm>

#if defined(__x86_64__) || defined(__i386__) || defined(_M_X64)
#include <xmmintrin.h>
#define PRISM_ROW_BANDS_HAVE_MXCSR 1
#endif

namespace prism::water::detail {
namespace {

// Denormals flushed to zero (FTZ and DAZ) while a task runs, as on the caller's thread
// during a step (Mesa's llvmpipe runs shaders that way; the CPU step mirrors it).
void runFlushed(const std::function<void(int, int)>& task, int z0, int z1) {
#ifdef PRISM_ROW_BANDS_HAVE_MXCSR
    const unsigned saved = _mm_getcsr();
    _mm_setcsr(saved | 0x8040u);
    task(z0, z1);
    _mm_setcsr(saved);
#else
    task(z0, z1);
#endif
}

}  // namespace

RowBands::RowBands(int threads) {
    for (int i = 1; i < std::max(1, threads); ++i) workers_.emplace_back([this, i] { work(i); });
}

RowBands::~RowBands() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    start_.notify_all();
    for (std::thread& t : workers_) t.join();
}

void RowBands::band(int rows, int parts, int index, int& z0, int& z1) {
    z0 = static_cast<int>(static_cast<long long>(rows) * index / parts);
    z1 = static_cast<int>(static_cast<long long>(rows) * (index + 1) / parts);
}

void RowBands::run(int rows, const std::function<void(int, int)>& task) {
    if (workers_.empty() || rows < 2) {
        runFlushed(task, 0, rows);
        return;
    }
    {
        std::lock_guard<std::mutex> lock(mutex_);
        task_ = &task;
        rows_ = rows;
        pending_ = static_cast<int>(workers_.size());
        ++generation_;
    }
    start_.notify_all();
    int z0 = 0, z1 = 0;
    band(rows, threads(), 0, z0, z1);
    runFlushed(task, z0, z1);
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
    task_ = nullptr;
}

void RowBands::work(int index) {
    std::uint64_t seen = 0;
    for (;;) {
        const std::function<void(int, int)>* task = nullptr;
        int rows = 0;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            start_.wait(lock, [&] { return stop_ || generation_ != seen; });
            if (stop_) return;
            seen = generation_;
            task = task_;
            rows = rows_;
        }
        int z0 = 0, z1 = 0;
        band(rows, threads(), index, z0, z1);
        if (z1 > z0) runFlushed(*task, z0, z1);
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (--pending_ == 0) done_.notify_one();
        }
    }
}

int threadsFor(int requested, std::size_t cells) {
    if (cells < 128u * 128u) return 1;
    const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    return std::clamp(requested > 0 ? requested : hardware, 1, 64);
}

}  // namespace prism::water::detail
