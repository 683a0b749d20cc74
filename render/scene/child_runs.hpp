// The world's placements (SceneDesc::roots) kept as runs: consecutive placements of
// consecutive nodes with the same transform block and the same location are one entry. A loop
// that writes `sphere { ... }` places each new sphere's node right after the last one, with no
// transform of its own and from the same place in the file, so a million such spheres are one
// run instead of a million 32-byte children. Profile finding (issue 24, RSS trace of 4M
// spheres placed by two loops): the roots were 134 MB of the 706 MB held at the end of
// evaluation, the whole render's peak. A placement that breaks the pattern costs one run, the
// size of the Child it was (the run's count sits in the Child's padding).
//
// Read in order only (range-for yields each Child by value, exactly as placed): the
// flattening, the summaries and the checks walk the placements front to back.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <utility>

#include "render/scene/chunked_vector.hpp"

namespace rts::render {

template <class Child>
class ChildRuns {
 public:
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  void push_back(const Child& c) {
    ++size_;
    if (!runs_.empty()) {
      Run& last = runs_.back();
      if (c.node == last.node + last.count && c.transform.same_block(last.transform) && same_place(c.loc, last.loc)) {
        ++last.count;
        return;
      }
    }
    runs_.push_back(Run{c.node, 1, c.transform, c.loc});
  }
  // How many entries the placements take (the tests check the runs).
  std::size_t run_count() const { return runs_.size(); }
  void clear() {
    runs_.clear();
    size_ = 0;
  }
  void swap(ChildRuns& other) noexcept {
    runs_.swap(other.runs_);
    std::swap(size_, other.size_);
  }

  class const_iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = Child;
    using difference_type = std::ptrdiff_t;
    using pointer = const Child*;
    using reference = Child;
    const_iterator() = default;
    const_iterator(const ChildRuns* owner, std::size_t run) : owner_(owner), run_(run) {}
    Child operator*() const {
      const Run& r = owner_->runs_[run_];
      return Child{r.node + k_, r.transform, r.loc};
    }
    const_iterator& operator++() {
      if (++k_ == owner_->runs_[run_].count) {
        ++run_;
        k_ = 0;
      }
      return *this;
    }
    const_iterator operator++(int) {
      const_iterator before = *this;
      ++*this;
      return before;
    }
    bool operator==(const const_iterator& o) const { return run_ == o.run_ && k_ == o.k_; }
    bool operator!=(const const_iterator& o) const { return !(*this == o); }

   private:
    const ChildRuns* owner_ = nullptr;
    std::size_t run_ = 0;
    uint32_t k_ = 0;  // within the run
  };
  const_iterator begin() const { return {this, 0}; }
  const_iterator end() const { return {this, runs_.size()}; }

 private:
  // `count` placements; the k-th is of node `node + k`, with the same transform and location.
  struct Run {
    decltype(Child::node) node;
    uint32_t count;
    decltype(Child::transform) transform;
    decltype(Child::loc) loc;
  };
  static_assert(sizeof(void*) != 8 || sizeof(Run) <= sizeof(Child), "a run of one costs more than the child");
  template <class Loc>
  static bool same_place(const Loc& a, const Loc& b) {
    return a.file == b.file && a.line == b.line && a.col == b.col;
  }
  ChunkedVector<Run> runs_;
  std::size_t size_ = 0;
};

}  // namespace rts::render
