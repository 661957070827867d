#pragma once
// Fixed-capacity FIFO, storage inside the object (no heap). push() on a full
// buffer fails and leaves it unchanged; the caller decides what to drop.
#include <array>
#include <cstddef>

namespace sinu::est {

template <typename T, std::size_t N>
class RingBuffer {
 public:
  static constexpr std::size_t kCapacity = N;
  bool push(const T& v) {
    if (size_ == N) return false;
    data_[(head_ + size_) % N] = v;
    ++size_;
    return true;
  }
  const T& front() const { return data_[head_]; }
  const T& back() const { return data_[(head_ + size_ - 1) % N]; }
  /// The i-th oldest element (0: front), i < size().
  const T& operator[](std::size_t i) const { return data_[(head_ + i) % N]; }
  void pop() {
    head_ = (head_ + 1) % N;
    --size_;
  }
  bool empty() const { return size_ == 0; }
  bool full() const { return size_ == N; }
  std::size_t size() const { return size_; }
  void clear() { head_ = size_ = 0; }

 private:
  std::array<T, N> data_{};
  std::size_t head_ = 0, size_ = 0;
};

}  // namespace sinu::est
