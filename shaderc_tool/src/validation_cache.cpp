// Validation results on disk, content-addressed, one pack per catalogue (see
// validation_cache.hpp).
#include "validation_cache.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include <nlohmann/json.hpp>

#include "output_file.hpp"
#include "vulkan_reflection.hpp"
#include "prism/hash/content_hash.hpp"

namespace prism::shaderc {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kFormat = 4;  // bump when the pack layout changes

// A pack's SPIR-V modules, each distinct one once, as raw words in a file beside the JSON
// (`<pack>.words`); entries name a module by its [offset, count] there. As JSON text (an
// array of numbers per stage) the words were a quarter of a re-check after an edit. The
// pack records the words file's size and hash: a words file of another writer, or torn,
// makes the pack a miss, never wrong words.
class ModuleTable {
  public:
    json add(const std::vector<std::uint32_t>& words) {
        const std::string_view bytes(reinterpret_cast<const char*>(words.data()), words.size() * sizeof(words[0]));
        auto [it, added] = offsets_.try_emplace(std::string(bytes), blob_.size());
        if (added) blob_.insert(blob_.end(), words.begin(), words.end());
        return json::array({it->second, words.size()});
    }
    const std::vector<std::uint32_t>& words() const { return blob_; }

  private:
    std::map<std::string, std::size_t> offsets_;  // a module's bytes -> its offset in blob_
    std::vector<std::uint32_t> blob_;
};

std::string wordsHash(const std::vector<std::uint32_t>& words) {
    return hash::ContentHash()
        .addBytes(std::string_view(reinterpret_cast<const char*>(words.data()), words.size() * sizeof(words[0])))
        .hex();
}

// The words file a pack names, checked against its recorded size and hash.
std::vector<std::uint32_t> readWords(const fs::path& path, const json& record) {
    const auto count = record.at("count").get<std::size_t>();
    // The size first: a torn pack's count must not decide how much memory is asked for.
    if (count > fs::file_size(path) / sizeof(std::uint32_t) || fs::file_size(path) % sizeof(std::uint32_t) != 0)
        throw std::runtime_error("the words file is not the size the pack records");
    std::vector<std::uint32_t> words(count);
    std::ifstream in(path, std::ios::binary);
    in.read(reinterpret_cast<char*>(words.data()), static_cast<std::streamsize>(words.size() * sizeof(words[0])));
    if (!in || in.peek() != std::char_traits<char>::eof() || wordsHash(words) != record.at("hash").get<std::string>())
        throw std::runtime_error("the words file is not the one the pack was written with");
    return words;
}

std::vector<std::uint32_t> moduleAt(const json& ref, const std::vector<std::uint32_t>& words) {
    const auto offset = ref.at(0).get<std::size_t>(), count = ref.at(1).get<std::size_t>();
    if (offset > words.size() || count > words.size() - offset) throw std::out_of_range("a module past the words");
    return {words.begin() + static_cast<std::ptrdiff_t>(offset),
            words.begin() + static_cast<std::ptrdiff_t>(offset + count)};
}

fs::path wordsPath(const std::string& packPath) {
    return fs::path(packPath).replace_extension(".words");
}

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

// The Vulkan client's part of a result: each stage's SPIR-V module, by its key in the
// pack's module table. Its layout is a function of the words (vulkan_reflection.hpp), so it
// is read from them again rather than stored.
json vulkanJson(const ProgramReflection& r, ModuleTable& modules) {
    json spirv = json::array();
    for (const auto& s : r.spirv) spirv.push_back({static_cast<int>(s.stage), modules.add(s.words)});
    return {{"spirv", spirv}};
}

void readVulkan(const json& j, const std::vector<std::uint32_t>& words, ProgramReflection& r) {
    for (const auto& s : j.at("spirv"))
        r.spirv.push_back({static_cast<catalog::Stage>(s.at(0).get<int>()), moduleAt(s.at(1), words)});
    reflectSpirv(r);
}

json toJson(const std::string& text, const ValidatedVariant& v, ModuleTable& modules) {
    json attributes = json::array(), uniforms = json::array(), diagnostics = json::array();
    for (const auto& a : v.reflection.attributes) attributes.push_back({a.name, a.glType, a.location});
    for (const auto& u : v.reflection.uniforms) uniforms.push_back({u.name, u.glType, u.arraySize});
    for (const auto& d : v.diagnostics) diagnostics.push_back(toJson(d));
    json result = {
        {"text", text}, {"ok", v.ok}, {"attributes", attributes}, {"uniforms", uniforms}, {"diagnostics", diagnostics}};
    if (!v.reflection.spirv.empty()) result["vulkan"] = vulkanJson(v.reflection, modules);
    return result;
}

ValidatedVariant resultFrom(const json& j, const std::vector<std::uint32_t>& words) {
    ValidatedVariant v;
    v.ok = j.at("ok").get<bool>();
    for (const auto& d : j.at("diagnostics")) v.diagnostics.push_back(diagnosticFrom(d));
    for (const auto& a : j.at("attributes"))
        v.reflection.attributes.push_back(
            {a.at(0).get<std::string>(), a.at(1).get<std::uint32_t>(), a.at(2).get<int>()});
    for (const auto& u : j.at("uniforms"))
        v.reflection.uniforms.push_back({u.at(0).get<std::string>(), u.at(1).get<std::uint32_t>(), u.at(2).get<int>()});
    if (j.contains("vulkan")) readVulkan(j.at("vulkan"), words, v.reflection);
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
        const auto words =
            j.contains("words") ? readWords(wordsPath(path_), j.at("words")) : std::vector<std::uint32_t>{};
        for (const auto& [key, entry] : j.at("entries").items())
            entries_[key] = {entry.at("text").get<std::string>(), resultFrom(entry, words)};
    } catch (const std::exception&) {  // json's, or a words file that is not the pack's
        entries_.clear();              // torn by hand, or another format: validate again
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
    ModuleTable modules;
    for (const auto& key : used_) entries[key] = toJson(entries_[key].text, entries_[key].result, modules);
    // Older entries stay too (an undone edit, another build of the tool), up to a bound,
    // so the pack cannot grow without limit.
    const std::size_t bound = 4 * used_.size() + 64;
    for (const auto& [key, entry] : entries_)
        if (entries.size() < bound && !used_.contains(key)) entries[key] = toJson(entry.text, entry.result, modules);
    json pack = {{"format", kFormat}, {"entries", entries}};
    // Atomic writes (output_file.hpp): readers see the old file or the new one. First the
    // words, then the pack that names them; a cache that cannot be written only costs time.
    std::string error;
    if (!modules.words().empty()) {
        const auto& words = modules.words();
        pack["words"] = {{"count", words.size()}, {"hash", wordsHash(words)}};
        const std::string bytes(reinterpret_cast<const char*>(words.data()), words.size() * sizeof(words[0]));
        if (writeIfChanged(wordsPath(path_).string(), bytes, error) == WriteOutcome::Failed) return;
    }
    if (writeIfChanged(path_, pack.dump(), error) == WriteOutcome::Failed) return;
    dirty_ = false;
}

}  // namespace prism::shaderc
