// Helpers of the C++ structs that a Vulkan-client catalogue's header declares for its blocks
// (docs/vulkan.md, "Block structs"): an array element whose stride in the block is larger than
// the element (a float array in a std140 block: 16 bytes apart) is a Padded<T, Stride>. A
// storage block that holds only a runtime array has an empty fixed part: its struct is empty,
// checked with std::is_empty_v, since C++ gives every struct at least one byte.
//
// Usage (snippet: examples/snippets/catalog_block_struct.cpp):
//
//     #include "prism/catalog/block_struct.hpp"
//     prism::catalog::Padded<float, 16> weights[4];  // std140 `float weights[4]`
//     weights[2] = 0.5f;                             // assigns the value, keeps the padding
//     static_assert(sizeof(weights) == 64);
#pragma once

#include <cstddef>
#include <type_traits>

namespace prism::catalog {

template <class T, std::size_t Stride>
struct Padded {
    static_assert(Stride > sizeof(T), "a Padded element is larger than its value");
    T value;
    std::byte padding[Stride - sizeof(T)];

    Padded& operator=(const T& v) {
        value = v;
        return *this;
    }
    operator const T&() const { return value; }
};

}  // namespace prism::catalog
