#include "render/scene/child_transform.hpp"

#include <cstddef>

namespace rts::render {

// The linear blocks made lately by this thread, by their bits: the scene's evaluation makes the
// children on one thread, and a loop's placements repeat a few rotations and scales. Four ways
// per set, so a handful of rotations that fall in one set do not evict each other on every
// placement (direct-mapped, 8 of a loop's 90 rotations did). Each entry holds a reference, so a
// block lives at least as long as its entry (8 KB of pointers per thread); an entry replaced
// lets its block go with its last child.
struct LinearCache {
  static constexpr std::size_t kSets = 256, kWays = 4;
  const ChildTransform::Linear* way[kSets][kWays] = {};
  uint8_t next[kSets] = {};  // the way a miss replaces, in turn
  ~LinearCache() {
    for (auto& set : way)
      for (const ChildTransform::Linear* l : set) ChildTransform::release(l);
  }
};

namespace {

std::size_t linear_hash(const glm::dvec4* columns) {
  // FNV-1a over the 96 bytes, 8 at a time, then folded: equal bits, equal slot.
  uint64_t h = 14695981039346656037ull;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 4; ++r) {
      uint64_t bits;
      std::memcpy(&bits, &columns[c][r], sizeof bits);
      h = (h ^ bits) * 1099511628211ull;
    }
  return static_cast<std::size_t>(h ^ (h >> 29) ^ (h >> 47));
}

}  // namespace

const ChildTransform::Linear* ChildTransform::shared_linear(const glm::dmat4& m) {
  thread_local LinearCache cache;
  const glm::dvec4 columns[3] = {m[0], m[1], m[2]};
  const std::size_t set = linear_hash(columns) % LinearCache::kSets;
  for (const Linear* l : cache.way[set])
    if (l && std::memcmp(l->columns, columns, sizeof columns) == 0) {
      retain(l);  // the caller's reference
      return l;
    }
  Linear* made = new Linear;
  std::memcpy(made->columns, columns, sizeof columns);
  const Linear*& slot = cache.way[set][cache.next[set]];
  cache.next[set] = static_cast<uint8_t>((cache.next[set] + 1) % LinearCache::kWays);
  release(slot);
  slot = made;  // the cache's reference
  retain(made);  // the caller's
  return made;
}

ChildTransform::ChildTransform(const glm::dmat4& m) {
  static const glm::dmat4 kIdentity(1.0);
  if (m == kIdentity) return;  // by value, as before: a -0 entry is the identity too
  if (m[3].w != 1.0) {  // projective: the whole matrix
    block_ = new Matrix(m);
    return;
  }
  // By bits: the rebuilt matrix must be this one exactly (a -0 in the linear part is kept).
  if (std::memcmp(&m, &kIdentity, 3 * sizeof(glm::dvec4)) == 0)
    block_ = new Offset(glm::dvec3(m[3]));
  else
    block_ = new Placed(shared_linear(m), glm::dvec3(m[3]));
}

bool ChildTransform::shares_linear_part(const ChildTransform& a, const ChildTransform& b) {
  if (!a.block_ || !b.block_ || a.block_->kind != Kind::Placed || b.block_->kind != Kind::Placed) return false;
  return static_cast<const Placed*>(a.block_)->linear == static_cast<const Placed*>(b.block_)->linear;
}

void ChildTransform::destroy(const Block* b) noexcept {
  switch (b->kind) {
    case Kind::Offset:
      delete static_cast<const Offset*>(b);
      break;
    case Kind::Linear:
      delete static_cast<const Linear*>(b);
      break;
    case Kind::Placed: {
      const Linear* l = static_cast<const Placed*>(b)->linear;
      delete static_cast<const Placed*>(b);
      release(l);
      break;
    }
    case Kind::Matrix:
      delete static_cast<const Matrix*>(b);
      break;
  }
}

}  // namespace rts::render
