// libFuzzer harness: the binding contract JSON (modules/contract.json), read from an
// in-memory file. Oracle: no crash, leak, undefined behaviour or escaping exception;
// a contract that loads has valid, unique attribute locations and named uniforms.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "contract.hpp"
#include "fuzz_input.hpp"

using namespace prism::shaderc;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    MemoryReader files{{"contract.json", prism::fuzz::text(data, size)}};
    const ContractLoadResult r = loadContracts({"contract.json"}, files);
    if (!r.diagnostics.empty()) return 0;
    for (const auto& a : r.contract.attributes)
        if (a.name.empty() || a.type.empty() || a.location < 0) {
            std::fprintf(stderr, "accepted a bad attribute '%s'\n", a.name.c_str());
            std::abort();
        }
    for (const auto& u : r.contract.uniforms)
        if (u.name.empty() || u.type.empty() || u.array < 0) {
            std::fprintf(stderr, "accepted a bad uniform '%s'\n", u.name.c_str());
            std::abort();
        }
    return 0;
}
