// A small open-addressing hash map from 64-bit keys to int values, for the solvers' inner loops
// (space-time search nodes, path tables): linear probing, power-of-two capacity, load <= 1/2.
// ~0 is reserved as the empty key. Not thread-safe.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace swarm::planner::mapf::detail {

class FlatMap {
 public:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

  explicit FlatMap(std::size_t expected = 16) { reset(expected); }

  void reset(std::size_t expected) {
    std::size_t cap = 16;
    while (cap < 2 * expected) cap <<= 1;
    keys_.assign(cap, kEmpty);
    values_.assign(cap, 0);
    size_ = 0;
  }
  void clear() {
    if (size_ == 0) return;
    std::fill(keys_.begin(), keys_.end(), kEmpty);
    size_ = 0;
  }
  [[nodiscard]] std::size_t size() const { return size_; }

  // The value stored under key, or nullptr.
  [[nodiscard]] const int* find(std::uint64_t key) const {
    for (std::size_t i = slot(key);; i = (i + 1) & (keys_.size() - 1)) {
      if (keys_[i] == key) return &values_[i];
      if (keys_[i] == kEmpty) return nullptr;
    }
  }
  [[nodiscard]] int* find(std::uint64_t key) {
    return const_cast<int*>(static_cast<const FlatMap*>(this)->find(key));
  }
  // The value under key, inserted as `fresh` if missing; `inserted` tells which.
  int& get_or_insert(std::uint64_t key, int fresh, bool& inserted) {
    if (2 * (size_ + 1) > keys_.size()) grow();
    for (std::size_t i = slot(key);; i = (i + 1) & (keys_.size() - 1)) {
      if (keys_[i] == key) {
        inserted = false;
        return values_[i];
      }
      if (keys_[i] == kEmpty) {
        keys_[i] = key;
        values_[i] = fresh;
        ++size_;
        inserted = true;
        return values_[i];
      }
    }
  }

  static std::uint64_t key(int a, int b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
  }

 private:
  std::size_t slot(std::uint64_t key) const {
    key ^= key >> 33;
    key *= 0xff51afd7ed558ccdULL;
    key ^= key >> 33;
    return static_cast<std::size_t>(key) & (keys_.size() - 1);
  }
  void grow() {
    std::vector<std::uint64_t> old_keys;
    std::vector<int> old_values;
    old_keys.swap(keys_);
    old_values.swap(values_);
    keys_.assign(old_keys.size() * 2, kEmpty);
    values_.assign(old_keys.size() * 2, 0);
    size_ = 0;
    bool ins = false;
    for (std::size_t i = 0; i < old_keys.size(); ++i) {
      if (old_keys[i] != kEmpty) get_or_insert(old_keys[i], old_values[i], ins);
    }
  }

  std::vector<std::uint64_t> keys_;
  std::vector<int> values_;
  std::size_t size_ = 0;
};

}  // namespace swarm::planner::mapf::detail
