// A differential corpus case: one folder with a case.json, read into Case (the format:
// test_reference_corpus.cpp's header comment and tests/README.md). Shared by the corpus tests
// (test_reference_corpus.cpp, test_reflection_oracle.cpp); a case.json at fault throws
// std::runtime_error naming the JSON path.
#pragma once

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace prism::test::corpus {

struct Case {
    std::string checks, client, reference, program, prismTarget, targetEnv;
    std::vector<std::string> stages, includeDirs, defines, prismArgs;
    std::optional<bool> prismAccepts, referenceAccepts;  // "expect"; unset: the two agree
    std::string prismSays;
};

inline std::vector<std::string> strings(const nlohmann::json& j, const std::string& key) {
    if (!j.contains(key)) return {};
    if (!j[key].is_array()) throw std::runtime_error("/" + key + ": expected an array of strings");
    std::vector<std::string> out;
    for (std::size_t i = 0; i < j[key].size(); ++i) {
        if (!j[key][i].is_string())
            throw std::runtime_error("/" + key + "/" + std::to_string(i) + ": expected a string");
        out.push_back(j[key][i].get<std::string>());
    }
    return out;
}

inline std::string text(const nlohmann::json& j, const std::string& key, const std::vector<std::string>& allowed = {}) {
    if (!j.contains(key) || !j[key].is_string()) throw std::runtime_error("/" + key + ": expected a string");
    auto value = j[key].get<std::string>();
    if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), value) == allowed.end()) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + ("'" + a + "'");
        throw std::runtime_error("/" + key + ": '" + value + "' is not one of " + list);
    }
    return value;
}

inline const std::vector<std::string> kReferences = {"glslangValidator -l",          "glslangValidator -V",
                                                     "glslc --target-env=vulkan1.0", "glslc --target-env=vulkan1.1",
                                                     "glslc --target-env=vulkan1.2", "glslc --target-env=vulkan1.3"};

inline std::optional<bool> expected(const nlohmann::json& j, const std::string& tool) {
    if (!j.contains("expect")) return std::nullopt;
    return text(j["expect"], tool, {"accept", "reject"}) == "accept";
}

// case.json, or an exception naming the JSON path at fault.
inline Case loadCase(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error("cannot read it; every folder of the corpus needs a case.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    Case c;
    c.checks = text(j, "checks");
    c.client = text(j, "client", {"opengl", "vulkan"});
    c.reference = text(j, "reference", kReferences);
    if (c.reference.starts_with("glslc")) c.targetEnv = c.reference.substr(c.reference.find('=') + 1);
    c.stages = strings(j, "stages");
    if (c.stages.empty()) throw std::runtime_error("/stages: name at least one stage file");
    c.includeDirs = strings(j, "include_dirs");
    c.defines = strings(j, "defines");
    c.prismArgs = strings(j, "prism_args");
    c.prismAccepts = expected(j, "prism");
    c.referenceAccepts = expected(j, "reference");
    if (j.contains("prism_says")) c.prismSays = text(j, "prism_says");
    if (j.contains("program")) c.program = text(j, "program");
    if (j.contains("prism_target")) c.prismTarget = text(j, "prism_target", {"es300"});
    return c;
}

// prism-shaderc's arguments for the case (`--check`, the client and its environment, the
// target, -I, -D, the case's own arguments and its stages), to which a test adds its outputs.
inline std::vector<std::string> prismArguments(const Case& c) {
    std::vector<std::string> args = {"--check"};
    if (c.client == "vulkan") args.insert(args.end(), {"--client", "vulkan"});
    if (c.client == "vulkan" && !c.targetEnv.empty()) args.insert(args.end(), {"--target-env", c.targetEnv});
    if (c.prismTarget == "es300") args.insert(args.end(), {"--target", "es300"});
    for (const auto& d : c.includeDirs) args.insert(args.end(), {"-I", d});
    for (const auto& d : c.defines) args.insert(args.end(), {"-D", d});
    args.insert(args.end(), c.prismArgs.begin(), c.prismArgs.end());
    if (c.program.empty()) {
        args.insert(args.end(), c.stages.begin(), c.stages.end());
    } else {
        std::string list;
        for (const auto& stage : c.stages) list += (list.empty() ? "" : ",") + stage;
        args.insert(args.end(), {"--program", c.program + "=" + list});
    }
    return args;
}

}  // namespace prism::test::corpus
