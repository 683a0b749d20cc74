// The media a path is inside (POV-Ray's and pbrt's "nested dielectrics"): a small stack of
// the transmissive instances the path has entered, each with its absolute index of
// refraction, so a surface refracts with the ratio of the media on its two sides (water 1.33
// inside glass 1.5 bends by 1.5/1.33, not by 1/1.33). Outside everything is vacuum/air, 1.
// Each entry also names the participating medium that fills the inside (render/shade/
// medium.hpp), if any: the innermost entry's is the one the path travels through.
#pragma once

#include <array>
#include <cstdint>

#include "render/geometry/tolerances.hpp"
#include "render/scene/scene.hpp"
#include "render/shade/material.hpp"

namespace rts::render {

class MediumStack {
 public:
  // User-provided, so that `MediumStack{}` does not zero the entries first.
  MediumStack() noexcept {}
  // The index of the medium the path is in now.
  double current() const { return size_ > 0 ? entries_[size_ - 1].ior : 1.0; }

  // The participating medium the path is in: the innermost entry's (kNoId: a clear inside),
  // or `outside` (the scene's, or kNoId) when it is inside nothing.
  MediumId medium(MediumId outside) const { return size_ > 0 ? entries_[size_ - 1].medium : outside; }

  // The absolute index of `instance` if the path is inside it.
  bool find(uint32_t instance, double& ior) const {
    for (int i = size_ - 1; i >= 0; --i)
      if (entries_[i].instance == instance) {
        ior = entries_[i].ior;
        return true;
      }
    return false;
  }

  // The index of the medium around `instance`: what the path is in once it leaves it.
  double outside(uint32_t instance) const {
    for (int i = size_ - 1; i >= 0; --i)
      if (entries_[i].instance == instance) {
        // The innermost other medium still entered (media may overlap, not only nest).
        for (int j = size_ - 1; j >= 0; --j)
          if (j != i) return entries_[j].ior;
        return 1.0;
      }
    return current();
  }

  // The indices on the two sides of a surface of `m` around `instance`, seen from the side a
  // ray comes from (`entering`: from outside): `ior` is absolute unless `ior_relative`, and a
  // surface left without having been entered (a camera inside) takes its own index inside.
  void interface(uint32_t instance, const MaterialDesc& m, bool entering, double& n_from, double& n_to) const {
    if (entering) {
      n_from = current();
      n_to = m.ior_relative ? n_from * m.ior : m.ior;
    } else {
      n_to = outside(instance);
      if (!find(instance, n_from)) n_from = m.ior_relative ? n_to * m.ior : m.ior;
    }
  }

  // Crosses a surface light passes through unchanged (passes_through(m), with the same index
  // on both sides): enters or leaves `instance` and returns true. Any other surface: false,
  // and the stack is as it was.
  bool cross_clear(uint32_t instance, const MaterialDesc& m, bool entering) {
    if (!passes_through(m)) return false;
    double n_from = 1.0, n_to = 1.0;
    interface(instance, m, entering, n_from, n_to);
    if (n_from != n_to) return false;
    if (entering)
      enter(instance, n_to, m.medium);
    else
      leave(instance);
    return true;
  }

  // Deeper nesting than the stack holds is not tracked: the path keeps the ratio of the
  // innermost media it does track (documented in docs/rendering.md).
  void enter(uint32_t instance, double ior, MediumId medium = kNoId) {
    if (size_ < tol::kMaxNestedMedia) entries_[size_++] = Entry{instance, static_cast<float>(ior), medium};
  }

  void leave(uint32_t instance) {
    for (int i = size_ - 1; i >= 0; --i)
      if (entries_[i].instance == instance) {
        for (int j = i; j + 1 < size_; ++j) entries_[j] = entries_[j + 1];
        --size_;
        return;
      }
  }

  int size() const { return size_; }

 private:
  // Float indices keep a pending ray small (it is copied on every bounce); 1e-7 relative is
  // far below any index a scene states.
  struct Entry {
    uint32_t instance;
    float ior;
    MediumId medium;
  };
  // Only the first size_ entries are ever read, so the rest stay uninitialised: a zeroed array
  // was written for every camera ray's PendingRay (profile finding: integrator.cpp's
  // `MediumStack{}` 1% of the csg race scene).
  std::array<Entry, tol::kMaxNestedMedia> entries_;
  int size_ = 0;
};

}  // namespace rts::render
