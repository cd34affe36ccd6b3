#include "text/parse_int.h"

#include <cerrno>
#include <cstdlib>

#include "text/input_error.h"

namespace fh {

int parse_int(const std::string& text, const std::string& what, int min, int max) {
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno == ERANGE)
        throw UsageError(what + " must be a whole number, got '" + text + "'");
    if (v < min || v > max)
        throw UsageError(what + " must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " +
                         text);
    return int(v);
}

}  // namespace fh
