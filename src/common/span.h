// A view of a contiguous array: a pointer and a length, owning nothing (std::span is C++20).
// The kernels take their inputs and outputs as spans, so that they depend on the shape of the
// data, not on the structs of the layer that owns it.
#pragma once

#include <cstddef>
#include <vector>

namespace lfem {

template <class T>
class Span {
public:
    Span() = default;
    Span(T* data, std::size_t size) : data_(data), size_(size) {}
    template <class U>
    Span(std::vector<U>& v) : data_(v.data()), size_(v.size()) {}  // NOLINT: implicit, as std::span
    template <class U>
    Span(const std::vector<U>& v) : data_(v.data()), size_(v.size()) {}  // NOLINT
    template <class U>
    Span(const Span<U>& s) : data_(s.data()), size_(s.size()) {}  // NOLINT: Span<T> -> Span<const T>

    T* data() const { return data_; }
    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    T& operator[](std::size_t i) const { return data_[i]; }
    T* begin() const { return data_; }
    T* end() const { return data_ + size_; }

private:
    T* data_ = nullptr;
    std::size_t size_ = 0;
};

}  // namespace lfem
