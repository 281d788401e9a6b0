// A minimal job pool for prism-shaderc (see job_pool.hpp).
#include "job_pool.hpp"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace prism::shaderc {

void runPool(std::size_t count, int jobs, const std::function<void(std::size_t)>& job) {
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t i; (i = next.fetch_add(1)) < count;) job(i);
    };
    const std::size_t threads =
        std::clamp<std::size_t>(static_cast<std::size_t>(std::max(jobs, 1)), 1, std::max<std::size_t>(1, count));
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& th : pool) th.join();
}

}  // namespace prism::shaderc
