// Validation results on disk, content-addressed, one pack per catalogue (see
// validation_cache.hpp).
#include "validation_cache.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace prism::shaderc {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kFormat = 2;  // bump when the pack layout changes

json toJson(const Diagnostic& d) {
    json sites = json::array();
    for (const auto& s : d.includedFrom) sites.push_back({s.file, s.line});
    json notes = json::array();
    for (const auto& n : d.notes) notes.push_back(toJson(n));
    return {{"severity", static_cast<int>(d.severity)},
            {"file", d.file},
            {"line", d.line},
            {"column", d.column},
            {"message", d.message},
            {"includedFrom", sites},
            {"notes", notes}};
}

Diagnostic diagnosticFrom(const json& j) {
    Diagnostic d;
    d.severity = static_cast<Severity>(j.at("severity").get<int>());
    d.file = j.at("file").get<std::string>();
    d.line = j.at("line").get<int>();
    d.column = j.at("column").get<int>();
    d.message = j.at("message").get<std::string>();
    for (const auto& s : j.at("includedFrom"))
        d.includedFrom.push_back({s.at(0).get<std::string>(), s.at(1).get<int>()});
    for (const auto& n : j.at("notes")) d.notes.push_back(diagnosticFrom(n));
    return d;
}

// The Vulkan client's part of a result: descriptors, push constants, specialisation
// constants and each stage's SPIR-V words.
json vulkanJson(const ProgramReflection& r) {
    json resources = json::array(), push = json::array(), spec = json::array(), spirv = json::array();
    for (const auto& x : r.resources) {
        json members = json::array();
        for (const auto& m : x.members) members.push_back({m.name, m.glType, m.offset, m.arraySize});
        resources.push_back({x.name, x.set, x.binding, static_cast<int>(x.kind), x.size, x.arraySize, members});
    }
    for (const auto& p : r.pushConstants) push.push_back({p.name, p.glType, p.offset, p.size});
    for (const auto& c : r.specConstants) spec.push_back({c.name, c.id, c.glType, c.defaultBits});
    for (const auto& s : r.spirv) spirv.push_back({static_cast<int>(s.stage), s.words});
    return {{"resources", resources}, {"pushConstants", push}, {"specConstants", spec}, {"spirv", spirv}};
}

void readVulkan(const json& j, ProgramReflection& r) {
    for (const auto& x : j.at("resources")) {
        r.resources.push_back({x.at(0).get<std::string>(), x.at(1).get<std::uint32_t>(), x.at(2).get<std::uint32_t>(),
                               static_cast<catalog::ResourceKind>(x.at(3).get<int>()), x.at(4).get<std::uint32_t>(),
                               x.at(5).get<std::uint32_t>()});
        for (const auto& m : x.at(6))
            r.resources.back().members.push_back({m.at(0).get<std::string>(), m.at(1).get<std::uint32_t>(),
                                                  m.at(2).get<std::uint32_t>(), m.at(3).get<int>()});
    }
    for (const auto& p : j.at("pushConstants"))
        r.pushConstants.push_back({p.at(0).get<std::string>(), p.at(1).get<std::uint32_t>(),
                                   p.at(2).get<std::uint32_t>(), p.at(3).get<std::uint32_t>()});
    for (const auto& c : j.at("specConstants"))
        r.specConstants.push_back({c.at(0).get<std::string>(), c.at(1).get<std::uint32_t>(),
                                   c.at(2).get<std::uint32_t>(), c.at(3).get<std::uint32_t>()});
    for (const auto& s : j.at("spirv"))
        r.spirv.push_back({static_cast<catalog::Stage>(s.at(0).get<int>()), s.at(1).get<std::vector<std::uint32_t>>()});
}

json toJson(const std::string& text, const ValidatedVariant& v) {
    json attributes = json::array(), uniforms = json::array(), diagnostics = json::array();
    for (const auto& a : v.reflection.attributes) attributes.push_back({a.name, a.glType, a.location});
    for (const auto& u : v.reflection.uniforms) uniforms.push_back({u.name, u.glType, u.arraySize});
    for (const auto& d : v.diagnostics) diagnostics.push_back(toJson(d));
    json result = {
        {"text", text}, {"ok", v.ok}, {"attributes", attributes}, {"uniforms", uniforms}, {"diagnostics", diagnostics}};
    if (!v.reflection.spirv.empty()) result["vulkan"] = vulkanJson(v.reflection);
    return result;
}

ValidatedVariant resultFrom(const json& j) {
    ValidatedVariant v;
    v.ok = j.at("ok").get<bool>();
    for (const auto& d : j.at("diagnostics")) v.diagnostics.push_back(diagnosticFrom(d));
    for (const auto& a : j.at("attributes"))
        v.reflection.attributes.push_back(
            {a.at(0).get<std::string>(), a.at(1).get<std::uint32_t>(), a.at(2).get<int>()});
    for (const auto& u : j.at("uniforms"))
        v.reflection.uniforms.push_back({u.at(0).get<std::string>(), u.at(1).get<std::uint32_t>(), u.at(2).get<int>()});
    if (j.contains("vulkan")) readVulkan(j.at("vulkan"), v.reflection);
    return v;
}

}  // namespace

ValidationCache::ValidationCache(std::string dir, const std::string& catalogueKey) {
    if (dir.empty()) return;
    path_ = (fs::path(dir) / (catalogueKey + ".json")).string();
    std::ifstream in(path_, std::ios::binary);
    if (!in) return;
    std::ostringstream text;
    text << in.rdbuf();
    try {
        const json j = json::parse(text.str());
        if (j.at("format").get<int>() != kFormat) return;
        for (const auto& [key, entry] : j.at("entries").items())
            entries_[key] = {entry.at("text").get<std::string>(), resultFrom(entry)};
    } catch (const json::exception&) {
        entries_.clear();  // torn by hand, or another format: validate again
    }
}

std::optional<ValidatedVariant> ValidationCache::find(const ProgramKey& key) const {
    std::lock_guard lock(mutex_);
    const auto it = entries_.find(key.tokens);
    if (it == entries_.end()) return std::nullopt;
    // Diagnostics carry lines and paths: only the same texts may reuse them.
    if (!it->second.result.diagnostics.empty() && it->second.text != key.text) return std::nullopt;
    used_.insert(key.tokens);
    return it->second.result;
}

void ValidationCache::store(const ProgramKey& key, const ValidatedVariant& result) {
    if (!enabled()) return;
    std::lock_guard lock(mutex_);
    entries_[key.tokens] = {key.text, result};
    used_.insert(key.tokens);
    dirty_ = true;
}

void ValidationCache::flush() {
    std::lock_guard lock(mutex_);
    if (!enabled() || !dirty_) return;
    json entries = json::object();
    for (const auto& key : used_) entries[key] = toJson(entries_[key].text, entries_[key].result);
    // Older entries stay too (an undone edit, another build of the tool), up to a bound,
    // so the pack cannot grow without limit.
    const std::size_t bound = 4 * used_.size() + 64;
    for (const auto& [key, entry] : entries_)
        if (entries.size() < bound && !used_.contains(key)) entries[key] = toJson(entry.text, entry.result);
    const json pack = {{"format", kFormat}, {"entries", entries}};
    const fs::path target = path_;
    std::error_code ec;
    fs::create_directories(target.parent_path(), ec);
    if (ec) return;  // a cache that cannot be written only costs time
    const fs::path temp = target.string() + ".tmp-" + std::to_string(::getpid());
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out << pack.dump();
        if (!out) {
            fs::remove(temp, ec);
            return;
        }
    }
    fs::rename(temp, target, ec);  // atomic: readers see the old pack or the new one
    if (ec) fs::remove(temp, ec);
    dirty_ = false;
}

}  // namespace prism::shaderc
