// What a file's name says of it: its extension, which picks the format of
// every file firsthit reads or writes by name.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace fh {

// ".png" for "Frame.PNG": the extension with its dot, in lower case; "" for none.
inline std::string lowercase_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

}  // namespace fh
