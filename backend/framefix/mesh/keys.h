#pragma once
// Keys for hashing and sorting mesh entities by their vertex ids.
// Pair and edge keys are first * stride + second in 64 bits: with stride the vertex count they
// order like (first, second) and stay below 2^63 for any int ids (stride <= 2^32). A triangle of
// three ids needs up to 3 x 31 bits, more than 64, so its key is the sorted id triple itself.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace framefix {

using PairKey = std::uint64_t;

// Stride for id sets that grow while keyed (e.g. surface refinement adds points): any int id fits.
constexpr std::uint64_t kAnyIdStride = std::uint64_t(1) << 32;

// Ordered pair (first, second), both in [0, stride).
constexpr PairKey pair_key(int first, int second, std::uint64_t stride) {
    return std::uint64_t(first) * stride + std::uint64_t(second);
}

// Unordered pair {a, b} (a mesh edge), both in [0, stride).
constexpr PairKey edge_key(int a, int b, std::uint64_t stride) {
    return a < b ? pair_key(a, b, stride) : pair_key(b, a, stride);
}

// The (first, second) ids of a pair key; for an edge key, the lower id first.
constexpr std::array<int, 2> key_ids(PairKey key, std::uint64_t stride) {
    return {int(key / stride), int(key % stride)};
}

using TriangleKey = std::array<int, 3>;  // sorted vertex ids

inline TriangleKey triangle_key(int a, int b, int c) {
    TriangleKey k = {a, b, c};
    std::sort(k.begin(), k.end());
    return k;
}

// For unordered containers of TriangleKey.
struct TriangleKeyHash {
    std::size_t operator()(const TriangleKey& k) const {
        // FNV-1a over the three ids; iteration order of a container using it is unspecified.
        std::uint64_t h = 14695981039346656037ull;
        for (int v : k) h = (h ^ std::uint32_t(v)) * 1099511628211ull;
        return std::size_t(h ^ (h >> 29));
    }
};

}  // namespace framefix
