// A std140 uniform block filled by member name at the reflected offsets (see
// prism/vk/uniform_block.hpp).
#include "prism/vk/uniform_block.hpp"

#include <cstring>
#include <stdexcept>

#include "prism/catalog/did_you_mean.hpp"

namespace prism::vk {
namespace {

// GL type enums of the members a setter writes (the catalogue's reflection uses GL's).
constexpr std::uint32_t kFloat = 0x1406, kVec2 = 0x8B50, kVec3 = 0x8B51, kVec4 = 0x8B52, kInt = 0x1404, kUInt = 0x1405,
                        kBool = 0x8B56, kMat3 = 0x8B5B, kMat4 = 0x8B5C;

std::string typeName(std::uint32_t glType) {
    switch (glType) {
        case kFloat: return "float";
        case kVec2: return "vec2";
        case kVec3: return "vec3";
        case kVec4: return "vec4";
        case kInt: return "int";
        case kUInt: return "uint";
        case kBool: return "bool";
        case kMat3: return "mat3";
        case kMat4: return "mat4";
        default: return "GL type " + std::to_string(glType);
    }
}

// "a[3]" -> ("a", 3); "a" -> ("a", 0).
std::pair<std::string_view, int> splitIndex(std::string_view name) {
    const auto open = name.find('[');
    if (open == std::string_view::npos || name.back() != ']') return {name, 0};
    int index = 0;
    for (char c : name.substr(open + 1, name.size() - open - 2)) {
        if (c < '0' || c > '9') return {name, -1};
        index = index * 10 + (c - '0');
    }
    return {name.substr(0, open), index};
}

}  // namespace

UniformBlock::UniformBlock(const catalog::Resource& block, std::string label, int offsetFault)
    : block_(&block), label_(std::move(label)), offsetFault_(offsetFault), bytes_(block.size) {}

bool UniformBlock::hasUniform(std::string_view name) const {
    const auto [base, index] = splitIndex(name);
    for (const auto& m : block_->members)
        if (m.name == base) return index >= 0 && index < std::max(m.arraySize, 1);
    return false;
}

UniformBlock::Slot UniformBlock::slot(std::string_view name, std::uint32_t glType) const {
    const auto [base, index] = splitIndex(name);
    std::vector<std::string> names;
    for (const auto& m : block_->members) {
        names.emplace_back(m.name);
        if (m.name != base) continue;
        const int elements = std::max(m.arraySize, 1);
        if (index < 0 || index >= elements)
            throw std::invalid_argument(label_ + ": " + std::string(name) + " is outside " + std::string(base) + "[" +
                                        std::to_string(elements) + "]");
        const bool boolFromInt = m.glType == kBool && (glType == kInt || glType == kUInt);
        if (m.glType != glType && !boolFromInt)
            throw std::invalid_argument(label_ + ": uniform " + std::string(base) + " is a " + typeName(m.glType) +
                                        ", not a " + typeName(glType));
        const std::size_t stride = m.glType == kMat4 ? 64 : m.glType == kMat3 ? 48 : 16;
        return {m.offset + stride * static_cast<std::size_t>(index), m.glType, elements - index};
    }
    throw std::invalid_argument(label_ + ": the uniform block " + std::string(block_->name) + " has no member '" +
                                std::string(base) + "'" + catalog::didYouMean(base, names) +
                                " (its members: " + catalog::nameList(names) + ")");
}

// `count` elements of `columns` columns of `rows` 4-byte components each, std140: every
// column and every array element starts 16 bytes after the last.
void UniformBlock::write(std::string_view name, std::uint32_t glType, const float* values, int count, int columns,
                         int rows) {
    const Slot s = slot(name, glType);
    if (count > s.elements)
        throw std::length_error(label_ + ": " + std::to_string(count) + " values for " + std::string(name) +
                                ", which holds " + std::to_string(s.elements));
    const std::size_t columnBytes = static_cast<std::size_t>(rows) * 4;
    for (int i = 0; i < count; ++i)
        for (int c = 0; c < columns; ++c) {
            const std::size_t at =
                s.offset + static_cast<std::size_t>(offsetFault_) + 16 * static_cast<std::size_t>(i * columns + c);
            if (at + columnBytes > bytes_.size()) {
                if (offsetFault_ != 0) continue;  // the injected fault pushed it past the end
                throw std::logic_error(label_ + ": " + std::string(name) + " lies past the end of its block");
            }
            std::memcpy(bytes_.data() + at, values + (i * columns + c) * rows, columnBytes);
        }
}

void UniformBlock::set(std::string_view name, float value) {
    write(name, kFloat, &value, 1, 1, 1);
}
void UniformBlock::set(std::string_view name, int value) {
    write(name, kInt, reinterpret_cast<const float*>(&value), 1, 1, 1);
}
void UniformBlock::set(std::string_view name, unsigned value) {
    write(name, kUInt, reinterpret_cast<const float*>(&value), 1, 1, 1);
}
void UniformBlock::set(std::string_view name, bool value) {
    const std::uint32_t bits = value ? 1u : 0u;
    write(name, kBool, reinterpret_cast<const float*>(&bits), 1, 1, 1);
}
void UniformBlock::set(std::string_view name, const glm::vec2& value) {
    write(name, kVec2, &value.x, 1, 1, 2);
}
void UniformBlock::set(std::string_view name, const glm::vec3& value) {
    write(name, kVec3, &value.x, 1, 1, 3);
}
void UniformBlock::set(std::string_view name, const glm::vec4& value) {
    write(name, kVec4, &value.x, 1, 1, 4);
}
void UniformBlock::set(std::string_view name, const glm::mat3& value) {
    write(name, kMat3, &value[0][0], 1, 3, 3);
}
void UniformBlock::set(std::string_view name, const glm::mat4& value) {
    write(name, kMat4, &value[0][0], 1, 4, 4);
}
void UniformBlock::set(std::string_view name, std::span<const float> values) {
    write(name, kFloat, values.data(), static_cast<int>(values.size()), 1, 1);
}
void UniformBlock::set(std::string_view name, std::span<const glm::vec3> values) {
    write(name, kVec3, values.empty() ? nullptr : &values[0].x, static_cast<int>(values.size()), 1, 3);
}
void UniformBlock::set(std::string_view name, std::span<const glm::vec4> values) {
    write(name, kVec4, values.empty() ? nullptr : &values[0].x, static_cast<int>(values.size()), 1, 4);
}

}  // namespace prism::vk
