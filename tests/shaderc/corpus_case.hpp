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
    std::string checks, client, reference;
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

inline const std::vector<std::string> kReferences = {"glslangValidator -l", "glslangValidator -V",
                                                     "glslc --target-env=vulkan1.2"};

inline std::optional<bool> expected(const nlohmann::json& j, const std::string& tool) {
    if (!j.contains("expect")) return std::nullopt;
    return text(j["expect"], tool, {"accept", "reject"}) == "accept";
}

// case.json, or an exception naming the JSON path at fault. `anyReference`: the reference
// tool is not checked against kReferences (for tests that do not run it).
inline Case loadCase(const std::filesystem::path& file, bool anyReference = false) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error("cannot read it; every folder of the corpus needs a case.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    Case c;
    c.checks = text(j, "checks");
    c.client = text(j, "client", {"opengl", "vulkan"});
    c.reference = anyReference ? text(j, "reference") : text(j, "reference", kReferences);
    c.stages = strings(j, "stages");
    if (c.stages.empty()) throw std::runtime_error("/stages: name at least one stage file");
    c.includeDirs = strings(j, "include_dirs");
    c.defines = strings(j, "defines");
    c.prismArgs = strings(j, "prism_args");
    c.prismAccepts = expected(j, "prism");
    c.referenceAccepts = expected(j, "reference");
    if (j.contains("prism_says")) c.prismSays = text(j, "prism_says");
    return c;
}

// Every folder under `root` (at any depth) that holds a case.json, sorted; none when `root`
// does not exist.
inline std::vector<std::filesystem::path> caseFoldersUnder(const std::filesystem::path& root) {
    std::vector<std::filesystem::path> out;
    std::error_code ec;
    for (auto it = std::filesystem::recursive_directory_iterator(root, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
        if (it->path().filename() == "case.json") out.push_back(it->path().parent_path());
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace prism::test::corpus
