// Frees a taken scene's shapes while the world's instances are made from them (World's
// constructor, PreparedScene of a scene it owns). Profile finding (issue 24, 4M spheres, RSS
// trace): the process peaked while the instances were made, with every 128-byte shape
// description still held beside the 48-byte instances made from it. The description's shapes
// grow by chunks (ChunkedVector); a chunk is freed once the loop over the placed shapes has
// passed the last placement that reads it, unless an instanced group or a CSG block (made
// after that loop, from the same array) reads one of its shapes. Scenes made by loops place
// their shapes in the order they were described, so the chunks go one by one.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/accel/flatten.hpp"
#include "render/accel/memory.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

class ShapeRelease {
 public:
  // Nothing is released when `taken` is null (the caller keeps the scene).
  ShapeRelease(SceneDesc* taken, const FlatScene& flat) : taken_(taken) {
    if (!taken_ || flat.shapes.size() < kReleaseMemoryMinItems) {
      taken_ = nullptr;
      return;
    }
    ChunkedVector<ShapeDesc>& shapes = taken_->shapes;
    constexpr std::size_t kNever = ~std::size_t{0};
    std::vector<std::size_t> last(shapes.chunk_count(), kNever);
    for (std::size_t i = 0; i < flat.shapes.size(); ++i) {
      const std::size_t k = ChunkedVector<ShapeDesc>::chunk_of(flat.shapes[i].shape);
      if (k < last.size()) last[k] = i;
    }
    // Shapes read after the loop: group members and CSG leaves (nested blocks are in the same
    // arrays, so their direct children cover every level).
    auto pin = [&](const std::vector<Child>& children) {
      for (const Child& c : children)
        if (c.node < taken_->nodes.size() && taken_->nodes[c.node].kind == NodeKind::Shape) {
          const std::size_t k = ChunkedVector<ShapeDesc>::chunk_of(taken_->nodes[c.node].index);
          if (k < last.size()) last[k] = kNever;
        }
    };
    for (const GroupDesc& g : taken_->groups) pin(g.children);
    for (const CsgDesc& c : taken_->csgs) pin(c.children);
    for (std::size_t k = 0; k < last.size(); ++k)
      if (last[k] != kNever) order_.push_back({last[k], k});
    std::sort(order_.begin(), order_.end());
  }

  // The loop has made the instance of placement i (and every one before it).
  void passed(std::size_t i) {
    if (!taken_) return;
    while (next_ < order_.size() && order_[next_].last_use <= i) {
      const std::size_t k = order_[next_++].chunk;
      released_ += taken_->shapes.chunk_capacity_bytes(k);
      taken_->shapes.release_chunk(k);
    }
    // The chunks lie in the evaluation's heap (runtime/evaluator.cpp keeps large blocks there):
    // freed, they stay resident until the heap's free pages are handed back.
    if (released_ >= kReturnBytes) {
      return_free_pages();
      released_ = 0;
    }
  }

 private:
  // Enough freed to be worth a scan of the heap (4M spheres: eight scans).
  static constexpr std::size_t kReturnBytes = std::size_t{64} << 20;
  struct Release {
    std::size_t last_use, chunk;
    bool operator<(const Release& o) const { return last_use < o.last_use || (last_use == o.last_use && chunk < o.chunk); }
  };
  SceneDesc* taken_;
  std::vector<Release> order_;
  std::size_t next_ = 0;
  std::size_t released_ = 0;
};

}  // namespace rts::render
