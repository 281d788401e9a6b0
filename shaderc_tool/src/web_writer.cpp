// The web catalogue of --emit-web (see web_writer.hpp). The entry is JSON (nlohmann's writer,
// every non-ASCII character and control character escaped), which is also a JavaScript
// expression; keys keep the order written here, so the same catalogue gives the same bytes.
#include "web_writer.hpp"

#include <map>

#include <nlohmann/json.hpp>

#include "contract.hpp"
#include "es300_target.hpp"
#include "generated_format.hpp"

namespace prism::shaderc {
namespace {

using Json = nlohmann::ordered_json;

// Each distinct es300 stage text once, in order of first use; variants refer to it by index.
class TextTable {
  public:
    std::size_t index(const std::string& text) {
        const auto [it, added] = indices_.emplace(text, texts_.size());
        if (added) texts_.push_back(text);
        return it->second;
    }
    Json json() const { return Json(texts_); }

  private:
    std::map<std::string, std::size_t> indices_;
    std::vector<std::string> texts_;
};

// What a page binds by name: the attributes (at the contract's locations) and the uniforms.
void addReflection(const ProgramReflection& r, Json& variant) {
    Json attributes = Json::array(), uniforms = Json::array();
    for (const auto& a : r.attributes)
        attributes.push_back({{"name", a.name}, {"type", glslTypeNameOf(a.glType)}, {"location", a.location}});
    for (const auto& u : r.uniforms)
        uniforms.push_back({{"name", u.name}, {"type", glslTypeNameOf(u.glType)}, {"size", u.arraySize}});
    variant["attributes"] = std::move(attributes);
    variant["uniforms"] = std::move(uniforms);
}

Json variantJson(const CatalogVariant& v, TextTable& texts) {
    Json defines = Json::object(), stages = Json::object(), files = Json::object();
    for (const auto& [name, value] : v.defines) defines[name] = value;
    for (const auto& st : v.stages) {
        const std::string stage(catalog::stageName(st.stage));
        stages[stage] = texts.index(es300Text(st.text));
        Json paths = Json::array();
        for (const auto& f : st.files) paths.push_back(f.path);
        files[stage] = std::move(paths);  // index = the source number of the text's #line lines
    }
    Json variant = {
        {"name", v.name}, {"defines", std::move(defines)}, {"stages", std::move(stages)}, {"files", std::move(files)}};
    addReflection(v.reflection, variant);
    return variant;
}

Json programJson(const CatalogData& c, const CatalogShader& s, TextTable& texts) {
    Json axes = Json::array(), variants = Json::array(), modules = Json::array();
    for (const auto& axis : s.axes) axes.push_back({{"name", axis.name}, {"values", axis.values}});
    for (const auto& v : s.variants)
        if (v.es300) variants.push_back(variantJson(v, texts));
    for (const auto m : s.modules) modules.push_back(c.modules[m].identifier);
    return {{"axes", std::move(axes)}, {"modules", std::move(modules)}, {"variants", std::move(variants)}};
}

Json modulesJson(const CatalogData& c) {
    Json modules = Json::object();
    for (const auto& m : c.modules) {
        Json dependencies = Json::array();
        for (const auto d : m.dependencies) dependencies.push_back(c.modules[d].identifier);
        modules[m.identifier] = {
            {"path", m.path}, {"description", m.description}, {"dependencies", std::move(dependencies)}};
    }
    return modules;
}

}  // namespace

std::string webCatalogueName(const CatalogData& catalog, const std::string& fallback) {
    return catalog.nameSpace.empty() ? fallback : catalog.nameSpace;
}

std::string writeWebCatalogue(const CatalogData& c, const std::string& fallbackName) {
    TextTable texts;
    Json programs = Json::object();
    for (const auto& s : c.shaders) {
        Json program = programJson(c, s, texts);
        if (!program["variants"].empty()) programs[s.name] = std::move(program);
    }
    const std::string name = webCatalogueName(c, fallbackName);
    const Json entry = {{"format", format::kWebFormat},
                        {"name", name},
                        {"texts", texts.json()},
                        {"modules", modulesJson(c)},
                        {"programs", std::move(programs)}};
    const std::string global(format::kWebGlobal);
    std::string out;
    out += std::string(format::kBannerStart) + PRISM_VERSION + std::string(format::kBannerEnd);
    out +=
        "// A Prism web catalogue (docs/targets.md, \"Web catalogue\"): the es300 (GLSL ES 3.00) texts, variants,\n"
        "// reflection and module IDs of a catalogue, for WebGL2. A plain script: load it with <script src>.\n";
    out += "var " + global + " = typeof " + global + " === \"object\" && " + global + " ? " + global + " : {};\n";
    out += global + "[" + Json(name).dump(-1, ' ', true) + "] = " + entry.dump(1, ' ', true) + ";\n";
    return out;
}

}  // namespace prism::shaderc
