// An 8-bit RGB image, rows from the top.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace fh {

// std::allocator, except that a vector grown without a value leaves its new
// bytes as they are: a frame's tiles write every pixel, so its image need not
// be zeroed first -- on one thread, before the workers start.
template <typename T>
struct UnzeroedAllocator : std::allocator<T> {
    template <typename U>
    struct rebind {
        using other = UnzeroedAllocator<U>;
    };
    UnzeroedAllocator() = default;
    template <typename U>
    UnzeroedAllocator(const UnzeroedAllocator<U>&) noexcept {}

    template <typename U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

using Bytes = std::vector<std::uint8_t, UnzeroedAllocator<std::uint8_t>>;

struct Image {
    int width = 0;
    int height = 0;
    Bytes rgb;  // width * height * 3

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgb(std::size_t(w) * std::size_t(h) * 3, 0) {}

    // Every byte left for the caller to write (a frame: its tiles write them
    // all, which tests/render/test_frame_image.cpp checks).
    static Image unzeroed(int w, int h) {
        Image im;
        im.width = w;
        im.height = h;
        im.rgb.resize(std::size_t(w) * std::size_t(h) * 3);
        return im;
    }

    const std::uint8_t* pixel(int x, int y) const { return &rgb[(std::size_t(y) * width + x) * 3]; }
    std::uint8_t* pixel(int x, int y) { return &rgb[(std::size_t(y) * width + x) * 3]; }
};

}  // namespace fh
