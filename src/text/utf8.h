// UTF-8 as RFC 3629 defines it, one character at a time: what the text
// checks (text/text_input.cpp) and the messages (text/input_error.h) agree
// a character is.
#pragma once

#include <cstddef>
#include <string>

namespace fh {

// The bytes of the well-formed UTF-8 character at text[i] (1 for ASCII), or
// 0 where none starts: a stray continuation byte, a character cut short by
// the end, an overlong form, a surrogate or a value past U+10FFFF.
inline std::size_t utf8_sequence(const std::string& text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u; };
    const auto cont = [&](std::size_t k, unsigned lo = 0x80, unsigned hi = 0xbf) {
        return byte(k) >= lo && byte(k) <= hi;
    };
    const unsigned c = byte(i);
    if (c < 0x80) return 1;
    if (c >= 0xc2 && c <= 0xdf) return cont(i + 1) ? 2 : 0;
    if (c == 0xe0) return cont(i + 1, 0xa0) && cont(i + 2) ? 3 : 0;
    if (c == 0xed) return cont(i + 1, 0x80, 0x9f) && cont(i + 2) ? 3 : 0;
    if (c >= 0xe1 && c <= 0xef) return cont(i + 1) && cont(i + 2) ? 3 : 0;
    if (c == 0xf0) return cont(i + 1, 0x90) && cont(i + 2) && cont(i + 3) ? 4 : 0;
    if (c >= 0xf1 && c <= 0xf3) return cont(i + 1) && cont(i + 2) && cont(i + 3) ? 4 : 0;
    if (c == 0xf4) return cont(i + 1, 0x80, 0x8f) && cont(i + 2) && cont(i + 3) ? 4 : 0;
    return 0;
}

// Whether text[i] starts a C1 control character (U+0080..U+009F, the bytes
// C2 80..C2 9F).
inline bool utf8_c1_control(const std::string& text, std::size_t i) {
    return static_cast<unsigned char>(text[i]) == 0xc2 && i + 1 < text.size() &&
           static_cast<unsigned char>(text[i + 1]) <= 0x9f;
}

}  // namespace fh
