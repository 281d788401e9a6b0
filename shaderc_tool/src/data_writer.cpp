// The generated data file (see data_writer.hpp). A stage's pieces are its #version/#define
// block, its #line lines, the module bodies it includes and its own body; the runtime
// concatenates them (prism::catalog::joinChunks) once per program it builds.
#include "data_writer.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

#include "es300_target.hpp"
#include "generated_format.hpp"
#include "module_naming.hpp"
#include "header_writer.hpp"

namespace prism::shaderc {
namespace {

std::string_view stageEnum(catalog::Stage s) {
    switch (s) {
        case catalog::Stage::Vertex: return "Vertex";
        case catalog::Stage::Geometry: return "Geometry";
        case catalog::Stage::Fragment: return "Fragment";
        case catalog::Stage::Compute: return "Compute";
        case catalog::Stage::TessControl: return "TessControl";
        case catalog::Stage::TessEvaluation: return "TessEvaluation";
        case catalog::Stage::Mesh: return "Mesh";
        case catalog::Stage::Task: return "Task";
        case catalog::Stage::RayGen: return "RayGen";
        case catalog::Stage::Intersect: return "Intersect";
        case catalog::Stage::AnyHit: return "AnyHit";
        case catalog::Stage::ClosestHit: return "ClosestHit";
        case catalog::Stage::Miss: return "Miss";
        case catalog::Stage::Callable: return "Callable";
    }
    return "Vertex";
}

// SPIR-V words as array items, eight hexadecimal words a line.
std::vector<std::string> wordLines(const std::vector<std::uint32_t>& words) {
    std::vector<std::string> lines;
    for (std::size_t i = 0; i < words.size(); i += 8) {
        std::string line;
        for (std::size_t k = i; k < std::min(words.size(), i + 8); ++k) {
            char hex[16];
            std::snprintf(hex, sizeof hex, "0x%08x", words[k]);
            line += (k == i ? "" : ", ") + std::string(hex);
        }
        lines.push_back(std::move(line));
    }
    return lines;
}

// The trailing searchDir of a SourceFile or Module row, left out when 0 (the default): files
// under --base-dir keep the rows they always had.
std::string searchDirField(std::uint32_t searchDir) {
    return searchDir == 0 ? "" : ", " + std::to_string(searchDir);
}

// Distinct text pieces, each defined once as `constexpr std::string_view pN`, in order
// of first use. Pieces over the 16 KB literal limit become several pool entries.
class TextPool {
  public:
    explicit TextPool(std::ostringstream& out) : out_(out) {}

    // Appends the references to `piece` to `refs`.
    void reference(const std::string& piece, std::vector<std::string>& refs) {
        if (piece.empty()) return;
        auto it = names_.find(piece);
        if (it == names_.end()) {
            std::vector<std::string> parts;
            for (const auto& chunk : splitIntoChunks(piece)) {
                std::string name = "p" + std::to_string(count_++);
                out_ << "constexpr std::string_view " << name << " = " << rawStringLiteral(chunk) << ";\n";
                parts.push_back(name);
            }
            it = names_.emplace(piece, std::move(parts)).first;
            if (piece.size() >= kMinSharedPiece) shareable_.push_back(piece);
        }
        refs.insert(refs.end(), it->second.begin(), it->second.end());
    }

    // Pieces long enough to look for inside module texts, longest first.
    std::vector<std::string> shareablePieces() const {
        auto pieces = shareable_;
        std::stable_sort(pieces.begin(), pieces.end(),
                         [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
        return pieces;
    }

  private:
    static constexpr std::size_t kMinSharedPiece = 32;
    std::ostringstream& out_;
    std::map<std::string, std::vector<std::string>> names_;
    std::vector<std::string> shareable_;
    std::size_t count_ = 0;
};

// Emits named constexpr arrays, sharing one array among identical contents (line tables
// and reflection repeat across variants).
class ArrayEmitter {
  public:
    explicit ArrayEmitter(std::ostringstream& out) : out_(out) {}

    // Returns the expression to use for a span of `type` built from `items`.
    std::string array(const std::string& type, const std::string& name, const std::vector<std::string>& items,
                      bool oneLine = true) {
        if (items.empty()) return "std::span<const " + type + ">{}";
        std::string body;
        for (const auto& i : items) body += (oneLine ? " " : "\n    ") + i + ",";
        std::string key = type + '\0' + body;
        if (auto it = seen_.find(key); it != seen_.end()) return it->second;
        out_ << "constexpr " << type << " " << name << "[] = {" << body << (oneLine ? " " : "\n") << "};\n";
        seen_.emplace(key, name);
        return name;
    }

    // A span of string_views holding pool references, twelve a line.
    std::string references(const std::string& name, const std::vector<std::string>& refs) {
        if (refs.empty()) return "std::span<const std::string_view>{}";
        std::string body;
        for (std::size_t i = 0; i < refs.size(); ++i) body += (i % 12 == 0 ? "\n    " : " ") + refs[i] + ",";
        std::string key = std::string("refs") + '\0' + body;
        if (auto it = seen_.find(key); it != seen_.end()) return it->second;
        out_ << "constexpr std::string_view " << name << "[] = {" << body << "\n};\n";
        seen_.emplace(key, name);
        return name;
    }

  private:
    std::ostringstream& out_;
    std::map<std::string, std::string> seen_;
};

// A flattened stage split into pieces that recur across stages and variants: each
// `#line` directive on its own, and the text between directives (a stretch of one file).
std::vector<std::string> stagePieces(const std::string& text) {
    std::vector<std::string> pieces;
    std::string body;
    std::size_t pos = 0;
    while (pos < text.size()) {
        auto end = text.find('\n', pos);
        end = end == std::string::npos ? text.size() : end + 1;
        std::string_view line(text.data() + pos, end - pos);
        if (line.starts_with("#line ")) {
            if (!body.empty()) pieces.push_back(std::move(body));
            body.clear();
            pieces.emplace_back(line);
        } else {
            body.append(line);
        }
        pos = end;
    }
    if (!body.empty()) pieces.push_back(std::move(body));
    return pieces;
}

// A module's own text as pool references: stretches equal to a piece already in the
// pool (the same text inside flattened stages) are shared; the rest (its blanked
// #include lines, mostly) become pieces of their own.
std::vector<std::string> moduleRefs(const std::string& text, TextPool& pool,
                                    const std::vector<std::string>& shareable) {
    std::vector<std::string> refs;
    std::string own;
    std::size_t pos = 0;
    while (pos < text.size()) {
        const std::string* match = nullptr;
        for (const auto& piece : shareable)
            if (text.compare(pos, piece.size(), piece) == 0) {
                match = &piece;
                break;
            }
        if (match) {
            pool.reference(own, refs);
            own.clear();
            pool.reference(*match, refs);
            pos += match->size();
            continue;
        }
        auto end = text.find('\n', pos);
        end = end == std::string::npos ? text.size() : end + 1;
        own.append(text, pos, end - pos);
        pos = end;
    }
    pool.reference(own, refs);
    return refs;
}

class DataWriter {
  public:
    explicit DataWriter(const CatalogData& c) : c_(c), pool_(poolOut_), arrays_(tablesOut_) {}

    std::string write(const std::string& headerFileName) {
        auto shaders = writeShaders();
        auto modules = writeModules();
        std::vector<std::string> attributes, uniforms;
        for (const auto& a : c_.contract.attributes)
            attributes.push_back("{" + quotedLiteral(a.name) + ", " + hexLiteral(glTypeOf(a.type)) + ", " +
                                 std::to_string(a.location) + "}");
        for (const auto& u : c_.contract.uniforms)
            uniforms.push_back("{" + quotedLiteral(u.name) + ", " + hexLiteral(glTypeOf(u.type)) + ", " +
                               std::to_string(std::max(1, u.array)) + "}");
        tablesOut_ << "// ---- binding contract\n";
        auto contractAttributes = arrays_.array("prism::catalog::Attribute", "contract_attributes", attributes, false);
        auto contractUniforms = arrays_.array("prism::catalog::Uniform", "contract_uniforms", uniforms, false);
        std::vector<std::string> files;
        for (std::size_t n = 0; n < c_.contractFiles.size(); ++n)
            files.push_back("{" + std::to_string(n) + ", " + quotedLiteral(c_.contractFiles[n].path) +
                            searchDirField(c_.contractFiles[n].searchDir) + "}");
        auto contractFiles = arrays_.array("prism::catalog::SourceFile", "contract_files", files);

        std::ostringstream out;
        out << format::kBannerStart << PRISM_VERSION << format::kBannerEnd << format::kFingerprintLine << c_.fingerprint
            << "\n"
            << "// The data of " << headerFileName << ": each text piece once (pool), stages as lists of pieces.\n"
            << "// Layout and use: docs/shaderc.md; types: <prism/catalog/shader_catalog.hpp>.\n"
            << "#include \"" << headerFileName << "\"\n\n"
            << "#include <span>\n\n"
            << "namespace " << c_.nameSpace << " {\nnamespace {\n\n"
            << "// ---- text pool\n"
            << poolOut_.str() << "\n"
            << tablesOut_.str() << "\n}  // namespace\n\n"
            << "constinit const prism::catalog::Catalog kCatalog{" << shaders << ", " << modules << ", "
            << contractAttributes << ", " << contractUniforms << ", " << quotedLiteral(c_.versionDirective) << ", "
            << contractFiles
            << (c_.rules.spirvEnv ? ", " + quotedLiteral(std::string(spirvEnvName(*c_.rules.spirvEnv))) : "") << "};\n"
            << "\n}  // namespace " << c_.nameSpace << "\n";
        if (!c_.sourcesBlock.empty()) out << "\n" << c_.sourcesBlock;
        return out.str();
    }

  private:
    std::string writeVariant(const CatalogShader& s, std::size_t index) {
        const auto& v = s.variants[index];
        const std::string prefix = mangleName(s.name) + "_v" + std::to_string(index);
        tablesOut_ << "// ---- shader " << s.name << ", variant " << v.name << "\n";
        std::vector<std::string> stages;
        const ProgramReflection* spirv = v.spirv ? &*v.spirv : nullptr;
        for (const auto& st : v.stages)
            stages.push_back(stageSource(st, st.text, prefix + "_" + std::string(catalog::stageName(st.stage)),
                                         spirv ? stageWords(*spirv, st.stage) : nullptr));
        auto stageArray = arrays_.array("prism::catalog::StageSource", prefix + "_stages", stages, false);
        std::vector<std::string> defines, uniforms;
        for (const auto& [n, val] : v.defines)
            defines.push_back("{" + quotedLiteral(n) + ", " + quotedLiteral(val) + "}");
        for (const auto& u : v.reflection.uniforms)
            uniforms.push_back("{" + quotedLiteral(u.name) + ", " + hexLiteral(u.glType) + ", " +
                               std::to_string(u.arraySize) + "}");
        auto defineArray = arrays_.array("prism::catalog::Define", prefix + "_defines", defines);
        auto attributeArray = attributeRows(v.reflection.attributes, prefix + "_attributes");
        auto uniformArray = arrays_.array("prism::catalog::Uniform", prefix + "_uniforms", uniforms);
        // The SPIR-V's and the other targets' fields only where there are: a gl catalogue stays as it was.
        const std::string layout =
            c_.rules.spirvEnv || v.es300 || v.spirv ? spirvLayout(v, prefix, attributeArray) : std::string();
        return "{" + quotedLiteral(v.name) + ", " + defineArray + ", " + stageArray + ", " + attributeArray + ", " +
               uniformArray + layout + "}";
    }

    // A stage's text through the pool, its line table and, where there are, its SPIR-V words
    // (each distinct module once).
    std::string stageSource(const CatalogStage& st, const std::string& text, const std::string& stageId,
                            const std::vector<std::uint32_t>* words) {
        std::vector<std::string> refs;
        for (const auto& piece : stagePieces(text)) pool_.reference(piece, refs);
        auto chunks = arrays_.references(stageId + "_chunks", refs);
        std::vector<std::string> files;
        for (std::size_t n = 0; n < st.files.size(); ++n)
            files.push_back("{" + std::to_string(n) + ", " + quotedLiteral(st.files[n].path) +
                            searchDirField(st.files[n].searchDir) + "}");
        auto fileArray = arrays_.array("prism::catalog::SourceFile", stageId + "_files", files);
        const std::string spirv =
            words ? ", " + arrays_.array("std::uint32_t", stageId + "_spirv", wordLines(*words), false) : "";
        return "{prism::catalog::Stage::" + std::string(stageEnum(st.stage)) + ", " + chunks + ", " + fileArray +
               spirv + "}";
    }

    // The SPIR-V's descriptors (uniform blocks with their members), push constants and
    // specialisation constants, then the es300 stages and the SPIR-V's vertex inputs.
    std::string spirvLayout(const CatalogVariant& v, const std::string& prefix, const std::string& attributeArray) {
        static const ProgramReflection none;
        const ProgramReflection& r = v.spirv ? *v.spirv : none;
        std::vector<std::string> resources, push, spec;
        for (std::size_t i = 0; i < r.resources.size(); ++i)
            resources.push_back(resourceRow(r.resources[i], prefix + "_resource" + std::to_string(i) + "_members"));
        for (const auto& p : r.pushConstants)
            push.push_back("{" + quotedLiteral(p.name) + ", " + hexLiteral(p.glType) + ", " + std::to_string(p.offset) +
                           ", " + std::to_string(p.size) +
                           layoutFields(p.arraySize != 1 || p.arrayStride != 0 || p.deviceAddress,
                                        {std::to_string(p.arraySize), std::to_string(p.arrayStride)}, p.deviceAddress) +
                           "}");
        for (const auto& c : r.specConstants)
            spec.push_back("{" + quotedLiteral(c.name) + ", " + std::to_string(c.id) + ", " + hexLiteral(c.glType) +
                           ", " + hexLiteral(c.defaultBits) + "}");
        // The Vulkan client's vertex inputs are `attributes` (its own locations); the spirv target's its own.
        const std::string inputs = c_.rules.spirvEnv ? attributeArray
                                   : v.spirv         ? attributeRows(v.spirv->attributes, prefix + "_spirv_inputs")
                                                     : "std::span<const prism::catalog::Attribute>{}";
        return ", " + arrays_.array("prism::catalog::Resource", prefix + "_resources", resources, false) + ", " +
               arrays_.array("prism::catalog::PushConstant", prefix + "_push_constants", push, false) + ", " +
               arrays_.array("prism::catalog::SpecConstant", prefix + "_spec_constants", spec, false) + ", " +
               writeEs300(v, prefix) + ", " + inputs;
    }

    std::string resourceRow(const ReflectedResource& x, const std::string& memberArrayName) {
        std::vector<std::string> members;
        for (const auto& m : x.members)
            members.push_back("{" + quotedLiteral(m.name) + ", " + hexLiteral(m.glType) + ", " +
                              std::to_string(m.offset) + ", " + std::to_string(m.arraySize) +
                              layoutFields(m.size != 0 || m.arrayStride != 0 || m.deviceAddress,
                                           {std::to_string(m.size), std::to_string(m.arrayStride)}, m.deviceAddress) +
                              "}");
        const bool tail = x.runtimeStride != 0 || !x.used;
        const std::string memberArray =
            !members.empty() ? ", " + arrays_.array("prism::catalog::BlockMember", memberArrayName, members, false)
            : tail           ? ", {}"
                             : "";
        return "{" + quotedLiteral(x.name) + ", " + std::to_string(x.set) + ", " + std::to_string(x.binding) +
               ", prism::catalog::ResourceKind::" + std::string(catalog::resourceKindName(x.kind)) + ", " +
               std::to_string(x.size) + ", " + std::to_string(x.arraySize) + memberArray +
               layoutFields(tail, {std::to_string(x.runtimeStride)}, !x.used, "false") + "}";
    }

    // The fields the SPIR-V's reflection added to a record, only where one differs from its
    // default: `values`, then `flag` (printed as `flagText`) when set. A record without them
    // is printed as before they existed.
    static std::string layoutFields(bool any, std::initializer_list<std::string> values, bool flag,
                                    const std::string& flagText = "true") {
        if (!any) return "";
        std::string out;
        for (const auto& v : values) out += ", " + v;
        return flag ? out + ", " + flagText : out;
    }

    std::string attributeRows(const std::vector<ReflectedAttribute>& list, const std::string& name) {
        std::vector<std::string> rows;
        for (const auto& a : list)
            rows.push_back("{" + quotedLiteral(a.name) + ", " + hexLiteral(a.glType) + ", " +
                           std::to_string(a.location) + (a.used ? "" : ", false") + "}");
        return arrays_.array("prism::catalog::Attribute", name, rows);
    }

    // The es300 stages: their pieces go through the pool, so what they share with the gl
    // text (every module body) is stored once.
    std::string writeEs300(const CatalogVariant& v, const std::string& prefix) {
        if (!v.es300) return "std::span<const prism::catalog::StageSource>{}";
        std::vector<std::string> stages;
        for (const auto& st : v.stages)
            stages.push_back(stageSource(st, es300Text(st.text),
                                         prefix + "_es300_" + std::string(catalog::stageName(st.stage)), nullptr));
        return arrays_.array("prism::catalog::StageSource", prefix + "_es300_stages", stages, false);
    }

    std::string writeShaders() {
        std::vector<std::string> entries;
        for (const auto& s : c_.shaders) {
            const std::string id = mangleName(s.name);
            std::vector<std::string> variants;
            for (std::size_t i = 0; i < s.variants.size(); ++i) variants.push_back(writeVariant(s, i));
            std::vector<std::string> axes;
            for (std::size_t a = 0; a < s.axes.size(); ++a) {
                std::vector<std::string> values;
                for (const auto& val : s.axes[a].values) values.push_back(quotedLiteral(val));
                auto valueArray =
                    arrays_.array("std::string_view", id + "_axis" + std::to_string(a) + "_values", values);
                axes.push_back("{" + quotedLiteral(s.axes[a].name) + ", " + valueArray + "}");
            }
            std::vector<std::string> modules;
            for (auto m : s.modules) modules.push_back(std::to_string(m));
            auto axisArray = arrays_.array("prism::catalog::VariantAxis", id + "_axes", axes);
            auto variantArray = arrays_.array("prism::catalog::Variant", id + "_variants", variants, false);
            auto moduleArray = arrays_.array("std::uint32_t", id + "_modules", modules);
            tablesOut_ << "\n";
            entries.push_back("{" + quotedLiteral(s.name) + ", " + axisArray + ", " + variantArray + ", " +
                              moduleArray + "}");
        }
        return arrays_.array("prism::catalog::Shader", "shaders", entries, false);
    }

    std::string writeModules() {
        const auto shareable = pool_.shareablePieces();
        std::vector<std::string> entries;
        for (const auto& m : c_.modules) {
            const std::string id = cppIdentifier(m.identifier);
            tablesOut_ << "// ---- module " << m.identifier << " (" << m.path << ")\n";
            auto refs = moduleRefs(m.text, pool_, shareable);
            auto chunks = arrays_.references("module_" + id + "_chunks", refs);
            std::vector<std::string> deps;
            for (auto d : m.dependencies) deps.push_back(std::to_string(d));
            auto depArray = arrays_.array("std::uint32_t", "module_" + id + "_dependencies", deps);
            entries.push_back("{" + quotedLiteral(m.identifier) + ", " + quotedLiteral(m.path) + ", " +
                              quotedLiteral(m.description) + ", " + chunks + ", " + depArray +
                              searchDirField(m.searchDir) + "}");
        }
        tablesOut_ << "\n";
        return arrays_.array("prism::catalog::Module", "modules", entries, false);
    }

    const CatalogData& c_;
    std::ostringstream poolOut_, tablesOut_;
    TextPool pool_;
    ArrayEmitter arrays_;
};

}  // namespace

std::string writeData(const CatalogData& catalog, const std::string& headerFileName, const std::string& headerText) {
    // The hash goes last but for the sources record, so the no-op's read of the tail sees it.
    auto text = DataWriter(catalog).write(headerFileName);
    const auto record = catalog.sourcesBlock.empty() ? text.size() : text.rfind(catalog.sourcesBlock);
    return text.insert(record, std::string(format::kHeaderHashLine) + headerHash(headerText) + "\n");
}

}  // namespace prism::shaderc
