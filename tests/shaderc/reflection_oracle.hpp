// Reflection against an oracle (issue 36): Prism's --emit-reflection JSON of a run, compared
// with what `spirv-cross --reflect` reads from each SPIR-V module the same run wrote: every
// descriptor (name, set, binding, kind, array size with unbounded as 0, block size, runtime
// array stride, members' offsets, types, array sizes and strides), push-constant members (a
// buffer_reference one as an 8-byte device address), vertex inputs with their locations, and
// specialisation constants. Stages are merged as Prism merges them (one descriptor per set and
// binding). Used by the differential corpus (test_reference_corpus.cpp) on every Vulkan case
// both tools accept; the `used` flags, which spirv-cross does not print, are checked on their
// own fixture (test_reflection_oracle.cpp).
#pragma once

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "tool_runner.hpp"

namespace prism::test {
namespace reflection_oracle {

using json = nlohmann::json;

// One leaf member as both sides describe it.
inline std::string oracleMemberRow(const std::string& name, const std::string& type, unsigned offset, unsigned array,
                                   unsigned stride, bool address) {
    return name + " : " + type + " @" + std::to_string(offset) + " [" + std::to_string(array) + "] stride " +
           std::to_string(stride) + (address ? " device-address" : "");
}

// spirv-cross's view of one module, in the rows Prism's JSON is compared with.
struct OracleView {
    std::map<std::pair<unsigned, unsigned>, std::string> descriptors;  // (set, binding) -> row
    std::map<std::pair<unsigned, unsigned>, std::set<std::string>> members;
    std::map<std::pair<unsigned, unsigned>, std::pair<std::string, unsigned>> declared;  // name, size
    // Push-constant members by offset, unnamed: stages name one push-constant block differently.
    std::map<unsigned, std::string> pushConstants;
    std::set<std::string> inputs, specConstants;
};

// The default of each specialisation constant, by its SPIR-V id: spirv-cross prints an array
// sized by one as the constant's id (array_size_is_literal false).
using SpecDefaults = std::map<unsigned, unsigned>;

inline unsigned oracleElements(const json& x, const SpecDefaults& specs) {
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
inline void flattenOracleType(const json& types, const SpecDefaults& specs, const std::string& typeId,
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
inline std::string oracleKind(const std::string& list, const std::string& type) {
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

inline std::string oracleDescriptorRow(const std::string& name, const std::string& kind, unsigned array, unsigned size,
                                       unsigned runtimeStride) {
    return name + " " + kind + " [" + std::to_string(array) + "] size " + std::to_string(size) + " runtime stride " +
           std::to_string(runtimeStride);
}

// The runtime array's stride: the last member's, when it is `T x[]`.
inline unsigned oracleRuntimeStride(const json& types, const std::string& typeId) {
    const auto& members = types.at(typeId).at("members");
    if (members.empty()) return 0;
    const auto& last = members.back();
    return last.contains("array") && last["array"].back() == 0 ? last.value("array_stride", 0u) : 0;
}

// A member row's offset, and the row without its name (what follows " : ").
inline unsigned rowOffset(const std::string& row) {
    return static_cast<unsigned>(std::stoul(row.substr(row.find(" @") + 2)));
}
inline std::string unnamed(const std::string& row) {
    return row.substr(row.find(" : ") + 3);
}

// Strips "<Block>." from Prism's member names: spirv-cross does not say whether a block has an
// instance name, which is what puts the prefix there.
inline std::string withoutBlockPrefix(const std::string& row, const std::string& block) {
    return row.rfind(block + ".", 0) == 0 ? row.substr(block.size() + 1) : row;
}

inline SpecDefaults specDefaultsOf(const json& r) {
    SpecDefaults specs;
    if (r.contains("specialization_constants"))
        for (const auto& c : r["specialization_constants"])
            specs[c.at("variable_id").get<unsigned>()] = c.at("default_value").get<unsigned>();
    return specs;
}

// True when an array of `r` is sized by arithmetic on a specialisation constant (`N + 1`),
// whose value spirv-cross does not print.
inline bool hasArraySizedByExpression(const json& j, const SpecDefaults& specs) {
    if (j.is_object() && j.contains("array_size_is_literal"))
        for (std::size_t d = 0; d < j["array"].size(); ++d)
            if (!j["array_size_is_literal"][d].get<bool>() && !specs.count(j["array"][d].get<unsigned>())) return true;
    if (j.is_structured())
        for (const auto& item : j) {
            if (hasArraySizedByExpression(item, specs)) return true;
        }
    return false;
}

// spirv-cross's reflection of the module at `spv`; where an array is sized by an expression, the
// layout (descriptors, types) is read from a copy whose constants spirv-opt froze and folded
// (`--freeze-spec-const --fold-spec-const-op-composite`, which keeps the type ids), and the
// specialisation constants from the module itself.
inline json reflectModule(const std::filesystem::path& spv, std::string& error) {
    const auto run = [&](const std::filesystem::path& file) {
        const auto r = runCommand({"spirv-cross", file.string(), "--reflect"}, {.workDir = {}, .mergeStderr = false});
        if (r.exitCode != 0) error = "spirv-cross --reflect failed on " + file.string() + ":\n" + r.out;
        return r.exitCode == 0 ? json::parse(r.out) : json::object();
    };
    json r = run(spv);
    if (!error.empty() || !hasArraySizedByExpression(r, specDefaultsOf(r))) return r;
    const auto folded = std::filesystem::path(spv.string() + ".folded");
    const auto opt = runCommand(
        {"spirv-opt", "--freeze-spec-const", "--fold-spec-const-op-composite", spv.string(), "-o", folded.string()},
        {.workDir = {}, .mergeStderr = true});
    if (opt.exitCode != 0) error = "spirv-opt could not fold " + spv.string() + ":\n" + opt.out;
    json layout = error.empty() ? run(folded) : json::object();
    if (r.contains("specialization_constants")) layout["specialization_constants"] = r["specialization_constants"];
    return layout;
}

inline void addOracleModule(const json& r, bool vertex, OracleView& view) {
    const json& types = r.contains("types") ? r["types"] : json::object();
    const SpecDefaults specs = specDefaultsOf(r);
    for (const char* list : {"ubos", "ssbos", "textures", "separate_images", "separate_samplers", "images",
                             "subpass_inputs", "acceleration_structures"}) {
        if (!r.contains(list)) continue;
        for (const auto& x : r[list]) {
            const std::pair key{x.value("set", 0u), x.value("binding", 0u)};
            const std::string type = x.at("type").get<std::string>();
            const bool block = types.contains(type);
            const std::string name = x.at("name").get<std::string>();
            unsigned size = x.value("block_size", 0u);
            const auto seen = view.declared.find(key);
            if (seen != view.declared.end() && seen->second.first == name) {
                // One block seen by two stages: the members of both, the larger size.
                size = std::max(size, seen->second.second);
            } else if (seen != view.declared.end()) {
                // Aliases of one binding: Prism names it by the first name in alphabetical order.
                if (seen->second.first < name) continue;
                view.members.erase(key);
            }
            view.declared[key] = {name, size};
            view.descriptors[key] = oracleDescriptorRow(name, oracleKind(list, type), oracleElements(x, specs), size,
                                                        block ? oracleRuntimeStride(types, type) : 0);
            if (block) flattenOracleType(types, specs, type, "", 0, view.members[key]);
        }
    }
    if (r.contains("push_constants"))
        for (const auto& p : r["push_constants"]) {
            std::set<std::string> rows;
            flattenOracleType(types, specs, p.at("type"), "", 0, rows);
            for (const auto& row : rows) view.pushConstants.try_emplace(rowOffset(row), unnamed(row));
        }
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
inline OracleView prismOracleView(const json& v) {
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
        view.pushConstants.try_emplace(
            m.at("offset").get<unsigned>(),
            unnamed(oracleMemberRow(m.at("name"), m.at("type"), m.at("offset"), m.at("array"), m.at("arrayStride"),
                                    m.at("deviceAddress"))));
    for (const auto& in : v.at("inputs"))
        view.inputs.insert(in.at("name").get<std::string>() + " : " + in.at("type").get<std::string>() + " @" +
                           std::to_string(in.at("location").get<int>()));
    for (const auto& c : v.at("specConstants"))
        view.specConstants.insert(std::to_string(c.at("id").get<unsigned>()) + " : " + c.at("type").get<std::string>());
    return view;
}

inline std::string rowText(const std::string& row) {
    return row;
}
inline std::string rowText(const std::pair<const unsigned, std::string>& row) {
    return std::to_string(row.first) + ": " + row.second;
}
template <class Key, class Value>
std::string rowText(const std::pair<Key, Value>& row) {
    std::string value;
    if constexpr (std::is_same_v<Value, std::string>) {
        value = row.second;
    } else {
        for (const auto& v : row.second) value += (value.empty() ? "" : "; ") + v;
    }
    return "(" + std::to_string(row.first.first) + ", " + std::to_string(row.first.second) + ") " + value;
}

}  // namespace reflection_oracle

// One line per disagreement between Prism's reflection (`reflectionJson`, as --emit-reflection
// writes it) and spirv-cross's reading of the modules it names in `spirvDir`; none when they agree.
inline std::vector<std::string> reflectionDisagreements(const std::filesystem::path& reflectionJson,
                                                        const std::filesystem::path& spirvDir) {
    using namespace reflection_oracle;
    std::vector<std::string> out;
    const json reflection = json::parse(readFile(reflectionJson));
    int variants = 0;
    for (const auto& shader : reflection.at("shaders"))
        for (const auto& v : shader.at("variants")) {
            OracleView oracle;
            for (const auto& [stage, file] : v.at("spirv").items()) {
                std::string error;
                const json r = reflectModule(spirvDir / file.get<std::string>(), error);
                if (!error.empty()) return {error};
                addOracleModule(r, stage == "vert", oracle);
            }
            const OracleView prism = prismOracleView(v);
            const std::string what =
                shader.at("name").get<std::string>() + " (" + v.at("name").get<std::string>() + ")";
            const auto compare = [&](const auto& mine, const auto& theirs, const std::string& part) {
                if (mine == theirs) return;
                std::string text = what + ": " + part + " differ from spirv-cross --reflect\n  prism:";
                for (const auto& row : mine) text += "\n    " + rowText(row);
                text += "\n  spirv-cross:";
                for (const auto& row : theirs) text += "\n    " + rowText(row);
                out.push_back(text);
            };
            compare(prism.descriptors, oracle.descriptors, "descriptors");
            compare(prism.members, oracle.members, "block members");
            compare(prism.pushConstants, oracle.pushConstants, "push constants");
            compare(prism.inputs, oracle.inputs, "vertex inputs");
            compare(prism.specConstants, oracle.specConstants, "specialisation constants");
            ++variants;
        }
    if (variants == 0) out.push_back("the reflection lists no variant");
    return out;
}

}  // namespace prism::test
