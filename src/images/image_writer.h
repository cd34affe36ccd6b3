// Still images in the format their file name's extension names: PNG (our
// own fast writer, images/png_writer.h), JPEG, BMP and TGA (stb_image_write).
// "-" is standard output, as PNG. Files are whole or absent
// (write_file_atomic).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "render/image.h"

namespace fh {

enum class ImageFormat { png, jpeg, bmp, tga };

// The format `path`'s extension names, in any case (.png, .jpg or .jpeg,
// .bmp, .tga); "-" is PNG. Anything else is a UsageError that lists these.
ImageFormat image_format_of(const std::string& path);

// JPEG at quality 95 (4:2:0 chroma, stb's baseline encoder).
std::vector<std::uint8_t> encode_image(const Image& image, ImageFormat format);

// The image encoded as image_format_of(path) says, then written atomically;
// "-": PNG to standard output (std::runtime_error if it cannot be written,
// e.g. a closed pipe).
void write_image(const std::string& path, const Image& image);

}  // namespace fh
