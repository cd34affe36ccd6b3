// Bad input: a message and, where known, the place in the file it comes from.
// Thrown by the loaders, caught once in main and printed as
//     FILE:LINE:COLUMN: error: WHAT
// with exit status 2.
#pragma once

#include <stdexcept>
#include <string>

namespace fh {

class InputError : public std::runtime_error {
public:
    InputError(std::string file, int line, int column, const std::string& what)
        : std::runtime_error(what), file_(std::move(file)), line_(line), column_(column) {}
    InputError(std::string file, const std::string& what) : InputError(std::move(file), 0, 0, what) {}

    const std::string& file() const { return file_; }
    int line() const { return line_; }      // 1-based; 0 = unknown
    int column() const { return column_; }  // 1-based; 0 = unknown

    // "FILE:LINE:COLUMN: error: WHAT", or "FILE: error: WHAT" without a position.
    std::string formatted() const {
        std::string s = file_;
        if (line_ > 0) s += ":" + std::to_string(line_) + ":" + std::to_string(column_);
        return s + ": error: " + what();
    }

private:
    std::string file_;
    int line_;
    int column_;
};

// Bad command-line usage: exit status 2, printed as "firsthit: error: WHAT".
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace fh
