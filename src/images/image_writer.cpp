#include "images/image_writer.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "files/atomic_file.h"
#include "files/file_names.h"
#include "text/input_error.h"
#include "images/png_writer.h"

// stb_image_write's JPEG, BMP and TGA encoders: compiled once, in
// images/png_writer.cpp, with the PNG hooks.
#include <stb_image_write.h>

namespace fh {

ImageFormat image_format_of(const std::string& path) {
    if (path == "-") return ImageFormat::png;
    const std::string ext = lowercase_extension(path);
    if (ext == ".png") return ImageFormat::png;
    if (ext == ".jpg" || ext == ".jpeg") return ImageFormat::jpeg;
    if (ext == ".bmp") return ImageFormat::bmp;
    if (ext == ".tga") return ImageFormat::tga;
    throw UsageError("cannot write '" + path + "': " + (ext.empty() ? "no extension" : "unknown extension '" + ext + "'") +
                     "; the extension picks the format: .png, .jpg or .jpeg, .bmp, .tga ('-': PNG to standard output)");
}

std::vector<std::uint8_t> encode_image(const Image& image, ImageFormat format) {
    if (format == ImageFormat::png) return encode_png(image);
    std::vector<std::uint8_t> out;
    auto append = [](void* ctx, void* data, int size) {
        auto* v = static_cast<std::vector<std::uint8_t>*>(ctx);
        const auto* p = static_cast<const std::uint8_t*>(data);
        v->insert(v->end(), p, p + size);
    };
    const int w = image.width, h = image.height;
    const void* px = image.rgb.data();
    const int ok = format == ImageFormat::jpeg ? stbi_write_jpg_to_func(append, &out, w, h, 3, px, 95)
                   : format == ImageFormat::bmp ? stbi_write_bmp_to_func(append, &out, w, h, 3, px)
                                                : stbi_write_tga_to_func(append, &out, w, h, 3, px);
    if (!ok) throw std::runtime_error("image encoding failed for a " + std::to_string(w) + "x" + std::to_string(h) + " image");
    return out;
}

void write_image(const std::string& path, const Image& image) {
    const ImageFormat format = image_format_of(path);
    if (path != "-") {
        write_file_atomic(path, encode_image(image, format));
        return;
    }
    const std::vector<std::uint8_t> bytes = encode_png(image);
    if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size() || std::fflush(stdout) != 0)
        throw std::runtime_error(std::string("cannot write the image to standard output: ") + std::strerror(errno));
}

}  // namespace fh
