// A vector that holds up to N elements in place and more on the heap: the points and corners of
// a K-gon. A mesh has one K-gon per face, vertex and edge, nearly all of them with K <= 4, so
// keeping those in place makes the K-gons of a mesh three arrays rather than two small heap
// blocks per K-gon (on a 100k-quad mesh, 800k blocks that a fresh heap faults in 4 kB at a time).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace stitch {

namespace detail {
/// A defined value for unused and new elements: zero for Eigen's vectors, whose default
/// constructor leaves them uninitialized (copying those would copy indeterminate values).
template <class T>
T zero_value() {
  if constexpr (requires { T::Zero(); })
    return T::Zero();
  else
    return T{};
}
}  // namespace detail

/// The elements live in place while there are at most N of them, else in `heap_` (then
/// heap_.size() == size()). Only what K-gons use of std::vector's interface; a contiguous range,
/// so that it converts to std::span.
template <class T, int N>
class SmallVector {
 public:
  using value_type = T;
  using size_type = std::size_t;
  using reference = T&;
  using const_reference = const T&;
  using iterator = T*;
  using const_iterator = const T*;

  SmallVector() = default;
  SmallVector(std::initializer_list<T> list) { assign(list.begin(), list.end()); }
  // Implicit, as a K-gon's corners are assigned from the mesh's loops and fans.
  SmallVector(const std::vector<T>& v) { assign(v.begin(), v.end()); }  // NOLINT

  template <class It>
  void assign(It first, It last) {
    const auto n = static_cast<size_type>(std::distance(first, last));
    if (n <= N) {
      heap_.clear();
      std::copy(first, last, in_place_.begin());
    } else {
      heap_.assign(first, last);
    }
    size_ = static_cast<std::uint32_t>(n);
  }
  void assign(size_type n, const T& value) {
    const T copy = value;  // value may be one of the elements
    resize(n);
    std::fill(begin(), end(), copy);
  }

  /// New elements are value-initialized, as std::vector's (zero for Eigen's vectors while they
  /// are held in place).
  void resize(size_type n) {
    const size_type old = size_;
    if (n <= N) {
      if (old > N)
        std::copy(heap_.begin(), heap_.begin() + static_cast<std::ptrdiff_t>(n), in_place_.begin());
      heap_.clear();
      for (size_type i = old; i < n; ++i) in_place_[i] = detail::zero_value<T>();
    } else {
      if (old <= N) heap_.assign(in_place_.begin(), in_place_.begin() + old);
      heap_.resize(n);
    }
    size_ = static_cast<std::uint32_t>(n);
  }
  void push_back(const T& value) {
    if (size_ < N) {
      in_place_[size_] = value;
    } else {
      if (size_ == N) {
        heap_.reserve(2 * N);
        heap_.assign(in_place_.begin(), in_place_.end());
      }
      heap_.push_back(value);  // value may be an in-place element: those stay as they are
    }
    ++size_;
  }
  void clear() {
    heap_.clear();
    size_ = 0;
  }

  [[nodiscard]] size_type size() const { return size_; }
  [[nodiscard]] bool empty() const { return size_ == 0; }
  [[nodiscard]] T* data() { return size_ <= N ? in_place_.data() : heap_.data(); }
  [[nodiscard]] const T* data() const { return size_ <= N ? in_place_.data() : heap_.data(); }
  T& operator[](size_type i) { return data()[i]; }
  const T& operator[](size_type i) const { return data()[i]; }
  T& front() { return data()[0]; }
  const T& front() const { return data()[0]; }
  T& back() { return data()[size_ - 1]; }
  const T& back() const { return data()[size_ - 1]; }
  iterator begin() { return data(); }
  iterator end() { return data() + size_; }
  const_iterator begin() const { return data(); }
  const_iterator end() const { return data() + size_; }

  [[nodiscard]] std::vector<T> to_vector() const { return {begin(), end()}; }

  friend bool operator==(const SmallVector& a, const SmallVector& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }

 private:
  static std::array<T, N> zeros() {
    std::array<T, N> a;
    a.fill(detail::zero_value<T>());
    return a;
  }

  std::array<T, N> in_place_ = zeros();
  std::vector<T> heap_;
  std::uint32_t size_ = 0;
};

}  // namespace stitch
