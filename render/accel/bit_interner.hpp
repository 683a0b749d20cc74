// Keeps each distinct value once, by its bits: the shared transforms (a flattened shape's
// linear part, an instance's or a placement's linear pair) are looked up here while the world
// is built. By bits, not by value: a -0 and a +0 are different entries, so every matrix given
// back is exactly the one given.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace rts::render {

template <class T>
class BitInterner {
  // The bytes are the key: T must be plain doubles (no padding whose bytes are unspecified).
  static_assert(std::is_trivially_copyable_v<T> && sizeof(T) % sizeof(double) == 0);

 public:
  // v's index in `values`, appended there the first time its bits are seen. `values` is the
  // same vector on every call (the interner remembers indices into it, not the values).
  uint32_t intern(const T& v, std::vector<T>& values) {
    std::string key(sizeof(T), '\0');
    std::memcpy(key.data(), &v, sizeof(T));
    auto [it, fresh] = lookup_.try_emplace(std::move(key), static_cast<uint32_t>(values.size()));
    if (fresh) values.push_back(v);
    return it->second;
  }
  // Frees the lookup (only building needs it); the values stay where they are.
  void release() { lookup_ = {}; }

 private:
  std::unordered_map<std::string, uint32_t> lookup_;
};

}  // namespace rts::render
