// The C++ structs of a Vulkan-client catalogue's blocks (see block_structs.hpp).
#include "block_structs.hpp"

#include <map>
#include <set>
#include <sstream>

#include "header_writer.hpp"
#include "module_naming.hpp"

namespace prism::shaderc {
namespace {

// A C++ type that holds one element at the SPIR-V's layout.
struct CppType {
    std::string name;
    std::uint32_t size = 0, align = 1;
};

std::uint32_t roundUp(std::uint32_t n, std::uint32_t to) {
    return (n + to - 1) / to * to;
}

// Scalars by their GLSL name; bool is 4 bytes in a block.
const std::map<std::string, CppType>& scalars() {
    static const std::map<std::string, CppType> types = {
        {"bool", {"std::uint32_t", 4, 4}},     {"int", {"std::int32_t", 4, 4}},
        {"uint", {"std::uint32_t", 4, 4}},     {"float", {"float", 4, 4}},
        {"double", {"double", 8, 8}},          {"int64_t", {"std::int64_t", 8, 8}},
        {"uint64_t", {"std::uint64_t", 8, 8}}, {"float16_t", {"std::uint16_t", 2, 2}},
        {"int16_t", {"std::int16_t", 2, 2}},   {"uint16_t", {"std::uint16_t", 2, 2}},
        {"int8_t", {"std::int8_t", 1, 1}},     {"uint8_t", {"std::uint8_t", 1, 1}},
    };
    return types;
}

// glm's vectors and matrices, and their scalar, by GLSL prefix ("" for float).
const std::map<std::string, std::pair<std::string, std::string>>& glmKinds() {
    static const std::map<std::string, std::pair<std::string, std::string>> kinds = {{"", {"glm::", "float"}},
                                                                                     {"i", {"glm::i", "int"}},
                                                                                     {"u", {"glm::u", "uint"}},
                                                                                     {"d", {"glm::d", "double"}},
                                                                                     {"b", {"glm::u", "bool"}}};
    return kinds;
}

// The C++ type of one element of a scalar, vector or matrix member; empty name: none fits.
CppType elementType(const ReflectedStructMember& m) {
    if (m.deviceAddress) return {"std::uint64_t", 8, 8};
    if (const auto s = scalars().find(m.glslType); s != scalars().end()) return s->second;
    const auto vec = m.glslType.find("vec"), mat = m.glslType.find("mat");
    const auto at = vec != std::string::npos ? vec : mat;
    if (at == std::string::npos) return {};
    const auto kind = glmKinds().find(m.glslType.substr(0, at));
    if (kind == glmKinds().end()) return {};
    const CppType scalar = scalars().at(kind->second.second);
    const std::string dims = m.glslType.substr(at + 3);
    if (vec != std::string::npos) {
        const std::uint32_t n = static_cast<std::uint32_t>(std::stoul(dims));
        return {kind->second.first + "vec" + dims, n * scalar.size, scalar.align};
    }
    if (m.rowMajor || kind->first == "i" || kind->first == "u" || kind->first == "b") return {};
    const std::uint32_t columns = static_cast<std::uint32_t>(dims[0] - '0');
    const std::uint32_t rows = dims.size() > 1 ? static_cast<std::uint32_t>(dims[2] - '0') : columns;
    if (m.matrixStride % scalar.size != 0 || m.matrixStride / scalar.size < rows || m.matrixStride / scalar.size > 4)
        return {};
    const std::uint32_t storedRows = m.matrixStride / scalar.size;
    return {kind->second.first + "mat" + std::to_string(columns) + "x" + std::to_string(storedRows),
            columns * m.matrixStride, scalar.align};
}

class StructWriter {
  public:
    explicit StructWriter(const ReflectedBlockLayout& layout, std::string prefix)
        : layout_(layout), prefix_(std::move(prefix)) {}

    // Every struct of the layout, nested ones first; the block's is `prefix`.
    std::string text() {
        for (std::size_t i = layout_.size(); i-- > 0;) writeStruct(static_cast<int>(i));
        return out_.str();
    }

  private:
    std::string structName(int index) const {
        return index == 0 ? prefix_ : prefix_ + "_" + cppIdentifier(layout_[index].name);
    }

    CppType typeOf(const ReflectedStructMember& m) {
        if (m.structIndex < 0) return elementType(m);
        return {structName(m.structIndex), roundUp(layout_[m.structIndex].size, aligns_[m.structIndex]),
                aligns_[m.structIndex]};
    }

    // One member's declaration (and its size and alignment in C++), or raw bytes where no type fits.
    std::pair<std::string, CppType> declaration(const ReflectedStructMember& m) {
        const std::string name = cppIdentifier(m.name);
        const CppType t = typeOf(m);
        const bool scalarOrStruct = !t.name.empty() && m.offset % t.align == 0;
        if (m.arrayDims.empty() && scalarOrStruct) return {t.name + " " + name, t};
        if (m.arrayDims.size() == 1 && scalarOrStruct && m.arrayStride == t.size)
            return {t.name + " " + name + "[" + std::to_string(m.arrayDims[0]) + "]", {t.name, m.size, t.align}};
        if (m.arrayDims.size() == 1 && scalarOrStruct && m.arrayStride > t.size && m.arrayStride % t.align == 0)
            return {"prism::catalog::Padded<" + t.name + ", " + std::to_string(m.arrayStride) + "> " + name + "[" +
                        std::to_string(m.arrayDims[0]) + "]",
                    {t.name, m.size, t.align}};
        return {"std::byte " + name + "[" + std::to_string(m.size) + "]", {"", m.size, 1}};
    }

    void writeStruct(int index) {
        const auto& s = layout_[index];
        const std::string name = structName(index);
        std::ostringstream body, asserts;
        std::uint32_t cursor = 0, align = 1;
        int pads = 0;
        for (const auto& m : s.members) {
            if (!m.arrayDims.empty() && m.arrayDims[0] == catalog::kUnboundedArray) {
                body << "    // then `" << m.name << "[]` at offset " << m.offset << ", " << m.arrayStride
                     << " bytes an element (the runtime array: not part of the struct)\n";
                continue;
            }
            auto [decl, t] = declaration(m);
            if (m.offset > cursor) body << "    std::byte padding" << pads++ << "_[" << m.offset - cursor << "];\n";
            body << "    " << decl << (t.name.empty() ? ";  // no C++ type has this layout\n" : ";\n");
            asserts << "static_assert(offsetof(" << name << ", " << cppIdentifier(m.name) << ") == " << m.offset
                    << ");\n";
            cursor = m.offset + m.size;
            align = std::max(align, t.align);
        }
        if (s.size > cursor) body << "    std::byte padding" << pads << "_[" << s.size - cursor << "];\n";
        aligns_[index] = align;
        if (!emitted_.insert(name).second) return;  // a struct type that two members share
        out_ << "struct " << name << " {  // " << s.name << ", " << s.size << " bytes\n"
             << body.str() << "};\n"
             << (s.size == 0
                     ? "static_assert(std::is_empty_v<" + name + ">);  // the fixed part is empty\n"
                     : "static_assert(sizeof(" + name + ") == " + std::to_string(roundUp(s.size, align)) + ");\n")
             << asserts.str();
    }

    const ReflectedBlockLayout& layout_;
    std::string prefix_;
    std::map<int, std::uint32_t> aligns_;
    std::set<std::string> emitted_;
    std::ostringstream out_;
};

// The blocks of one variant: (C++ struct name, its declarations).
std::map<std::string, std::string> variantBlocks(const ProgramReflection& r) {
    std::map<std::string, std::string> blocks;
    const auto add = [&](const ReflectedBlockLayout& layout) {
        if (layout.empty()) return;
        const std::string name = cppIdentifier(layout[0].name);
        if (!blocks.count(name)) blocks[name] = StructWriter(layout, name).text();
    };
    for (const auto& x : r.resources) add(x.layout);
    add(r.pushConstantLayout);
    return blocks;
}

}  // namespace

void writeBlockStructs(std::ostream& out, const CatalogData& c) {
    if (!c.rules.spirvEnv) return;
    out << "\n// The blocks' C++ structs at the SPIR-V's layout (prism-shaderc docs/vulkan.md, \"Block structs\"):\n"
        << "// blocks::<shader>::<Block>, or blocks::<shader>::<variant>::<Block> where variants differ.\n"
        << "namespace blocks {\n";
    for (const auto& s : c.shaders) {
        // Block name -> its declarations -> the variants that have them.
        std::map<std::string, std::map<std::string, std::vector<std::string>>> layouts;
        for (const auto& v : s.variants)
            if (v.spirv)
                for (const auto& [name, text] : variantBlocks(*v.spirv)) layouts[name][text].push_back(v.name);
        if (layouts.empty()) continue;
        const std::string ns = cppIdentifier(mangleName(s.name));
        out << "namespace " << ns << " {\n";
        for (const auto& [name, texts] : layouts) {
            if (texts.size() == 1) {
                out << texts.begin()->first;
                continue;
            }
            for (const auto& [text, variants] : texts)
                for (const auto& variant : variants)
                    out << "namespace " << cppIdentifier(variant) << " {\n" << text << "}\n";
        }
        out << "}  // namespace " << ns << "\n";
    }
    out << "}  // namespace blocks\n";
}

}  // namespace prism::shaderc
