// Bytes from the fuzzer turned into the values a call needs. Reads past the end give zeros,
// so every input is a complete program.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace lfem_fuzz {

class Input {
public:
    Input(const uint8_t* data, size_t size) : data_(data), size_(size) {}
    bool empty() const { return pos_ >= size_; }

    uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
    uint32_t u32() {
        uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= uint32_t(byte()) << (8 * i);
        return v;
    }
    // A number in [0, n) (n > 0).
    uint32_t below(uint32_t n) { return u32() % n; }
    // Any double: one byte chooses between plain values in a range that makes sense for the
    // argument, and the raw bit patterns (NaN, infinities, denormals, huge) that must be refused.
    double number(double lo, double hi) {
        const uint8_t kind = byte();
        if (kind < 200) return lo + (hi - lo) * (u32() / 4294967295.0);
        uint64_t bits = uint64_t(u32()) | (uint64_t(u32()) << 32);
        double v;
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }

private:
    const uint8_t* data_;
    size_t size_;
    size_t pos_ = 0;
};

}  // namespace lfem_fuzz
