// Bad input: a message and, where known, the place in the file it comes from.
// Thrown by the loaders, caught once in main and printed as
//     FILE:LINE:COLUMN: error: WHAT
// with exit status 2.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include "text/utf8.h"

namespace fh {

// `text` made safe for one line on a terminal: control characters (C0, DEL
// and C1, so also newlines) and bytes that are not UTF-8 become \xNN, and
// past `max_bytes` it is cut, on a character boundary, and ends in "...".
// Messages quote values from files, which may be long or hold escapes like
// "\n" (and yaml-cpp 0.7 turns "\N" into the lone byte 0x85).
inline std::string printable(const std::string& text, std::size_t max_bytes = 400) {
    static const char hex[] = "0123456789abcdef";
    std::string out;
    auto escape = [&](unsigned char code) {
        out += "\\x";
        out += hex[code >> 4];
        out += hex[code & 15];
    };
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (out.size() >= max_bytes) return out + "...";
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x80) {
            if (c < 0x20 || c == 0x7f) escape(c);
            else out += static_cast<char>(c);
            continue;
        }
        const std::size_t n = utf8_sequence(text, i);
        if (n == 0) {
            escape(c);
        } else if (utf8_c1_control(text, i)) {
            escape(static_cast<unsigned char>(text[++i]));  // a C1 control character
        } else {
            out.append(text, i, n);
            i += n - 1;
        }
    }
    return out;
}

class InputError : public std::runtime_error {
public:
    InputError(std::string file, int line, int column, const std::string& what)
        : std::runtime_error(printable(what)), file_(std::move(file)), line_(line), column_(column) {}
    InputError(std::string file, const std::string& what) : InputError(std::move(file), 0, 0, what) {}

    const std::string& file() const { return file_; }
    int line() const { return line_; }      // 1-based; 0 = unknown
    int column() const { return column_; }  // 1-based; 0 = unknown

    // "FILE:LINE:COLUMN: error: WHAT", or "FILE: error: WHAT" without a position.
    std::string formatted() const {
        // Appends rather than operator+ on temporaries: GCC 12 warns falsely
        // (-Wrestrict) about the inlined copies of the latter.
        std::string s = printable(file_, 4096);
        if (line_ > 0) {
            s.append(":").append(std::to_string(line_));
            s.append(":").append(std::to_string(column_));
        }
        s.append(": error: ").append(what());
        return s;
    }

private:
    std::string file_;
    int line_;
    int column_;
};

// Bad command-line usage: exit status 2, printed as "firsthit: error: WHAT".
class UsageError : public std::runtime_error {
public:
    explicit UsageError(const std::string& what) : std::runtime_error(printable(what)) {}
};

}  // namespace fh
