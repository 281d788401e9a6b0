// Loading of the binding contract (its check against the shaders: contract_check.cpp).
#include "prism/io/json_nesting.hpp"
#include "contract.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <limits>
#include <map>
#include <optional>

namespace prism::shaderc {
namespace {

using nlohmann::json;

struct Field {
    const std::string& file;
    std::vector<Diagnostic>& out;
    bool ok = true;

    void fail(const std::string& pointer, const std::string& expected) {
        out.push_back(makeError(file, 0, 0, pointer + ": expected " + expected));
        ok = false;
    }
    std::string string(const json& obj, const std::string& key, const std::string& at) {
        if (!obj.contains(key) || !obj[key].is_string()) {
            fail(at + "/" + key, "a string");
            return {};
        }
        return obj[key].get<std::string>();
    }
    int integer(const json& obj, const std::string& key, const std::string& at, bool required) {
        if (!obj.contains(key)) {
            if (required) fail(at + "/" + key, "an integer");
            return 0;
        }
        // Checked as unsigned too: 2^31 and more would wrap to a negative int (found by fuzzing).
        if (!obj[key].is_number_integer() || obj[key].get<long long>() < 0 ||
            obj[key].get<unsigned long long>() > static_cast<unsigned long long>(std::numeric_limits<int>::max())) {
            fail(at + "/" + key, "a non-negative integer up to 2147483647");
            return 0;
        }
        return obj[key].get<int>();
    }
};

bool isGlslIdentifier(const std::string& name) {
    auto letter = [](char ch) { return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || ch == '_'; };
    if (name.empty() || !letter(name[0])) return false;
    return std::all_of(name.begin(), name.end(), [&](char ch) { return letter(ch) || (ch >= '0' && ch <= '9'); });
}

// Contracts nest 3 levels; deeper JSON is refused before parsing (docs/reliability.md).
constexpr int kMaxJsonDepth = 64;

// The parsed document, or nullopt with the error (nesting too deep, or malformed JSON).
std::optional<json> parseContractJson(const std::string& path, const std::string& text, std::vector<Diagnostic>& out) {
    if (const auto deep = io::firstTooDeep(text, kMaxJsonDepth)) {
        auto [line, col] = io::lineColumnAt(text, *deep);
        out.push_back(makeError(path, line, col,
                                "contract JSON nested more than " + std::to_string(kMaxJsonDepth) +
                                    " levels deep (the limit); a contract needs 3"));
        return std::nullopt;
    }
    try {
        return json::parse(text);
    } catch (const json::parse_error& e) {
        auto [line, col] = io::lineColumnAt(text, e.byte > 0 ? e.byte - 1 : 0);
        std::string what = e.what();
        auto pos = what.find("syntax error");
        out.push_back(makeError(path, line, col,
                                "malformed contract JSON: " + (pos == std::string::npos ? what : what.substr(pos))));
    } catch (const json::exception& e) {  // e.g. out_of_range 406: a number too large for a double
        std::string what = e.what();
        auto pos = what.find("] ");
        out.push_back(makeError(
            path, 0, 0, "malformed contract JSON: " + (pos == std::string::npos ? what : what.substr(pos + 2))));
    }
    return std::nullopt;
}

// The array under `key`: each entry an object (`shape`), read by `read(entry, at)`.
template <class Read>
void readArray(const json& doc, const std::string& key, const std::string& shape, Field& f, Read read) {
    if (!doc[key].is_array()) return f.fail("/" + key, "an array");
    for (std::size_t i = 0; i < doc[key].size(); ++i) {
        const std::string at = "/" + key + "/" + std::to_string(i);
        if (doc[key][i].is_object())
            read(doc[key][i], at);
        else
            f.fail(at, "an object " + shape);
    }
}

// An entry's "name" must be a GLSL identifier and its "type" a GLSL type ("" is none).
void checkNameAndType(const json& entry, const std::string& name, const std::string& type, const std::string& at,
                      const std::string& typeExample, const std::string& nameExample, Field& f) {
    if (entry.contains("type") && entry["type"].is_string() && glTypeOf(type) == 0)
        f.fail(at + "/type", "a GLSL type such as " + typeExample);
    if (entry.contains("name") && entry["name"].is_string() && !isGlslIdentifier(name))
        f.fail(at + "/name", "a GLSL identifier such as " + nameExample);
}

void readAttributes(const json& doc, Field& f, Contract& c) {
    readArray(doc, "attributes", "{name, type, location}", f, [&](const json& a, const std::string& at) {
        ContractAttribute attr{f.string(a, "name", at), f.string(a, "type", at), f.integer(a, "location", at, true),
                               f.file + " " + at};
        checkNameAndType(a, attr.name, attr.type, at, "vec3", "a_position", f);
        c.attributes.push_back(std::move(attr));
    });
}

void readUniforms(const json& doc, Field& f, Contract& c) {
    readArray(doc, "uniforms", "{name, type[, array]}", f, [&](const json& u, const std::string& at) {
        ContractUniform uni{f.string(u, "name", at), f.string(u, "type", at), f.integer(u, "array", at, false)};
        checkNameAndType(u, uni.name, uni.type, at, "mat4", "u_world", f);
        c.uniforms.push_back(std::move(uni));
    });
}

void loadOne(const std::string& path, const std::string& text, Contract& c, std::vector<Diagnostic>& out) {
    const auto doc = parseContractJson(path, text, out);
    if (!doc) return;
    Field f{path, out};
    if (!doc->is_object()) return f.fail("/", "an object with \"attributes\" and \"uniforms\"");
    if (doc->contains("attributes")) readAttributes(*doc, f, c);
    if (doc->contains("uniforms")) readUniforms(*doc, f, c);
}

// GLSL type names and their GL enums, for both directions of lookup.
const std::map<std::string, std::uint32_t>& glslTypes() {
    static const std::map<std::string, std::uint32_t> types = {
        {"float", 0x1406},
        {"vec2", 0x8B50},
        {"vec3", 0x8B51},
        {"vec4", 0x8B52},
        {"int", 0x1404},
        {"ivec2", 0x8B53},
        {"ivec3", 0x8B54},
        {"ivec4", 0x8B55},
        {"uint", 0x1405},
        {"uvec2", 0x8DC6},
        {"uvec3", 0x8DC7},
        {"uvec4", 0x8DC8},
        {"bool", 0x8B56},
        {"bvec2", 0x8B57},
        {"bvec3", 0x8B58},
        {"bvec4", 0x8B59},
        {"mat2", 0x8B5A},
        {"mat3", 0x8B5B},
        {"mat4", 0x8B5C},
        {"mat2x3", 0x8B65},
        {"mat2x4", 0x8B66},
        {"mat3x2", 0x8B67},
        {"mat3x4", 0x8B68},
        {"mat4x2", 0x8B69},
        {"mat4x3", 0x8B6A},
        {"double", 0x140A},
        {"dvec2", 0x8FFC},
        {"dvec3", 0x8FFD},
        {"dvec4", 0x8FFE},
        {"dmat2", 0x8F46},
        {"dmat3", 0x8F47},
        {"dmat4", 0x8F48},
        {"int64_t", 0x140E},
        {"i64vec2", 0x8FE9},
        {"i64vec3", 0x8FEA},
        {"i64vec4", 0x8FEB},
        {"uint64_t", 0x140F},
        {"u64vec2", 0x8FF5},
        {"u64vec3", 0x8FF6},
        {"u64vec4", 0x8FF7},
        {"sampler2D", 0x8B5E},
        {"sampler3D", 0x8B5F},
        {"samplerCube", 0x8B60},
        {"sampler2DShadow", 0x8B62},
        {"sampler2DArray", 0x8DC1},
        {"isampler2D", 0x8DCA},
        {"usampler2D", 0x8DD2},
        {"image2D", 0x904D},
        {"image2DArray", 0x9053},
    };
    return types;
}

}  // namespace

std::uint32_t glTypeOf(const std::string& t) {
    auto it = glslTypes().find(t);
    return it == glslTypes().end() ? 0 : it->second;
}

std::string glslTypeNameOf(std::uint32_t glType) {
    for (const auto& [name, type] : glslTypes())
        if (type == glType) return name;
    return "";
}

ContractLoadResult loadContracts(const std::vector<std::string>& paths, const SourceReader& reader) {
    ContractLoadResult r;
    if (paths.empty()) {
        loadOne("<Prism's built-in contract>", std::string(builtInContractJson()), r.contract, r.diagnostics);
        r.contract.builtIn = true;
    }
    for (const auto& p : paths) {
        auto text = reader.read(p);
        if (!text) {
            r.diagnostics.push_back(makeError(p, 0, 0, "cannot read the contract file; check the --contract path"));
            r.ioError = true;
            continue;
        }
        r.contract.files.push_back(p);
        loadOne(p, *text, r.contract, r.diagnostics);
    }
    std::stable_sort(r.contract.attributes.begin(), r.contract.attributes.end(),
                     [](const auto& a, const auto& b) { return a.location < b.location; });
    std::stable_sort(r.contract.uniforms.begin(), r.contract.uniforms.end(),
                     [](const auto& a, const auto& b) { return a.name < b.name; });
    for (std::size_t i = 1; i < r.contract.attributes.size(); ++i) {
        const auto& a = r.contract.attributes[i - 1];
        const auto& b = r.contract.attributes[i];
        if (a.location == b.location)
            r.diagnostics.push_back(
                makeError(r.contract.files.empty() ? "<Prism's built-in contract>" : r.contract.files.back(), 0, 0,
                          "attributes '" + a.name + "' and '" + b.name + "' share location " +
                              std::to_string(a.location) + "; give each its own"));
    }
    return r;
}

}  // namespace prism::shaderc
