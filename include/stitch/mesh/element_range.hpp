// The live elements of one kind, in index order, as a range over the mesh's deleted flags: what
// HalfedgeMesh::vertices(), edges(), halfedges() and faces() return. Iterating builds no list.
//
// The range reads the mesh it came from, so it must not outlive it, and it sees the mesh as it
// is when each element is reached: elements deleted during the loop are skipped, elements added
// during the loop (past the capacity the range was made with) are not visited, and
// garbage_collection() must not run inside the loop. Code that edits the mesh while walking a
// list it made before takes a copy first with to_vector().
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

namespace stitch {

template <class Handle>
class ElementRange {
 public:
  class iterator {
   public:
    using iterator_concept = std::forward_iterator_tag;
    using iterator_category = std::input_iterator_tag;  // *it is a value, not a reference
    using value_type = Handle;
    using difference_type = std::ptrdiff_t;
    using reference = Handle;

    iterator() = default;
    Handle operator*() const { return Handle(index_); }
    iterator& operator++() {
      ++index_;
      skip_deleted();
      return *this;
    }
    iterator operator++(int) {
      iterator before = *this;
      ++*this;
      return before;
    }
    bool operator==(const iterator& other) const { return index_ == other.index_; }

   private:
    friend ElementRange;
    iterator(const std::vector<std::uint8_t>* deleted, int index, int end, int shift)
        : deleted_(deleted), index_(index), end_(end), shift_(shift) {
      skip_deleted();
    }
    void skip_deleted() {
      while (index_ < end_ && (*deleted_)[static_cast<size_t>(index_ >> shift_)] != 0) ++index_;
    }

    // The flags' vector, not its data: an element added during the loop may reallocate it.
    const std::vector<std::uint8_t>* deleted_ = nullptr;
    int index_ = 0;
    int end_ = 0;
    int shift_ = 0;  ///< half-edges read their edge's flag: index >> 1
  };

  /// Elements 0 .. capacity-1 whose flag deleted[index >> shift] is 0; `count` of them are live.
  ElementRange(const std::vector<std::uint8_t>& deleted, int capacity, int count, int shift = 0)
      : deleted_(&deleted), capacity_(capacity), count_(count), shift_(shift) {}

  [[nodiscard]] iterator begin() const { return iterator(deleted_, 0, capacity_, shift_); }
  [[nodiscard]] iterator end() const { return iterator(deleted_, capacity_, capacity_, shift_); }
  /// The number of live elements when the range was made.
  [[nodiscard]] size_t size() const { return static_cast<size_t>(count_); }
  [[nodiscard]] bool empty() const { return count_ == 0; }
  /// The same elements (e.g. two meshes with the same live vertex numbers).
  friend bool operator==(const ElementRange& a, const ElementRange& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
  }
  /// A list of the elements, for indexing or for walking while the mesh changes.
  [[nodiscard]] std::vector<Handle> to_vector() const {
    std::vector<Handle> out;
    out.reserve(size());
    for (Handle h : *this) out.push_back(h);
    return out;
  }

 private:
  const std::vector<std::uint8_t>* deleted_;
  int capacity_;
  int count_;
  int shift_;
};

}  // namespace stitch
