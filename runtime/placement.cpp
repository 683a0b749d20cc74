#include "runtime/placement.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "parser/diagnostics.hpp"

namespace rts::runtime {

namespace {
// Placing a group of this many objects or more checks the memory budget first.
constexpr uint64_t kObjectsPerMemoryCheck = 1 << 16;
// What the renderer spends per object in the world (instance record, BVH share), roughly.
constexpr std::size_t kBytesPerInstance = 256;
// Where node's entry is, or would go, in a list sorted by node.
template <class List>
auto find_node(List& list, uint32_t node) {
  return std::lower_bound(list.begin(), list.end(), node, [](const auto& e, uint32_t n) { return e.first < n; });
}
}  // namespace

void Placement::admit(SourceLoc loc) {
  if (!allowed_)
    throw LanguageError(
        loc, "objects can only be placed at top level, in a group or in a macro (not inside another block)");
  if (++placements_ > limits_.max_objects)
    throw LanguageError(
        loc, fmt::format("more than {} objects placed (raise the limit with --max-objects)", limits_.max_objects));
}

bool Placement::to_world(const render::Child& c, SourceLoc loc) {
  if (target_) {
    target_->push_back(c);
    return false;
  }
  ObjectCount n = count(c.node);
  world_.shapes = std::min(world_.shapes + n.shapes, kSaturatedCount);
  world_.lights = std::min(world_.lights + n.lights, kSaturatedCount);
  if (published_) published_->store(world_.total(), std::memory_order_relaxed);
  if (world_.total() > limits_.max_objects)
    throw LanguageError(loc, fmt::format("the scene holds more than {} objects once its groups are expanded (raise the "
                                         "limit with --max-objects)",
                                         limits_.max_objects));
  // Every object in the world costs the renderer an instance record and BVH nodes.
  if (n.total() >= kObjectsPerMemoryCheck)
    budget_.check_memory(n.total() * kBytesPerInstance, loc, "this group's objects");
  return true;
}

void Placement::record(uint32_t node, ObjectCount count) {
  const bool one_shape = count.shapes == 1 && count.lights == 0;
  if (one_shape_.size() <= node) one_shape_.resize(std::size_t(node) + 1, false);
  one_shape_[node] = one_shape;
  auto it = find_node(other_counts_, node);
  const bool listed = it != other_counts_.end() && it->first == node;
  if (one_shape) {
    if (listed) other_counts_.erase(it);  // recorded again (not done today: nodes are recorded once)
  } else if (listed) {
    it->second = count;
  } else {
    other_counts_.insert(it, {node, count});  // at the end: nodes are recorded as they are made
  }
}

Placement::ObjectCount Placement::count(uint32_t node) const {
  if (node < one_shape_.size() && one_shape_[node]) return ObjectCount{1, 0};
  auto it = find_node(other_counts_, node);
  return it != other_counts_.end() && it->first == node ? it->second : ObjectCount{};
}

Placement::ObjectCount Placement::count(const std::vector<render::Child>& children) const {
  ObjectCount sum;
  for (const render::Child& c : children) {
    ObjectCount n = count(c.node);
    sum.shapes = std::min(sum.shapes + n.shapes, kSaturatedCount);
    sum.lights = std::min(sum.lights + n.lights, kSaturatedCount);
  }
  return sum;
}

}  // namespace rts::runtime
