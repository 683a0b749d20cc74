// A vector that grows by chunks: the scene description's arrays with one entry per placed
// object (SceneDesc::shapes, ::nodes, ::roots; the evaluator's per-node counts). A scene of
// millions of shapes grows those arrays last and largest; a std::vector's doubling then holds
// the old and the new block at once (4M spheres: 537 MB more for the shapes at the end of
// evaluation, the whole render's peak), while here growing copies one chunk at most: chunks of
// 4096 elements, each a std::vector that grows by doubling up to that size (so a small scene
// holds no more than it uses) and is never moved once full. std::deque also grows without
// copying, but libstdc++'s 512-byte blocks (four shapes each) made every index a walk through
// its block map (the world's build 20% slower); here an index is one shift and one mask.
#pragma once

#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rts::render {

template <class T>
class ChunkedVector {
 public:
  static constexpr std::size_t kChunkBits = 12;
  static constexpr std::size_t kChunk = std::size_t{1} << kChunkBits;

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](std::size_t i) { return chunks_[i >> kChunkBits][i & (kChunk - 1)]; }
  const T& operator[](std::size_t i) const { return chunks_[i >> kChunkBits][i & (kChunk - 1)]; }
  T& at(std::size_t i) { return size_ > i ? (*this)[i] : throw std::out_of_range("ChunkedVector::at"); }
  const T& at(std::size_t i) const { return size_ > i ? (*this)[i] : throw std::out_of_range("ChunkedVector::at"); }
  T& back() { return (*this)[size_ - 1]; }
  const T& back() const { return (*this)[size_ - 1]; }

  void push_back(const T& v) { emplace_back(v); }
  void push_back(T&& v) { emplace_back(std::move(v)); }
  template <class... Args>
  T& emplace_back(Args&&... args) {
    if (chunks_.empty() || chunks_.back().size() == kChunk) chunks_.emplace_back();
    T& placed = chunks_.back().emplace_back(std::forward<Args>(args)...);
    ++size_;
    return placed;
  }
  // Appends default elements up to size n (never shrinks).
  void grow_to(std::size_t n) {
    while (size_ < n) emplace_back();
  }
  void clear() {
    chunks_.clear();
    size_ = 0;
  }

  // The chunk that holds element i, and how many chunks there are.
  static constexpr std::size_t chunk_of(std::size_t i) { return i >> kChunkBits; }
  std::size_t chunk_count() const { return chunks_.size(); }
  std::size_t chunk_capacity_bytes(std::size_t k) const { return chunks_[k].capacity() * sizeof(T); }
  // Frees chunk k's elements ahead of the rest, for a reader that has passed them for good (the
  // world's build consuming a scene it took: World's constructor). size() is unchanged;
  // reading an element of a released chunk afterwards is an error.
  void release_chunk(std::size_t k) { std::vector<T>().swap(chunks_[k]); }
  void swap(ChunkedVector& other) noexcept {
    chunks_.swap(other.chunks_);
    std::swap(size_, other.size_);
  }

  // Forward iteration in index order (range-for).
  template <class Owner, class Value>
  class Iter {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = T;
    using difference_type = std::ptrdiff_t;
    using pointer = Value*;
    using reference = Value&;
    Iter() = default;
    Iter(Owner* owner, std::size_t i) : owner_(owner), i_(i) {}
    reference operator*() const { return (*owner_)[i_]; }
    pointer operator->() const { return &(*owner_)[i_]; }
    Iter& operator++() {
      ++i_;
      return *this;
    }
    Iter operator++(int) {
      Iter before = *this;
      ++i_;
      return before;
    }
    bool operator==(const Iter& o) const { return i_ == o.i_; }
    bool operator!=(const Iter& o) const { return i_ != o.i_; }

   private:
    Owner* owner_ = nullptr;
    std::size_t i_ = 0;
  };
  using iterator = Iter<ChunkedVector, T>;
  using const_iterator = Iter<const ChunkedVector, const T>;
  iterator begin() { return {this, 0}; }
  iterator end() { return {this, size_}; }
  const_iterator begin() const { return {this, 0}; }
  const_iterator end() const { return {this, size_}; }

 private:
  std::vector<std::vector<T>> chunks_;  // every one full (kChunk elements) but the last
  std::size_t size_ = 0;
};

}  // namespace rts::render
