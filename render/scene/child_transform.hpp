// A child's placement, child space → parent space (render/scene/scene.hpp's Child). The identity
// costs no block: shapes placed by loops mostly carry their position in their own parameters,
// and a 128-byte matrix per such child was a third of the scene description of a million
// spheres (issue 24's memory per object). A pure translation (`translate`, the usual way to
// place an object) keeps only its offset (a 32-byte block). Any other affine transform keeps its
// offset and a pointer to its linear part (a 40-byte block), and linear parts equal bit for bit
// are one block (shared_linear: a loop placing a group `rotate`d and `translate`d repeats a few
// rotations, and a 136-byte matrix per placement was most of the description of a million of
// them). A projective matrix keeps the whole matrix. matrix() gives the matrix back bit for bit;
// the blocks are shared by the copies of the child.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstring>
#include <utility>

#include <glm/glm.hpp>

namespace rts::render {

class ChildTransform {
 public:
  ChildTransform() = default;
  ChildTransform(const glm::dmat4& m);  // NOLINT: implicit, a child is placed by a matrix
  ChildTransform(const ChildTransform& o) noexcept : block_(o.block_) { retain(block_); }
  ChildTransform(ChildTransform&& o) noexcept : block_(std::exchange(o.block_, nullptr)) {}
  ChildTransform& operator=(const ChildTransform& o) noexcept {
    if (block_ != o.block_) {
      release(block_);
      block_ = o.block_;
      retain(block_);
    }
    return *this;
  }
  ChildTransform& operator=(ChildTransform&& o) noexcept {
    if (this != &o) {
      release(block_);
      block_ = std::exchange(o.block_, nullptr);
    }
    return *this;
  }
  ~ChildTransform() { release(block_); }

  // The same transform by identity: both the identity, or copies of one child's transform
  // (which need not be the only way to write it: equal matrices made apart are not one block).
  bool same_block(const ChildTransform& o) const { return block_ == o.block_; }

  glm::dmat4 matrix() const {
    if (!block_) return glm::dmat4(1.0);
    switch (block_->kind) {
      case Kind::Offset: {
        glm::dmat4 m(1.0);
        m[3] = glm::dvec4(static_cast<const Offset&>(*block_).offset, 1.0);
        return m;
      }
      case Kind::Placed: {
        const Placed& p = static_cast<const Placed&>(*block_);
        const glm::dvec4* c = p.linear->columns;
        return glm::dmat4(c[0], c[1], c[2], glm::dvec4(p.offset, 1.0));
      }
      default:
        return static_cast<const Matrix&>(*block_).m;
    }
  }
  operator glm::dmat4() const { return matrix(); }  // NOLINT: reads as the matrix it is
  glm::dvec4 operator[](int column) const { return matrix()[column]; }

  // Whether both keep their linear part in one block (tests: a loop's repeated rotations do).
  static bool shares_linear_part(const ChildTransform& a, const ChildTransform& b);

 private:
  enum class Kind : uint8_t { Offset, Linear, Placed, Matrix };
  // Counted in the block itself: one pointer per child (a shared_ptr was two, and its control
  // block 16 bytes more per block).
  struct Block {
    explicit Block(Kind k) : kind(k) {}
    mutable std::atomic<uint32_t> refs{1};
    Kind kind;
  };
  struct Offset : Block {
    explicit Offset(const glm::dvec3& t) : Block(Kind::Offset), offset(t) {}
    glm::dvec3 offset;
  };
  // The first three columns of an affine matrix, w components included (bit for bit).
  struct Linear : Block {
    Linear() : Block(Kind::Linear) {}
    glm::dvec4 columns[3];
  };
  struct Placed : Block {
    Placed(const Linear* l, const glm::dvec3& t) : Block(Kind::Placed), linear(l), offset(t) {}
    const Linear* linear;  // holds a reference
    glm::dvec3 offset;
  };
  struct Matrix : Block {
    explicit Matrix(const glm::dmat4& matrix) : Block(Kind::Matrix), m(matrix) {}
    glm::dmat4 m;
  };
  // A block with m's linear part, shared with the earlier ones of the same bits (a reference
  // the caller owns).
  static const Linear* shared_linear(const glm::dmat4& m);
  static void retain(const Block* b) noexcept {
    if (b) b->refs.fetch_add(1, std::memory_order_relaxed);
  }
  static void release(const Block* b) noexcept {
    if (!b || b->refs.fetch_sub(1, std::memory_order_acq_rel) != 1) return;
    destroy(b);
  }
  static void destroy(const Block* b) noexcept;
  friend struct LinearCache;

  const Block* block_ = nullptr;
};

}  // namespace rts::render
