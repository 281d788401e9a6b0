// Validation results on disk, content-addressed (see validation_cache.hpp).
#include "validation_cache.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

namespace prism::shaderc {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kFormat = 1;  // bump when the entry layout changes

json toJson(const Diagnostic& d) {
    json sites = json::array();
    for (const auto& s : d.includedFrom) sites.push_back({s.file, s.line});
    json notes = json::array();
    for (const auto& n : d.notes) notes.push_back(toJson(n));
    return {{"severity", static_cast<int>(d.severity)}, {"file", d.file}, {"line", d.line}, {"column", d.column},
            {"message", d.message}, {"includedFrom", sites}, {"notes", notes}};
}

Diagnostic diagnosticFrom(const json& j) {
    Diagnostic d;
    d.severity = static_cast<Severity>(j.at("severity").get<int>());
    d.file = j.at("file").get<std::string>();
    d.line = j.at("line").get<int>();
    d.column = j.at("column").get<int>();
    d.message = j.at("message").get<std::string>();
    for (const auto& s : j.at("includedFrom")) d.includedFrom.push_back({s.at(0).get<std::string>(), s.at(1).get<int>()});
    for (const auto& n : j.at("notes")) d.notes.push_back(diagnosticFrom(n));
    return d;
}

}  // namespace

ValidationCache::ValidationCache(std::string dir) : dir_(std::move(dir)) {}

std::string ValidationCache::entryPath(const std::string& tokenKey) const {
    return (fs::path(dir_) / tokenKey.substr(0, 2) / (tokenKey + ".json")).string();
}

std::optional<ValidatedVariant> ValidationCache::find(const ProgramKey& key) const {
    if (!enabled()) return std::nullopt;
    std::ifstream in(entryPath(key.tokens), std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    try {
        const json j = json::parse(text.str());
        if (j.at("format").get<int>() != kFormat || j.at("tokens").get<std::string>() != key.tokens)
            return std::nullopt;
        ValidatedVariant v;
        v.ok = j.at("ok").get<bool>();
        for (const auto& d : j.at("diagnostics")) v.diagnostics.push_back(diagnosticFrom(d));
        // Diagnostics carry lines and paths: only the same texts may reuse them.
        if (!v.diagnostics.empty() && j.at("text").get<std::string>() != key.text) return std::nullopt;
        for (const auto& a : j.at("attributes"))
            v.reflection.attributes.push_back(
                {a.at(0).get<std::string>(), a.at(1).get<std::uint32_t>(), a.at(2).get<int>()});
        for (const auto& u : j.at("uniforms"))
            v.reflection.uniforms.push_back(
                {u.at(0).get<std::string>(), u.at(1).get<std::uint32_t>(), u.at(2).get<int>()});
        return v;
    } catch (const json::exception&) {
        return std::nullopt;  // torn by hand, or another format: validate again
    }
}

void ValidationCache::store(const ProgramKey& key, const ValidatedVariant& result) const {
    if (!enabled()) return;
    json attributes = json::array(), uniforms = json::array(), diagnostics = json::array();
    for (const auto& a : result.reflection.attributes) attributes.push_back({a.name, a.glType, a.location});
    for (const auto& u : result.reflection.uniforms) uniforms.push_back({u.name, u.glType, u.arraySize});
    for (const auto& d : result.diagnostics) diagnostics.push_back(toJson(d));
    const json j = {{"format", kFormat},         {"tokens", key.tokens},   {"text", key.text},
                    {"ok", result.ok},           {"attributes", attributes}, {"uniforms", uniforms},
                    {"diagnostics", diagnostics}};
    const fs::path target = entryPath(key.tokens);
    std::error_code ec;
    fs::create_directories(target.parent_path(), ec);
    if (ec) return;  // a cache that cannot be written only costs time
    const fs::path temp = target.string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                          std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id()) & 0xffffff);
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out << j.dump();
        if (!out) {
            fs::remove(temp, ec);
            return;
        }
    }
    fs::rename(temp, target, ec);  // atomic: readers see the old entry or the new one
    if (ec) fs::remove(temp, ec);
}

}  // namespace prism::shaderc
