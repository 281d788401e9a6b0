// The reflection JSON of --emit-reflection (see reflection_writer.hpp). Keys keep the order
// written here (nlohmann's ordered_json), so the same catalogue gives the same bytes.
#include "reflection_writer.hpp"

#include <nlohmann/json.hpp>

#include "contract.hpp"
#include "generated_format.hpp"
#include "glsl_emitter.hpp"

namespace prism::shaderc {
namespace {

using Json = nlohmann::ordered_json;

// A record's GLSL type: the SPIR-V's own name, else its GL enum's.
std::string typeName(const std::string& glslType, std::uint32_t glType) {
    return glslType.empty() ? glslTypeNameOf(glType) : glslType;
}

Json membersJson(const std::vector<ReflectedBlockMember>& members) {
    Json out = Json::array();
    for (const auto& m : members)
        out.push_back({{"name", m.name},
                       {"type", typeName(m.glslType, m.glType)},
                       {"offset", m.offset},
                       {"size", m.size},
                       {"array", m.arraySize},
                       {"arrayStride", m.arrayStride},
                       {"deviceAddress", m.deviceAddress}});
    return out;
}

Json resourcesJson(const ProgramReflection& r) {
    Json out = Json::array();
    for (const auto& x : r.resources)
        out.push_back({{"name", x.name},
                       {"set", x.set},
                       {"binding", x.binding},
                       {"kind", catalog::resourceKindName(x.kind)},
                       {"array", x.arraySize},
                       {"size", x.size},
                       {"runtimeStride", x.runtimeStride},
                       {"used", x.used},
                       {"members", membersJson(x.members)}});
    return out;
}

Json pushConstantsJson(const ProgramReflection& r) {
    std::vector<ReflectedBlockMember> members;
    for (const auto& p : r.pushConstants)
        members.push_back(
            {p.name, p.glType, p.offset, p.arraySize, p.size, p.arrayStride, p.deviceAddress, p.glslType});
    return membersJson(members);
}

Json variantJson(const CatalogShader& s, const CatalogVariant& v, const ProgramReflection& r) {
    Json defines = Json::object(), spirv = Json::object(), inputs = Json::array(), spec = Json::array();
    for (const auto& [name, value] : v.defines) defines[name] = value;
    for (const auto& st : r.spirv) spirv[std::string(catalog::stageName(st.stage))] = spirvFileName(s, v, st.stage);
    for (const auto& a : r.attributes)
        inputs.push_back(
            {{"name", a.name}, {"type", typeName(a.glslType, a.glType)}, {"location", a.location}, {"used", a.used}});
    for (const auto& c : r.specConstants)
        spec.push_back(
            {{"name", c.name}, {"id", c.id}, {"type", glslTypeNameOf(c.glType)}, {"defaultBits", c.defaultBits}});
    return {{"name", v.name},
            {"defines", std::move(defines)},
            {"spirv", std::move(spirv)},
            {"inputs", inputs},
            {"resources", resourcesJson(r)},
            {"pushConstants", pushConstantsJson(r)},
            {"specConstants", spec},
            {"pushConstantBlock", r.pushConstantLayout.empty() ? "" : r.pushConstantLayout[0].name}};
}

}  // namespace

std::string writeReflectionJson(const CatalogData& catalog) {
    Json shaders = Json::array();
    for (const auto& s : catalog.shaders) {
        Json variants = Json::array();
        for (const auto& v : s.variants)
            if (v.spirv) variants.push_back(variantJson(s, v, *v.spirv));
        if (!variants.empty()) shaders.push_back({{"name", s.name}, {"variants", std::move(variants)}});
    }
    const Json root = {{"format", format::kReflectionFormat}, {"shaders", std::move(shaders)}};
    return root.dump(2) + "\n";
}

}  // namespace prism::shaderc
