// Where placed objects go and how many there are: the world, or the body of the group or CSG
// block being evaluated; and the object counts behind --max-objects (a group's count is what
// it expands to, so groups of groups cannot multiply past the limit unseen). Internal to
// runtime/: the interpreter asks it before handing an object to the scene builder.
#pragma once

#include <atomic>
#include <cstdint>
#include <utility>
#include <vector>

#include "parser/source.hpp"
#include "render/scene/scene.hpp"
#include "runtime/budget.hpp"
#include "runtime/evaluator.hpp"

namespace rts::runtime {

class Placement {
 public:
  // Shapes and lights a node stands for once groups are expanded (1 for a shape or light).
  struct ObjectCount {
    uint64_t shapes = 0, lights = 0;
    uint64_t total() const { return shapes + lights; }
  };
  // Object counts stop growing here (no overflow however groups multiply).
  static constexpr uint64_t kSaturatedCount = uint64_t(1) << 62;

  // `published` (EvalOptions::placed, may be null) receives the world's object count after
  // each placement, for a progress display on another thread.
  Placement(const EvalLimits& limits, const Budget& budget, std::atomic<uint64_t>* published = nullptr)
      : limits_(limits), budget_(budget), published_(published) {}

  // While one lives, objects placed go into `children` (the body of a group or CSG block).
  class Into {
   public:
    Into(Placement& p, std::vector<render::Child>& children) : p_(p), saved_(p.target_) { p.target_ = &children; }
    ~Into() { p_.target_ = saved_; }
    Into(const Into&) = delete;
    Into& operator=(const Into&) = delete;

   private:
    Placement& p_;
    std::vector<render::Child>* saved_;
  };
  // While one lives, placing an object is allowed or not (inside a material, a shape's
  // properties... it is an error).
  class Allow {
   public:
    Allow(Placement& p, bool allowed) : p_(p), saved_(p.allowed_) { p.allowed_ = allowed; }
    ~Allow() { p_.allowed_ = saved_; }
    Allow(const Allow&) = delete;
    Allow& operator=(const Allow&) = delete;

   private:
    Placement& p_;
    bool saved_;
  };

  // Fails unless an object may be placed here, and counts the placement against --max-objects.
  void admit(SourceLoc loc);
  // Takes the placed object `c`: into the body being collected (false), or counted into the
  // world against --max-objects and --max-memory (true: the caller hands it to the builder).
  bool to_world(const render::Child& c, SourceLoc loc);

  void record(uint32_t node, ObjectCount count);
  ObjectCount count(uint32_t node) const;
  // What `children` expand to, saturated at kSaturatedCount.
  ObjectCount count(const std::vector<render::Child>& children) const;
  ObjectCount world() const { return world_; }

 private:
  const EvalLimits& limits_;
  const Budget& budget_;
  std::vector<render::Child>* target_ = nullptr;  // null: the world
  bool allowed_ = true;
  std::size_t placements_ = 0;
  // The recorded counts by NodeId: a bit for each node that stands for one shape (nearly every
  // node of a large scene), and the others' counts (lights, groups, CSG blocks) sorted by node.
  // Profile finding (issue 24, RSS trace of 4M spheres placed by loops): 16 bytes per node,
  // 67 MB of the evaluation's peak, when all but a few said "one shape".
  std::vector<bool> one_shape_;
  std::vector<std::pair<uint32_t, ObjectCount>> other_counts_;
  ObjectCount world_;                     // placed in the world, groups expanded
  std::atomic<uint64_t>* published_ = nullptr;  // EvalOptions::placed
};

}  // namespace rts::runtime
