// glslang's SPIR-V generator and SPIRV-Tools' validator behind one target-environment enum.
#include "spirv_codegen.hpp"

#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv-tools/libspirv.hpp>

#include <time.h>

#include <array>
#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string_view>
#include <tuple>

#include "prism/hash/content_hash.hpp"
#include "spirv_words.hpp"

namespace prism::shaderc {
namespace {

// SPIRV-Tools' environment of each SpirvEnv, in its order.
constexpr std::array<spv_target_env, 5> kToolsEnvs{SPV_ENV_VULKAN_1_0, SPV_ENV_VULKAN_1_1, SPV_ENV_VULKAN_1_2,
                                                   SPV_ENV_VULKAN_1_3, SPV_ENV_OPENGL_4_5};

}  // namespace

bool generateSpirv(const glslang::TProgram& program, EShLanguage stage, std::vector<std::uint32_t>& words,
                   std::string& log, bool withLineInfo) {
    words.clear();
    const auto* intermediate = const_cast<glslang::TProgram&>(program).getIntermediate(stage);
    if (intermediate == nullptr) {
        log = "the program has no such stage";
        return false;
    }
    spv::SpvBuildLogger logger;
    glslang::SpvOptions options;  // unoptimised, no debug information: what glslc -O0 -g0 writes
    options.generateDebugInfo = withLineInfo;
    std::vector<unsigned int> out;
    glslang::GlslangToSpv(*intermediate, out, &logger, &options);
    log = logger.getAllMessages();
    words.assign(out.begin(), out.end());
    return !words.empty();
}

namespace {

// One SPIRV-Tools context per environment and thread: building one (its grammar tables)
// cost more than validating a stage. Validation itself is thread-safe only per context.
spvtools::SpirvTools& toolsFor(SpirvEnv env) {
    thread_local std::map<SpirvEnv, std::unique_ptr<spvtools::SpirvTools>> tools;
    auto& slot = tools[env];
    if (!slot) slot = std::make_unique<spvtools::SpirvTools>(kToolsEnvs[static_cast<std::size_t>(env)]);
    return *slot;
}

}  // namespace

namespace {

constexpr std::uint32_t kOpSourceExtension = 4, kOpName = 5, kOpString = 7, kOpLine = 8, kOpTypeVoid = 19,
                        kOpFunction = 54, kOpFunctionEnd = 56, kOpDecorate = 71, kOpNoLine = 317;

// The OpName of each id the instruction at `index` names: its result id and its id operands
// (any operand word that is a named id: literals that collide with an id name it too, rarely).
SpirvSite siteOf(std::span<const std::uint32_t> words, std::size_t index) {
    std::map<std::uint32_t, std::string> names, strings;
    std::vector<std::uint32_t> operands;
    SpirvSite site;
    std::uint32_t lineFile = 0;
    forEachInstruction(words, [&](std::uint32_t op, std::span<const std::uint32_t> a, std::size_t i) {
        if (op == kOpName && a.size() >= 2) names[a[0]] = literalString(a.subspan(1));
        if (op == kOpString && a.size() >= 2) strings[a[0]] = literalString(a.subspan(1));
        if (op == kOpLine && a.size() >= 2) std::tie(lineFile, site.line) = std::pair{a[0], static_cast<int>(a[1])};
        if (op == kOpNoLine || op == kOpFunctionEnd) site.line = 0;
        if (op == kOpFunction) site.inFunction = true;
        if (op == kOpFunctionEnd) site.inFunction = false;
        if (i != index) return true;
        operands.assign(a.begin(), a.end());
        return false;
    });
    if (site.line > 0) site.lineFile = strings[lineFile];
    for (auto id : operands)
        if (auto it = names.find(id); it != names.end() && !it->second.empty()) site.names.push_back(it->second);
    return site;
}

spvtools::ValidatorOptions validatorOptionsFor(const BlockLayoutRules& rules) {
    spvtools::ValidatorOptions options;
    options.SetScalarBlockLayout(rules.scalar);
    options.SetWorkgroupScalarBlockLayout(rules.workgroupScalar);
    return options;
}

}  // namespace

BlockLayoutRules blockLayoutRulesOf(std::span<const std::uint32_t> words) {
    bool scalar = false, sharedMemoryBlock = false;
    forEachInstruction(words, [&](std::uint32_t op, std::span<const std::uint32_t> a, std::size_t) {
        if (op != kOpSourceExtension) return op != kOpDecorate && op != kOpTypeVoid;  // past the debug section
        const auto extension = literalString(a);
        scalar = scalar || extension == "GL_EXT_scalar_block_layout";
        sharedMemoryBlock = sharedMemoryBlock || extension == "GL_EXT_shared_memory_block";
        return true;
    });
    return {scalar, scalar && sharedMemoryBlock};
}

namespace {

// The modules SPIRV-Tools accepted in this process, by their words' content hash and the
// environment. Programs of a catalogue often compile a stage to the same words (variants
// whose axis only the other stage reads), and the validator's result depends on the words
// and the environment alone; a rejected module is not kept, so its messages are its own.
class AcceptedModules {
  public:
    static std::string keyOf(std::span<const std::uint32_t> words, SpirvEnv env, const BlockLayoutRules& rules) {
        hash::ContentHash key;
        key.add(spirvEnvName(env))
            .add(rules.scalar ? "scalar" : "-")
            .add(rules.workgroupScalar ? "workgroup-scalar" : "-")
            .addBytes(std::string_view(reinterpret_cast<const char*>(words.data()), words.size_bytes()));
        return key.hex();
    }
    bool contains(const std::string& key) const {
        const std::lock_guard lock(mutex_);
        return keys_.count(key) != 0;
    }
    void add(std::string key) {
        const std::lock_guard lock(mutex_);
        keys_.insert(std::move(key));
    }

  private:
    mutable std::mutex mutex_;
    std::set<std::string> keys_;
};

AcceptedModules& acceptedModules() {
    static AcceptedModules accepted;
    return accepted;
}

// The validator's use, for --stats: modules run and their thread CPU time in nanoseconds.
std::atomic<std::size_t> validatedModules{0};
std::atomic<std::int64_t> validatorCpuNs{0};

std::int64_t threadCpuNs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return std::int64_t{t.tv_sec} * 1'000'000'000 + t.tv_nsec;
}

}  // namespace

SpirvValidatorUse spirvValidatorUse() {
    return {validatedModules.load(), static_cast<double>(validatorCpuNs.load()) / 1e6};
}

std::vector<Diagnostic> validateSpirv(std::span<const std::uint32_t> words, SpirvEnv env, const std::string& file,
                                      const std::string& what, const SpirvSiteLocator& locate) {
    const BlockLayoutRules rules = blockLayoutRulesOf(words);
    const std::string key = AcceptedModules::keyOf(words, env, rules);
    if (acceptedModules().contains(key)) return {};
    std::vector<Diagnostic> out;
    auto& tools = toolsFor(env);
    tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t& at, const char* message) {
        auto d = makeError(
            file, 0, 0,
            "SPIRV-Tools rejected the SPIR-V of " + what + " for " + std::string(spirvEnvName(env)) + ": " + message);
        if (locate && at.index > 0) locate(siteOf(words, at.index), d);
        out.push_back(std::move(d));
    });
    const auto start = threadCpuNs();
    const bool valid = tools.Validate(words.data(), words.size(), validatorOptionsFor(rules));
    validatorCpuNs += threadCpuNs() - start;
    ++validatedModules;
    tools.SetMessageConsumer(nullptr);  // it refers to `out`, which ends here
    if (!valid && out.empty()) out.push_back(makeError(file, 0, 0, "SPIRV-Tools rejected the SPIR-V of " + what));
    if (valid && out.empty()) acceptedModules().add(key);
    return out;
}

}  // namespace prism::shaderc
