// Parallel resolution of a shader's variants (see variant_resolution.hpp).
#include "variant_resolution.hpp"

#include <algorithm>
#include <atomic>
#include <thread>

namespace prism::shaderc {

std::vector<std::vector<ResolveResult>> resolveVariants(const std::vector<std::string>& stagePaths,
                                                        const ResolveOptions& base,
                                                        const std::vector<VariantChoice>& choices,
                                                        const SourceReader& reader, int jobs) {
    std::vector<std::vector<ResolveResult>> results(choices.size(), std::vector<ResolveResult>(stagePaths.size()));
    std::vector<ResolveOptions> options(choices.size(), base);
    for (std::size_t v = 0; v < choices.size(); ++v)
        options[v].defines.insert(options[v].defines.end(), choices[v].defines.begin(), choices[v].defines.end());
    const std::size_t count = choices.size() * stagePaths.size();
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t i; (i = next.fetch_add(1)) < count;) {
            const std::size_t v = i / stagePaths.size(), st = i % stagePaths.size();
            results[v][st] = resolveStage(stagePaths[st], options[v], reader);
        }
    };
    const std::size_t threads =
        std::clamp<std::size_t>(static_cast<std::size_t>(std::max(jobs, 1)), 1, std::max<std::size_t>(1, count));
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& th : pool) th.join();
    return results;
}

}  // namespace prism::shaderc
