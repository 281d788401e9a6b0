// Reflection against an oracle: for every Vulkan case of the differential corpora
// (fixtures/reference_corpus/, fixtures/real_corpus/, at any depth) that Prism accepts,
// prism-shaderc --emit-spirv --emit-reflection, then `spirv-cross --reflect` on each emitted
// module, and Prism's metadata must equal what spirv-cross reads from the same words: every
// descriptor (name, set, binding, kind, array size with unbounded as 0, block size, runtime
// array stride, members' offsets, types, array sizes and strides), push-constant members
// (a buffer_reference one as an 8-byte device address), vertex inputs with their locations,
// and specialisation constants. Stages are merged as Prism merges them (one descriptor per
// set and binding). The `used` flags, which spirv-cross does not print, are checked on the
// fixture made for them (vk_reflection_layouts).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "corpus_case.hpp"
#include "tool_runner.hpp"

namespace {
namespace fs = std::filesystem;
using json = nlohmann::json;
using prism::test::runCommand;
using prism::test::ScratchDir;

const fs::path kCorpusFixtures = fs::path(PRISM_SOURCE_DIR) / "tests/shaderc/fixtures";

std::vector<fs::path> vulkanCorpusCases() {
    std::vector<fs::path> out;
    for (const char* corpus : {"reference_corpus", "real_corpus"})
        for (const auto& dir : prism::test::corpus::caseFoldersUnder(kCorpusFixtures / corpus)) {
            try {
                if (prism::test::corpus::loadCase(dir / "case.json", true).client == "vulkan") out.push_back(dir);
            } catch (const std::exception&) {
                out.push_back(dir);  // its test reports the case.json at fault
            }
        }
    return out;
}

// One leaf member as both sides describe it.
std::string oracleMemberRow(const std::string& name, const std::string& type, unsigned offset, unsigned array,
                            unsigned stride, bool address) {
    return name + " : " + type + " @" + std::to_string(offset) + " [" + std::to_string(array) + "] stride " +
           std::to_string(stride) + (address ? " device-address" : "");
}

// spirv-cross's view of one module, in the rows Prism's JSON is compared with.
struct OracleView {
    std::map<std::pair<unsigned, unsigned>, std::string> descriptors;  // (set, binding) -> row
    std::map<std::pair<unsigned, unsigned>, std::set<std::string>> members;
    std::set<std::string> pushConstants, inputs, specConstants;
};

// The default of each specialisation constant, by its SPIR-V id: spirv-cross prints an array
// sized by one as the constant's id (array_size_is_literal false).
using SpecDefaults = std::map<unsigned, unsigned>;

unsigned oracleElements(const json& x, const SpecDefaults& specs) {
    unsigned n = 1;
    if (!x.contains("array")) return n;
    for (std::size_t d = 0; d < x["array"].size(); ++d) {
        const unsigned size = x["array"][d].get<unsigned>();
        const bool literal = !x.contains("array_size_is_literal") || x["array_size_is_literal"][d].get<bool>();
        n *= literal ? size : specs.at(size);
    }
    return n;
}

// Leaves of struct type `typeId` of spirv-cross's "types", at `base`, named from `prefix`.
void flattenOracleType(const json& types, const SpecDefaults& specs, const std::string& typeId,
                       const std::string& prefix, unsigned base, std::set<std::string>& out) {
    for (const auto& m : types.at(typeId).at("members")) {
        const std::string type = m.at("type").get<std::string>();
        const unsigned offset = base + m.at("offset").get<unsigned>(), count = oracleElements(m, specs);
        const unsigned stride = m.value("array_stride", 0u);
        const bool address = m.value("physical_pointer", false);
        const std::string name = prefix + m.at("name").get<std::string>();
        if (address || !types.contains(type) || type.rfind('_', 0) != 0) {
            out.insert(oracleMemberRow(name, address ? "uint64_t" : type, offset, count, stride, address));
        } else if (!m.contains("array")) {
            flattenOracleType(types, specs, type, name + ".", offset, out);
        } else {
            for (unsigned e = 0; e < std::max(count, 1u); ++e)
                flattenOracleType(types, specs, type, name + "[" + std::to_string(e) + "].", offset + e * stride, out);
        }
    }
}

// The kind Prism gives a spirv-cross list entry (VkDescriptorType's names).
std::string oracleKind(const std::string& list, const std::string& type) {
    const bool texel = type.find("Buffer") != std::string::npos;
    if (list == "ubos") return "UniformBuffer";
    if (list == "ssbos") return "StorageBuffer";
    if (list == "textures") return texel ? "UniformTexelBuffer" : "CombinedImageSampler";
    if (list == "separate_images") return texel ? "UniformTexelBuffer" : "SampledImage";
    if (list == "images") return texel ? "StorageTexelBuffer" : "StorageImage";
    if (list == "separate_samplers") return "Sampler";
    if (list == "subpass_inputs") return "InputAttachment";
    return "AccelerationStructure";
}

std::string oracleDescriptorRow(const std::string& name, const std::string& kind, unsigned array, unsigned size,
                                unsigned runtimeStride) {
    return name + " " + kind + " [" + std::to_string(array) + "] size " + std::to_string(size) + " runtime stride " +
           std::to_string(runtimeStride);
}

// The runtime array's stride: the last member's, when it is `T x[]`.
unsigned oracleRuntimeStride(const json& types, const std::string& typeId) {
    const auto& members = types.at(typeId).at("members");
    if (members.empty()) return 0;
    const auto& last = members.back();
    return last.contains("array") && last["array"].back() == 0 ? last.value("array_stride", 0u) : 0;
}

// Strips "<Block>." from Prism's member names: spirv-cross does not say whether a block has an
// instance name, which is what puts the prefix there.
std::string withoutBlockPrefix(const std::string& row, const std::string& block) {
    return row.rfind(block + ".", 0) == 0 ? row.substr(block.size() + 1) : row;
}

void addOracleModule(const json& r, bool vertex, OracleView& view) {
    const json& types = r.contains("types") ? r["types"] : json::object();
    SpecDefaults specs;
    if (r.contains("specialization_constants"))
        for (const auto& c : r["specialization_constants"])
            specs[c.at("variable_id").get<unsigned>()] = c.at("default_value").get<unsigned>();
    for (const char* list : {"ubos", "ssbos", "textures", "separate_images", "separate_samplers", "images",
                             "subpass_inputs", "acceleration_structures"}) {
        if (!r.contains(list)) continue;
        for (const auto& x : r[list]) {
            const std::pair key{x.value("set", 0u), x.value("binding", 0u)};
            const std::string type = x.at("type").get<std::string>();
            const bool block = types.contains(type);
            // Aliases of one binding: Prism names it by the first name in alphabetical order.
            if (view.descriptors.count(key) && view.descriptors[key] < x.at("name").get<std::string>() + " ") continue;
            view.members.erase(key);
            view.descriptors[key] =
                oracleDescriptorRow(x.at("name"), oracleKind(list, type), oracleElements(x, specs),
                                    x.value("block_size", 0u), block ? oracleRuntimeStride(types, type) : 0);
            if (block) flattenOracleType(types, specs, type, "", 0, view.members[key]);
        }
    }
    if (r.contains("push_constants"))
        for (const auto& p : r["push_constants"])
            flattenOracleType(types, specs, p.at("type"), "", 0, view.pushConstants);
    if (vertex && r.contains("inputs"))
        for (const auto& in : r["inputs"])
            if (in.at("name").get<std::string>().rfind("gl_", 0) != 0)
                view.inputs.insert(in.at("name").get<std::string>() + " : " + in.at("type").get<std::string>() + " @" +
                                   std::to_string(in.at("location").get<int>()));
    if (r.contains("specialization_constants"))
        for (const auto& c : r["specialization_constants"])
            view.specConstants.insert(std::to_string(c.at("id").get<unsigned>()) + " : " +
                                      c.at("type").get<std::string>());
}

// Prism's JSON of one variant in the same rows.
OracleView prismOracleView(const json& v) {
    OracleView view;
    for (const auto& x : v.at("resources")) {
        const std::pair key{x.at("set").get<unsigned>(), x.at("binding").get<unsigned>()};
        const std::string name = x.at("name");
        view.descriptors[key] =
            oracleDescriptorRow(name, x.at("kind"), x.at("array"), x.at("size"), x.at("runtimeStride"));
        for (const auto& m : x.at("members"))
            view.members[key].insert(oracleMemberRow(withoutBlockPrefix(m.at("name"), name), m.at("type"),
                                                     m.at("offset"), m.at("array"), m.at("arrayStride"),
                                                     m.at("deviceAddress")));
    }
    for (const auto& m : v.at("pushConstants"))
        view.pushConstants.insert(oracleMemberRow(withoutBlockPrefix(m.at("name"), v.at("pushConstantBlock")),
                                                  m.at("type"), m.at("offset"), m.at("array"), m.at("arrayStride"),
                                                  m.at("deviceAddress")));
    for (const auto& in : v.at("inputs"))
        view.inputs.insert(in.at("name").get<std::string>() + " : " + in.at("type").get<std::string>() + " @" +
                           std::to_string(in.at("location").get<int>()));
    for (const auto& c : v.at("specConstants"))
        view.specConstants.insert(std::to_string(c.at("id").get<unsigned>()) + " : " + c.at("type").get<std::string>());
    return view;
}

// Runs Prism on the case into `out`; false (with its output in `log`) when Prism rejects it.
bool runPrismWithReflection(const prism::test::corpus::Case& c, const fs::path& dir, const fs::path& out,
                            std::string& log) {
    std::vector<std::string> args = {PRISM_SHADERC_EXE,   "--check",
                                     "--client",          "vulkan",
                                     "--cache-dir",       "none",
                                     "--emit-spirv",      (out / "spv").string(),
                                     "--emit-reflection", (out / "reflection.json").string()};
    for (const auto& d : c.includeDirs) args.insert(args.end(), {"-I", d});
    for (const auto& d : c.defines) args.insert(args.end(), {"-D", d});
    args.insert(args.end(), c.prismArgs.begin(), c.prismArgs.end());
    args.insert(args.end(), c.stages.begin(), c.stages.end());
    const auto r = runCommand(args, {.workDir = dir.string(), .mergeStderr = true});
    log = r.out;
    return r.exitCode == 0;
}

json readReflectionJson(const fs::path& path) {
    return json::parse(prism::test::readFile(path));
}

class ReflectionOracle : public ::testing::TestWithParam<fs::path> {};

TEST_P(ReflectionOracle, PrismReflectsWhatSpirvCrossReads) {
    const fs::path dir = GetParam();
    const auto c = prism::test::corpus::loadCase(dir / "case.json", true);
    ScratchDir out("reflection-oracle");
    std::string log;
    if (!runPrismWithReflection(c, dir, out.path(), log))
        GTEST_SKIP() << "Prism rejects the case (its corpus test judges that)";
    const json reflection = readReflectionJson(out.path() / "reflection.json");
    int variants = 0;
    for (const auto& shader : reflection.at("shaders"))
        for (const auto& v : shader.at("variants")) {
            OracleView oracle;
            for (const auto& [stage, file] : v.at("spirv").items()) {
                const auto r = runCommand({"spirv-cross", (out.path() / "spv" / file).string(), "--reflect"},
                                          {.mergeStderr = false});
                ASSERT_EQ(r.exitCode, 0) << file << "\n" << r.out;
                addOracleModule(json::parse(r.out), stage == "vert", oracle);
            }
            const OracleView prism = prismOracleView(v);
            const std::string what =
                shader.at("name").get<std::string>() + " (" + v.at("name").get<std::string>() + ")";
            EXPECT_EQ(prism.descriptors, oracle.descriptors) << what;
            EXPECT_EQ(prism.members, oracle.members) << what;
            EXPECT_EQ(prism.pushConstants, oracle.pushConstants) << what;
            EXPECT_EQ(prism.inputs, oracle.inputs) << what;
            EXPECT_EQ(prism.specConstants, oracle.specConstants) << what;
            ++variants;
        }
    EXPECT_GT(variants, 0) << "an accepted Vulkan case with no reflected variant\n" << log;
}

std::string oracleCaseName(const ::testing::TestParamInfo<fs::path>& info) {
    std::string name = info.param.lexically_relative(kCorpusFixtures).generic_string();
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Cases, ReflectionOracle, ::testing::ValuesIn(vulkanCorpusCases()), oracleCaseName);

TEST(ReflectionOracleCases, CoverTheSeedCorpus) {
    EXPECT_GE(vulkanCorpusCases().size(), 13u) << "the Vulkan cases of reference_corpus/ went missing";
}

// What spirv-cross does not print, on the fixture made for it: `used`, and the named values.
TEST(ReflectionOracleFixture, MarksUseAndUnboundedArrays) {
    const fs::path dir = kCorpusFixtures / "reference_corpus/vk_reflection_layouts";
    ScratchDir out("reflection-fixture");
    std::string log;
    ASSERT_TRUE(runPrismWithReflection(prism::test::corpus::loadCase(dir / "case.json"), dir, out.path(), log)) << log;
    const json v = readReflectionJson(out.path() / "reflection.json").at("shaders").at(0).at("variants").at(0);
    std::map<std::string, json> resources, inputs;
    for (const auto& x : v.at("resources")) resources[x.at("name")] = x;
    for (const auto& x : v.at("inputs")) inputs[x.at("name")] = x;
    EXPECT_EQ(resources.at("textures").at("array"), 0) << "textures[] is unbounded (kUnboundedArray)";
    EXPECT_EQ(resources.at("textures").at("used"), true);
    EXPECT_EQ(resources.at("Unused").at("used"), false);
    EXPECT_EQ(resources.at("u_unusedTexture").at("used"), false);
    EXPECT_EQ(resources.at("Materials").at("size"), 32) << "scalar layout: tint at 20, factors[] at 32";
    EXPECT_EQ(resources.at("Materials").at("runtimeStride"), 4);
    EXPECT_EQ(inputs.at("a_unused").at("used"), false);
    EXPECT_EQ(inputs.at("a_unused").at("location"), 3);
    EXPECT_EQ(inputs.at("a_position").at("used"), true);
    const auto& push = v.at("pushConstants");
    ASSERT_EQ(push.size(), 4u) << push.dump();
    EXPECT_EQ(push[1].at("name"), "Push.vertices");
    EXPECT_EQ(push[1].at("offset"), 64);
    EXPECT_EQ(push[1].at("size"), 8);
    EXPECT_EQ(push[1].at("deviceAddress"), true);
}

// --emit-reflection writes the SPIR-V's layout: a usage error where the run makes none, and the
// spirv target's (its loose uniforms in gl_DefaultUniformBlock) where it does.
TEST(ReflectionJson, NeedsSpirvAndCoversTheSpirvTarget) {
    ScratchDir dir("reflection-json");
    dir.write("t.vert",
              "#version 330 core\nin vec3 a_position;\nuniform mat4 u_mvp;\n"
              "void main() { gl_Position = u_mvp * vec4(a_position, 1.0); }\n");
    dir.write("t.frag", "#version 330 core\nuniform vec4 u_color;\nout vec4 o;\nvoid main() { o = u_color; }\n");
    auto run = prism::test::runShaderc("--check --emit-reflection r.json t.vert t.frag", dir.str());
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("--emit-reflection r.json writes the SPIR-V's layout, and this run makes none; add the "
                              "spirv target"),
              std::string::npos)
        << run.output;
    run = prism::test::runShaderc("--check --target gl,spirv --emit-reflection r.json t.vert t.frag", dir.str());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const json r = readReflectionJson(dir.path() / "r.json");
    EXPECT_EQ(r.at("format"), "prism-reflection 1");
    const json& block = r.at("shaders").at(0).at("variants").at(0).at("resources").at(0);
    EXPECT_EQ(block.at("name"), "gl_DefaultUniformBlock");
    std::map<std::string, unsigned> offsets;
    for (const auto& m : block.at("members")) offsets[m.at("name")] = m.at("offset");
    EXPECT_EQ(offsets, (std::map<std::string, unsigned>{{"u_color", 64}, {"u_mvp", 0}})) << block.dump();
}

}  // namespace
