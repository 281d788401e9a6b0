// The generated header's text, and the literal helpers both generated files use
// (see header_writer.hpp and docs/shaderc.md).
#include "header_writer.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "block_structs.hpp"
#include "generated_format.hpp"
#include "module_naming.hpp"

namespace prism::shaderc {
namespace {

// What a uniform handle's type says (prism/catalog/uniform_handle.hpp) for a reflected GL type.
std::string_view handleType(std::uint32_t glType) {
    switch (glType) {
        case 0x1406: return "Float";
        case 0x8B50: return "Vec2";
        case 0x8B51: return "Vec3";
        case 0x8B52: return "Vec4";
        case 0x1404: return "Int";
        case 0x8B53: return "IVec2";
        case 0x8B54: return "IVec3";
        case 0x8B55: return "IVec4";
        case 0x1405: return "UInt";
        case 0x8B56: return "Bool";
        case 0x8B5B: return "Mat3";
        case 0x8B5C: return "Mat4";
        default: break;
    }
    const bool sampler = (glType >= 0x8B5D && glType <= 0x8B64) || (glType >= 0x8DC0 && glType <= 0x8DC5) ||
                         (glType >= 0x8DC9 && glType <= 0x8DD8) || (glType >= 0x9108 && glType <= 0x910D);
    return sampler ? "Sampler" : "Other";
}

struct HandleDecl {
    std::string_view type;
    int length = 1;
    bool conflicting = false;  // variants disagree on the type: no handle
};

// Every plain uniform (no struct member) of any variant of `s`, by name.
std::map<std::string, HandleDecl> uniformUnion(const CatalogShader& s) {
    std::map<std::string, HandleDecl> out;
    for (const auto& v : s.variants)
        for (const auto& u : v.reflection.uniforms) {
            if (u.name.find_first_of(".[") != std::string::npos) continue;
            auto [it, added] = out.try_emplace(u.name, HandleDecl{handleType(u.glType), u.arraySize});
            if (!added && it->second.type != handleType(u.glType)) it->second.conflicting = true;
            it->second.length = std::max(it->second.length, u.arraySize);
        }
    return out;
}

// A shader's namespace name: its identifier, unless that is a name the header declares itself.
std::string shaderNamespace(const std::string& shaderName) {
    static const std::set<std::string> taken = {"ShaderId",         "ModuleId",         "kShaderCount", "kModuleCount",
                                                "kShaderNames",     "kModuleNames",     "kModulePaths", "kCatalog",
                                                "shaderInfo",       "moduleInfo",       "name",         "modulePath",
                                                "shaderIdFromName", "moduleIdFromName", "contract"};
    std::string id = mangleName(shaderName);
    return taken.count(id) ? id + "_" : id;
}

// The identifier of uniform `name` in its shader's namespace, clear of the names declared there.
std::string handleIdentifier(const std::string& name) {
    const std::string id = cppIdentifier(name);
    return id == "Shader" || id == "Uniform" || id == "Contract" ? id + "_" : id;
}

// `namespace <shader> { struct Shader {...}; <handles> }` for every shader.
void writeUniformHandles(std::ostream& out, const CatalogData& c) {
    out << "\n// Typed uniforms (prism/catalog/uniform_handle.hpp): <shader>::<uniform> for every uniform of any\n"
        << "// variant, set with prism::gl::Program::set(handle, value) or prism::gl::ProgramOf<<shader>::Shader>.\n";
    for (const auto& s : c.shaders) {
        const std::string ns = shaderNamespace(s.name);
        out << "namespace " << ns
            << " {\nstruct Shader {\n    static constexpr ShaderId id = ShaderId::" << mangleName(s.name) << ";\n};\n"
            << "template <prism::catalog::GlslType T, std::size_t N>\n"
            << "using Uniform = prism::catalog::UniformHandle<T, N, Shader>;\n";
        for (const auto& [name, decl] : uniformUnion(s)) {
            if (decl.conflicting) continue;  // no one C++ type fits every variant
            out << "inline constexpr Uniform<prism::catalog::GlslType::" << decl.type << ", " << decl.length << "> "
                << handleIdentifier(name) << "{" << quotedLiteral(name) << "};\n";
        }
        out << "}  // namespace " << ns << "\n";
    }
}

// `namespace contract { ... }`: a handle for every uniform of the binding contract, which
// the runtime sets in any program that has it (a program without it ignores the set).
void writeContractHandles(std::ostream& out, const Contract& contract) {
    out << "\n// The binding contract's uniforms, for code that feeds every shader (what a program lacks, it skips).\n"
        << "namespace contract {\nstruct Contract {};\n"
        << "template <prism::catalog::GlslType T, std::size_t N>\n"
        << "using Uniform = prism::catalog::UniformHandle<T, N, Contract>;\n";
    for (const auto& u : contract.uniforms)
        out << "inline constexpr Uniform<prism::catalog::GlslType::" << handleType(glTypeOf(u.type)) << ", "
            << std::max(u.array, 1) << "> " << handleIdentifier(u.name) << "{" << quotedLiteral(u.name) << "};\n";
    out << "}  // namespace contract\n";
}

}  // namespace

std::vector<std::string> splitIntoChunks(const std::string& text, std::size_t maxBytes) {
    std::vector<std::string> chunks;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = std::min(text.size(), start + maxBytes);
        if (end < text.size()) {
            auto nl = text.rfind('\n', end - 1);
            if (nl != std::string::npos && nl >= start) end = nl + 1;
        }
        chunks.push_back(text.substr(start, end - start));
        start = end;
    }
    return chunks;
}

std::string rawStringLiteral(const std::string& text) {
    std::string delimiter = "prism";
    for (int i = 0; text.find(")" + delimiter + "\"") != std::string::npos; ++i)
        delimiter = "prism" + std::to_string(i);
    return "R\"" + delimiter + "(" + text + ")" + delimiter + "\"";
}

std::string quotedLiteral(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string hexLiteral(std::uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%04X", v);
    return buf;
}

// The text is generated code, laid out as the header shows it: not for clang-format.
// clang-format off
std::string writeHeader(const CatalogData& c, const std::string& dataFileName) {
    std::ostringstream out;
    out << format::kBannerStart << PRISM_VERSION << format::kBannerEnd
        << "// Declarations only; the sources, line tables and reflection are in " << dataFileName << ",\n"
        << "// which prism_add_shaders() compiles into this catalogue's target. This file changes only\n"
        << "// when a shader or module is added, removed or renamed, or a shader's uniforms change\n"
        << "// (docs/shaderc.md).\n"
        << "#pragma once\n\n"
        << "#include <array>\n#include <cstddef>\n#include <cstdint>\n#include <optional>\n#include <string_view>\n\n"
        << "#include <prism/catalog/shader_catalog.hpp>\n#include <prism/catalog/uniform_handle.hpp>\n"
        << (c.rules.spirvEnv ? "#include <prism/catalog/block_struct.hpp>\n\n#include <glm/glm.hpp>\n\n" : "\n")
        << "namespace " << c.nameSpace << " {\n\n";
    out << "enum class ShaderId : std::uint32_t {\n";
    for (std::size_t i = 0; i < c.shaders.size(); ++i)
        out << "    " << mangleName(c.shaders[i].name) << " = " << i << ",\n";
    out << "};\ninline constexpr std::size_t kShaderCount = " << c.shaders.size() << ";\n\n";
    out << "// Every module of the include directories, with its own source and its dependencies.\n";
    out << "enum class ModuleId : std::uint32_t {\n";
    for (std::size_t i = 0; i < c.modules.size(); ++i)
        out << "    " << cppIdentifier(c.modules[i].identifier) << " = " << i << ",  // " << c.modules[i].path << "\n";
    out << "};\ninline constexpr std::size_t kModuleCount = " << c.modules.size() << ";\n\n";
    out << "// Names and module paths, for lookups at compile time.\n";
    out << "inline constexpr std::array<std::string_view, kShaderCount> kShaderNames{";
    for (const auto& s : c.shaders) out << "\n    " << quotedLiteral(s.name) << ",";
    out << (c.shaders.empty() ? "" : "\n") << "};\n";
    out << "inline constexpr std::array<std::string_view, kModuleCount> kModuleNames{";
    for (const auto& m : c.modules) out << "\n    " << quotedLiteral(m.identifier) << ",";
    out << (c.modules.empty() ? "" : "\n") << "};\n";
    out << "inline constexpr std::array<std::string_view, kModuleCount> kModulePaths{";
    for (const auto& m : c.modules) out << "\n    " << quotedLiteral(m.path) << ",";
    out << (c.modules.empty() ? "" : "\n") << "};\n";
    out << R"cpp(
// The catalogue's data: sources, line tables, variants, reflection (defined in the data file).
extern const prism::catalog::Catalog kCatalog;

inline const prism::catalog::Shader& shaderInfo(ShaderId id) { return kCatalog.shaders[static_cast<std::size_t>(id)]; }
inline const prism::catalog::Module& moduleInfo(ModuleId id) { return kCatalog.modules[static_cast<std::size_t>(id)]; }
constexpr std::string_view name(ShaderId id) { return kShaderNames[static_cast<std::size_t>(id)]; }
constexpr std::string_view name(ModuleId id) { return kModuleNames[static_cast<std::size_t>(id)]; }
constexpr std::string_view modulePath(ModuleId id) { return kModulePaths[static_cast<std::size_t>(id)]; }

constexpr std::optional<ShaderId> shaderIdFromName(std::string_view n) {
    for (std::size_t i = 0; i < kShaderCount; ++i)
        if (kShaderNames[i] == n) return static_cast<ShaderId>(i);
    return std::nullopt;
}

constexpr std::optional<ModuleId> moduleIdFromName(std::string_view n) {
    for (std::size_t i = 0; i < kModuleCount; ++i)
        if (kModuleNames[i] == n) return static_cast<ModuleId>(i);
    return std::nullopt;
}
)cpp";
    writeUniformHandles(out, c);
    writeContractHandles(out, c.contract);
    writeBlockStructs(out, c);
    out << "\n}  // namespace " << c.nameSpace << "\n";
    return out.str();
}
// clang-format on

}  // namespace prism::shaderc
