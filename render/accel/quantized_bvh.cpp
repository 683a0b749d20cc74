#include "render/accel/quantized_bvh.hpp"

#include <algorithm>
#include <cmath>

namespace rts::render {

namespace {

QuantizedBox from_floats(const float lo[3], const float hi[3]) {
  return QuantizedBox{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
}

// A subtree of the binary tree, or a run of a leaf's primitives (split in halves here).
struct Item {
  bool is_node = true;
  uint32_t node = 0;              // is_node: its index in bvh.nodes
  uint32_t begin = 0, count = 0;  // otherwise: slots [begin, begin + count) of bvh.order
  QuantizedBox box{};             // its own box: float bounds, rounded outwards
};

class Quantizer {
 public:
  Quantizer(const BVH& bvh, const std::function<AABB(uint32_t)>& box_of, QuantizedBVH& out)
      : bvh_(bvh), box_of_(box_of), out_(out) {}

  bool failed() const { return failed_; }

  Item node_item(uint32_t index) const {
    Item item;
    item.node = index;
    item.box = from_floats(bvh_.nodes[index].lo, bvh_.nodes[index].hi);
    return item;
  }

  // The reference to `item`, whose decoded box is `box`: the primitive itself for one, or a
  // node made here with its children's codes against `box`.
  uint32_t emit(const Item& item, const QuantizedBox& box) {
    if (failed_) return 0;
    uint32_t single = 0;
    if (is_single(item, single)) return QuantizedNode::kLeafBit | single;
    if (out_.nodes.size() >= QuantizedNode::kLeafBit) {
      failed_ = true;
      return 0;
    }
    const uint32_t index = static_cast<uint32_t>(out_.nodes.size());
    out_.nodes.emplace_back();
    Item child[2];
    children(item, child);
    QuantizedBox decoded[2];
    for (int c = 0; c < 2; ++c)
      if (!encode(box, child[c].box, out_.nodes[index], c, decoded[c])) {
        failed_ = true;
        return 0;
      }
    for (int c = 0; c < 2; ++c) {
      const uint32_t ref = emit(child[c], decoded[c]);
      out_.nodes[index].child[c] = ref;
    }
    return index;
  }

 private:
  bool is_single(const Item& item, uint32_t& primitive) {
    uint32_t begin = item.begin, count = item.count;
    if (item.is_node) {
      const BVHNode& n = bvh_.nodes[item.node];
      if (n.count == 0) return false;
      begin = n.offset;
      count = n.count;
    }
    if (count != 1) return false;
    primitive = bvh_.order[begin];
    if (primitive >= QuantizedNode::kLeafBit) failed_ = true;
    return true;
  }

  Item run(uint32_t begin, uint32_t count) const {
    Item item;
    item.is_node = false;
    item.begin = begin;
    item.count = count;
    AABB box;
    for (uint32_t s = begin; s < begin + count; ++s) box.extend(leaf_boxes_[s - leaf_begin_]);
    float lo[3], hi[3];
    round_outwards(box, lo, hi);
    item.box = from_floats(lo, hi);
    return item;
  }

  void children(const Item& item, Item child[2]) {
    uint32_t begin = item.begin, count = item.count;
    if (item.is_node) {
      const BVHNode& n = bvh_.nodes[item.node];
      if (n.count == 0) {
        child[0] = node_item(item.node + 1);
        child[1] = node_item(n.offset);
        return;
      }
      begin = n.offset;
      count = n.count;
      // The leaf's boxes, once each: its runs are emitted before the next leaf's. Profile
      // finding (4M placements): asking box_of again at each halving made quantizing 0.7 s.
      leaf_begin_ = begin;
      leaf_boxes_.clear();
      for (uint32_t s = begin; s < begin + count; ++s) leaf_boxes_.push_back(box_of_(bvh_.order[s]));
    }
    child[0] = run(begin, count / 2);
    child[1] = run(begin + count / 2, count - count / 2);
  }

  // Child c's codes in `node` for its box `child` inside `parent` (decoded), and the box they
  // decode to, which encloses `child`: each bound is first put on the step at or outside it,
  // then stepped further out while the decoding's rounding leaves it inside (0 decodes to the
  // parent's own bound, which encloses it).
  static bool encode(const QuantizedBox& parent, const QuantizedBox& child, QuantizedNode& node, int c,
                     QuantizedBox& decoded) {
    for (int a = 0; a < 3; ++a) {
      if (!(child.lo[a] >= parent.lo[a] && child.hi[a] <= parent.hi[a])) return false;  // also NaN
      const double step = quantized_step(parent.lo[a], parent.hi[a]);
      double in_lo = 0.0, in_hi = 0.0;
      if (step > 0.0) {
        in_lo = std::floor((child.lo[a] - parent.lo[a]) / step);
        in_hi = std::floor((parent.hi[a] - child.hi[a]) / step);
      }
      node.code[2 * a + c] = static_cast<uint8_t>(std::clamp(in_lo, 0.0, 255.0));
      node.code[6 + 2 * a + c] = static_cast<uint8_t>(std::clamp(in_hi, 0.0, 255.0));
    }
    decode_child(parent, node, c, decoded);
    for (int a = 0; a < 3; ++a) {
      while (decoded.lo[a] > child.lo[a]) {
        --node.code[2 * a + c];
        decode_child(parent, node, c, decoded);
      }
      while (decoded.hi[a] < child.hi[a]) {
        --node.code[6 + 2 * a + c];
        decode_child(parent, node, c, decoded);
      }
    }
    return true;
  }

  const BVH& bvh_;
  const std::function<AABB(uint32_t)>& box_of_;
  std::vector<AABB> leaf_boxes_;  // the boxes of the binary leaf being split, from leaf_begin_
  uint32_t leaf_begin_ = 0;
  QuantizedBVH& out_;
  bool failed_ = false;
};

}  // namespace

QuantizedBVH quantize_bvh(const BVH& bvh, const std::function<AABB(uint32_t)>& box_of) {
  QuantizedBVH out;
  if (bvh.nodes.empty()) return out;
  Quantizer q(bvh, box_of, out);
  const Item root = q.node_item(0);
  for (int a = 0; a < 3; ++a) {
    // Steps of an infinite extent decode to infinities and NaNs (0 * inf).
    if (!std::isfinite(root.box.lo[a]) || !std::isfinite(root.box.hi[a])) return {};
  }
  out.nodes.reserve(bvh.order.size() > 0 ? bvh.order.size() - 1 : 0);
  out.root_box = root.box;
  out.root = q.emit(root, root.box);
  if (q.failed()) return {};
  out.nodes.shrink_to_fit();
  out.present = true;
  return out;
}

}  // namespace rts::render
