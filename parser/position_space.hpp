// The space of positions SourceLoc points into (parser/source.hpp): each loaded file's run
// of positions. Internal to parser/source.cpp; a header of its own so that tests can run one
// with a small end.
#pragma once

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <shared_mutex>
#include <utility>
#include <vector>

#include "parser/source.hpp"

namespace rts::source_detail {

// The position space SourceLoc resolves through: each live file's run of positions, sorted.
// Runs are handed out in order from 1; once the 2^31 positions are used up, a file gets the
// first gap a freed file left that fits it, and the generation changes so that no thread's
// cache keeps naming the old file. Lookups take a shared lock (the language server analyses
// on several threads); most never get here (LineCache).
class PositionSpace {
 public:
  static constexpr uint64_t kEnd = uint64_t{1} << 31;

  uint32_t add(const SourceFile* f, std::size_t positions) {
    std::unique_lock lock(mutex_);
    uint64_t first = next_;
    auto at = runs_.end();
    if (next_ + positions > end_) {
      // Out of fresh positions: the first gap that fits, in order.
      first = 1;
      at = runs_.begin();
      while (at != runs_.end() && first + positions > at->first) first = uint64_t{at->first} + at->count, ++at;
      if (at == runs_.end() && first + positions > end_)
        throw SourceError("error: the files loaded at once hold more than 2 GiB of text");
      source_detail::generation.fetch_add(1, std::memory_order_acq_rel);
    } else {
      next_ += positions;
    }
    runs_.insert(at, Run{static_cast<uint32_t>(first), static_cast<uint32_t>(positions), f});
    return static_cast<uint32_t>(first);
  }
  void remove(uint32_t first) {
    std::unique_lock lock(mutex_);
    auto it = std::lower_bound(runs_.begin(), runs_.end(), first, [](const Run& r, uint32_t p) { return r.first < p; });
    if (it != runs_.end() && it->first == first) runs_.erase(it);
  }
  // Ends the space at `end` (tests of running out; at most kEnd).
  explicit PositionSpace(uint64_t end = kEnd) : end_(std::min(end, kEnd)) {}
  // The file holding position p and its first position, or null.
  std::pair<const SourceFile*, uint32_t> find(uint32_t p) const {
    std::shared_lock lock(mutex_);
    auto it = std::upper_bound(runs_.begin(), runs_.end(), p, [](uint32_t q, const Run& r) { return q < r.first; });
    if (it == runs_.begin()) return {nullptr, 0};
    --it;
    if (p - it->first >= it->count) return {nullptr, 0};
    return {it->file, it->first};
  }

 private:
  struct Run {
    uint32_t first, count;
    const SourceFile* file;
  };
  mutable std::shared_mutex mutex_;
  std::vector<Run> runs_;
  uint64_t next_ = 1;  // 0 means "no location"
  uint64_t end_;
};

}  // namespace rts::source_detail
