// A value kept on the heap behind one pointer and copied with its owner (deep copy): the
// large, rarely used parts of a shape live in one, so they stay out of ShapeGeometry's size.
// Every alternative of that variant pays for the largest one: a sphere's description was
// 216 bytes for the sake of a prism's outline, a triangle's vertex normals and an
// isosurface's container (profile finding: bench/growth/spheres.rts at 4M spheres).
#pragma once

#include <memory>
#include <utility>

namespace rts::render {

template <class T>
class Boxed {
 public:
  Boxed() = default;
  explicit Boxed(T value) : p_(std::make_unique<T>(std::move(value))) {}
  Boxed(const Boxed& other) : p_(other.p_ ? std::make_unique<T>(*other.p_) : nullptr) {}
  Boxed(Boxed&&) noexcept = default;
  Boxed& operator=(const Boxed& other) {
    if (this != &other) p_ = other.p_ ? std::make_unique<T>(*other.p_) : nullptr;
    return *this;
  }
  Boxed& operator=(Boxed&&) noexcept = default;

  explicit operator bool() const { return p_ != nullptr; }
  T& operator*() { return *p_; }
  const T& operator*() const { return *p_; }
  T* operator->() { return p_.get(); }
  const T* operator->() const { return p_.get(); }

 private:
  std::unique_ptr<T> p_;
};

// A shape kind whose whole data is boxed (a prism, an isosurface): built from its data, which
// `->` and `*` reach. Each kind derives its own type from it, so the ShapeGeometry variant
// still tells them apart.
template <class Data>
struct BoxedShape {
  Boxed<Data> data{Data{}};
  BoxedShape() = default;
  BoxedShape(Data d) : data(std::move(d)) {}  // NOLINT: a shape from its data
  Data* operator->() { return data.operator->(); }
  const Data* operator->() const { return data.operator->(); }
  const Data& operator*() const { return *data; }
};

}  // namespace rts::render
