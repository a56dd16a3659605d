// Finds the first key equal to an earlier one among many (the names of a
// million spheres, checked at every load and every render): open addressing
// over 8-byte slots, each the top half of a key's hash and its index, in one
// allocation. std::unordered_map allocated a node a name; at 1,000,000
// spheres its inserts took a sixth of loading and rendering a scene file.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

namespace whitted {

// keyOf(i) is item i's key, for every i below `count`, a std::string_view
// that lives as long as the finder.
template <typename KeyOf>
class RepeatFinder {
  public:
    RepeatFinder(std::size_t count, KeyOf keyOf)
        : keyOf_(std::move(keyOf)),
          count_(count),
          slots_(std::bit_ceil(std::max<std::size_t>(16, count + count / 2))),
          mask_(slots_.size() - 1) {}

    // The earlier item whose key equals item `index`'s; else nothing, and
    // item `index` is kept for the items after it. Indices below 2^32 - 1.
    std::optional<std::size_t> add(std::size_t index) {
        const std::string_view key = keyOf_(index);
        const std::uint64_t hash = std::hash<std::string_view>{}(key);
        prefetchSlotOf(index + kAhead);
        const std::uint64_t tag = hash >> 32 << 32;
        for (std::size_t s = hash & mask_;; s = (s + 1) & mask_) {
            const std::uint64_t slot = slots_[s];
            if (slot == 0) {
                slots_[s] = tag | (std::uint64_t(index) + 1);
                return std::nullopt;
            }
            const std::size_t other = std::size_t(slot & 0xffffffffu) - 1;
            if ((slot & ~std::uint64_t(0xffffffffu)) == tag && keyOf_(other) == key) return other;
        }
    }

  private:
    // A million names' slots are scattered over 16 MB: the slot of the key
    // this many adds ahead is fetched meanwhile.
    static constexpr std::size_t kAhead = 8;
    void prefetchSlotOf(std::size_t index) const {
        if (index >= count_) return;
        __builtin_prefetch(&slots_[std::hash<std::string_view>{}(keyOf_(index)) & mask_]);
    }

    KeyOf keyOf_;
    std::size_t count_;
    std::vector<std::uint64_t> slots_;  // 0: empty; else tag | (index + 1)
    std::size_t mask_;
};

}  // namespace whitted
