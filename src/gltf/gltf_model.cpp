// tinygltf's implementation, compiled here once, without its image writer;
// images go through decode_image below (stb_image, from Debian's libstb).
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_STB_IMAGE
#include "gltf/gltf_model.h"

#include <stb/stb_image.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <cstdlib>
#include <filesystem>

#include "files/input_files.h"
#include "gltf/gltf_schema.h"
#include "gltf/image_checks.h"
#include "text/input_error.h"

namespace fh {

namespace fs = std::filesystem;

const std::vector<std::string>& supported_gltf_extensions() {
    static const std::vector<std::string> names = {
        "KHR_lights_punctual",           // directional, point and spot lights
        "KHR_materials_emissive_strength",
        "KHR_mesh_quantization",         // integer positions and normals
        "EXT_mesh_gpu_instancing",       // a node's rows of placements
        "KHR_texture_transform",         // offset, rotation and scale of texture coordinates
    };
    return names;
}

namespace {

// What the callbacks need: where the model is, and the first problem seen.
struct Folder {
    fs::path dir;
    std::string file;
    std::string problem;
    std::size_t image_bytes = 0;  // decoded so far
    std::size_t read_bytes = 0;   // read through uris so far
};

// A uri as a message shows it: at most 60 characters (a data: uri can be
// megabytes).
std::string shown(const std::string& uri) { return uri.size() <= 60 ? uri : uri.substr(0, 57) + "..."; }

// Why a uri may not be read, or empty: it must name a file inside the
// model's folder (or be a data: uri, which tinygltf decodes itself).
std::string uri_problem(const std::string& uri) {
    if (uri.rfind("data:", 0) == 0) return "";
    if (uri.empty()) return "an empty uri";
    const size_t colon = uri.find(':'), slash = uri.find('/');
    if (colon != std::string::npos && (slash == std::string::npos || colon < slash))
        return "uri '" + shown(uri) + "' has a scheme other than data: (a model reads only its own files)";
    if (uri[0] == '/' || uri[0] == '\\')
        return "uri '" + shown(uri) + "' is absolute (a model reads only its own files)";
    int depth = 0;
    for (const fs::path& part : fs::path(uri)) {
        if (part == "..") --depth;
        else if (part != "." && !part.empty()) ++depth;
        if (depth < 0) return "uri '" + shown(uri) + "' climbs out of the model's folder";
    }
    return "";
}

// Why a file a uri names cannot be read: a data: uri tinygltf did not
// decode itself (it decodes base64 of glTF's media types), or a file that
// is not there.
std::string missing_file(const std::string& name) {
    if (name.rfind("data:", 0) == 0)
        return "a data: uri that is not base64 of a glTF media type ('" + shown(name) + "')";
    return "cannot find '" + shown(name) + "' beside the model (named by a uri)";
}

// Whether `path`, its links followed, is inside `dir`, its links followed.
bool leads_inside(const fs::path& path, const fs::path& dir) {
    std::error_code ec, dir_ec;
    const fs::path real = fs::canonical(path, ec), root = fs::canonical(dir.empty() ? "." : dir, dir_ec);
    if (ec || dir_ec) return false;
    return std::mismatch(root.begin(), root.end(), real.begin(), real.end()).first == root.end();
}

// tinygltf's file callbacks, confined to the model's folder.
bool file_exists(const std::string& name, void* user) {
    auto* folder = static_cast<Folder*>(user);
    if (const std::string why = uri_problem(name); !why.empty()) {
        if (folder->problem.empty()) folder->problem = why;
        return false;
    }
    std::error_code ec;  // a name too long for the file system: not there
    if (name.rfind("data:", 0) != 0 && fs::is_regular_file(folder->dir / name, ec)) return true;
    if (folder->problem.empty()) folder->problem = missing_file(name);
    return false;
}

std::string expand_file_path(const std::string& path, void*) { return path; }  // no ~, no $VAR

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& name, void* user) {
    auto* folder = static_cast<Folder*>(user);
    if (const std::string why = uri_problem(name); !why.empty()) {
        if (folder->problem.empty()) folder->problem = why;
        if (err) *err = why;
        return false;
    }
    const fs::path path = folder->dir / name;
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (ec || !fs::is_regular_file(path, ec) || name.rfind("data:", 0) == 0) {
        if (folder->problem.empty()) folder->problem = missing_file(name);
        return false;
    }
    // A symbolic link inside the folder may lead anywhere: where it leads
    // must be inside too.
    if (!leads_inside(path, folder->dir)) {
        if (folder->problem.empty())
            folder->problem = "uri '" + shown(name) + "' leads out of the model's folder (through a symbolic link)";
        return false;
    }
    if (size > kMaxGltfBufferBytes) {
        if (folder->problem.empty())
            folder->problem = "'" + shown(name) + "' is " + std::to_string(size) + " bytes (the limit is 1 GiB)";
        return false;
    }
    if (size > kMaxGltfUriReadBytes - folder->read_bytes) {
        if (folder->problem.empty())
            folder->problem = "reading '" + shown(name) + "' would make more than 2 GiB read through uris in all "
                              "(a file is read again for each image that names it)";
        return false;
    }
    folder->read_bytes += size;
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) {
        if (folder->problem.empty()) folder->problem = "cannot read '" + shown(name) + "' (named by a uri)";
        return false;
    }
    out->resize(size);
    const size_t n = size ? std::fread(out->data(), 1, size, f) : 0;
    std::fclose(f);
    if (n != size) {
        if (folder->problem.empty()) folder->problem = "cannot read '" + shown(name) + "' whole";
        return false;
    }
    note_input_file(path.string());
    return true;
}

bool write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err = "firsthit never writes through tinygltf";
    return false;
}

// tinygltf's image callback: a PNG or JPEG (by its first bytes, whatever
// the mimeType says) decoded to 8-bit RGBA within the limits, its size
// read from the header before anything is allocated for it.
bool decode_image(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                  const unsigned char* bytes, int size, void* user) {
    auto* folder = static_cast<Folder*>(user);
    const std::string name = "image " + std::to_string(index) + (image->name.empty() ? "" : " ('" + image->name + "')");
    auto refuse = [&](const std::string& why) {
        if (folder->problem.empty()) folder->problem = name + ": " + why;
        return false;
    };
    const bool png = size >= 8 && std::memcmp(bytes, "\x89PNG\r\n\x1a\n", 8) == 0;
    const bool jpeg = size >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff;
    if (!png && !jpeg) return refuse("not a PNG or JPEG image");
    auto too_large = [&](std::uint64_t w, std::uint64_t h) {
        return w > std::uint64_t(kMaxGltfImageSide) || h > std::uint64_t(kMaxGltfImageSide) ||
               w * h > kMaxGltfImageTexels;
    };
    auto refuse_size = [&](std::uint64_t w, std::uint64_t h) {
        return refuse(std::to_string(w) + " x " + std::to_string(h) +
                      " texels (the limit is 16,384 a side and 67,108,864 in all)");
    };
    // A PNG's size straight from its IHDR: stb_image refuses some large
    // headers itself with a vaguer reason ("unknown image type").
    if (png && size >= 24) {
        const std::uint64_t w = big_endian_u32(bytes + 16), h = big_endian_u32(bytes + 20);
        if (too_large(w, h)) return refuse_size(w, h);
    }
    // What Debian's stb_image 2.27 would read past its tables or out of
    // uninitialised memory, or inflate without bound (gltf/image_checks.h).
    if (const std::string why = png ? png_problem(bytes, std::size_t(size)) : jpeg_problem(bytes, std::size_t(size));
        !why.empty())
        return refuse(why);
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(bytes, size, &w, &h, &channels))
        return refuse(std::string("cannot be decoded (stb_image: ") + stbi_failure_reason() + ")");
    const std::size_t texels = std::size_t(w) * std::size_t(h);
    if (too_large(std::uint64_t(w), std::uint64_t(h))) return refuse_size(std::uint64_t(w), std::uint64_t(h));
    if (folder->image_bytes + 4 * texels > kMaxGltfImageBytes)
        return refuse("the images take more than 1 GiB decoded (the limit)");
    unsigned char* pixels = stbi_load_from_memory(bytes, size, &w, &h, &channels, 4);
    if (!pixels) return refuse(std::string("cannot be decoded (stb_image: ") + stbi_failure_reason() + ")");
    image->width = w;
    image->height = h;
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image.assign(pixels, pixels + 4 * std::size_t(w) * std::size_t(h));
    stbi_image_free(pixels);
    folder->image_bytes += 4 * texels;
    return true;
}

std::uint32_t u32(const std::string& b, size_t at) {
    std::uint32_t v;
    std::memcpy(&v, b.data() + at, 4);
    return v;  // little-endian, as x86-64 is
}

// A GLB's JSON chunk, its header and chunk lengths checked against the file.
std::string glb_json(const std::string& bytes, const std::string& file) {
    if (bytes.size() < 20) throw InputError(file, "GLB file cut short: " + std::to_string(bytes.size()) + " bytes");
    if (u32(bytes, 4) != 2) throw InputError(file, "GLB version " + std::to_string(u32(bytes, 4)) + " (glTF 2.0 is version 2)");
    // The header's length is the whole file's (glTF 2.0, 4.4.2): shorter
    // means bytes after the last chunk, which no reader should guess about.
    const std::uint64_t length = u32(bytes, 8);
    if (length != bytes.size())
        throw InputError(file, "GLB header says " + std::to_string(length) + " bytes, the file has " +
                                   std::to_string(bytes.size()));
    const std::uint64_t json_length = u32(bytes, 12);
    if (u32(bytes, 16) != 0x4E4F534Au) throw InputError(file, "GLB's first chunk is not JSON");
    if (20 + json_length > length)
        throw InputError(file, "GLB's JSON chunk of " + std::to_string(json_length) + " bytes runs past the file (" +
                                   std::to_string(length) + " bytes)");
    const std::uint64_t bin_at = 20 + ((json_length + 3) & ~std::uint64_t(3));
    if (bin_at + 8 <= length) {
        const std::uint64_t bin_length = u32(bytes, size_t(bin_at));
        if (bin_at + 8 + bin_length > length)
            throw InputError(file, "GLB's binary chunk of " + std::to_string(bin_length) +
                                       " bytes runs past the file (" + std::to_string(length) + " bytes)");
    }
    return bytes.substr(20, size_t(json_length));
}

// The JSON's line and column of byte `at`, 1-based.
void position_of(const std::string& json, size_t at, int& line, int& column) {
    line = 1;
    column = 1;
    for (size_t i = 0; i < at && i < json.size(); ++i) {
        if (json[i] == '\n') ++line, column = 1;
        else ++column;
    }
}

// Arrays and objects nested deeper than this are refused before parsing:
// tinygltf copies `extras` and `extensions` recursively, so depth is stack.
constexpr int kMaxJsonNesting = 64;

// Where the JSON first asks for too much, before any of it is parsed: the
// byte where its nesting passes kMaxJsonNesting, or where its values pass
// kMaxGltfJsonValues (a value not first in its array or object follows a
// comma, so values <= commas + arrays and objects + 1). npos: neither.
struct JsonExcess {
    size_t too_deep = std::string::npos, too_many = std::string::npos;
};
JsonExcess json_excess(const std::string& json) {
    int depth = 0;
    size_t values = 1;
    bool in_string = false, opened = false;  // opened: nothing yet since a '[' or '{'
    for (size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (in_string) {
            if (c == '\\') ++i;
            else if (c == '"') in_string = false;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') continue;
        const bool was_opened = opened;
        opened = false;
        if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonNesting) return {i, std::string::npos};
            // Counted as its first value: an empty one gives it back below.
            if (++values > kMaxGltfJsonValues) return {std::string::npos, i};
            opened = true;
        } else if (c == ',') {
            if (++values > kMaxGltfJsonValues) return {std::string::npos, i};
        } else if (c == ']' || c == '}') {
            --depth;
            if (was_opened) --values;
        }
    }
    return {};
}

// nlohmann's message without its "[json.exception...] " prefix.
std::string json_message(const nlohmann::json::exception& e) {
    std::string what = e.what();
    const size_t bracket = what.find("] ");
    if (bracket != std::string::npos) what = what.substr(bracket + 2);
    if (what.rfind("parse error", 0) == 0) {
        const size_t colon = what.find(": ");
        if (colon != std::string::npos) what = what.substr(colon + 2);
    }
    return what;
}

// Buffers of at least a byte (tinygltf 2.7 copies a GLB buffer of none
// from its first byte: an exception of its own, not an error), and images
// in buffer views that lie inside their buffers: tinygltf hands such an
// image's bytes to the decoder before any check of ours, from wherever
// the view says (a view 1 MiB past its buffer crashed the process).
// The schema has made every index and length a whole number below 2^31.
void check_buffers_and_image_views(const nlohmann::json& j, const std::string& file) {
    static const nlohmann::json kNone = nlohmann::json::array();
    // By reference: a buffer's data: uri may be most of a 1 GiB file.
    auto list = [&](const char* key) -> const nlohmann::json& { return j.contains(key) ? j.at(key) : kNone; };
    const nlohmann::json &buffers = list("buffers"), &views = list("bufferViews"), &images = list("images");
    for (size_t b = 0; b < buffers.size(); ++b)
        if (buffers[b]["byteLength"].get<std::uint64_t>() == 0)
            throw InputError(file, "buffers[" + std::to_string(b) + "].byteLength: must be at least 1, got 0");
    for (size_t i = 0; i < images.size(); ++i) {
        if (!images[i].contains("bufferView")) continue;
        const std::string at = "images[" + std::to_string(i) + "]: ";
        const std::uint64_t v = images[i]["bufferView"].get<std::uint64_t>();
        if (v >= views.size()) throw InputError(file, at + "buffer view " + std::to_string(v) + " does not exist");
        const nlohmann::json& view = views[v];
        const std::uint64_t b = view["buffer"].get<std::uint64_t>();
        if (b >= buffers.size()) throw InputError(file, at + "buffer " + std::to_string(b) + " does not exist");
        const std::uint64_t offset = view.value("byteOffset", std::uint64_t(0));
        const std::uint64_t length = view["byteLength"].get<std::uint64_t>();
        const std::uint64_t size = buffers[b]["byteLength"].get<std::uint64_t>();
        if (offset + length > size)
            throw InputError(file, at + "buffer view " + std::to_string(v) + " (" + std::to_string(offset) + " + " +
                                       std::to_string(length) + " bytes) runs past its buffer (" +
                                       std::to_string(size) + " bytes)");
    }
}

// glTF 2.0, or a later 2.x this loader may read (asset.minVersion at most
// 2.0): a glTF 1.0 file -- Debian's glTF/ folder holds several -- is told
// so, not failed on its first 1.0-shaped field ("scene" as a name).
void check_version(const nlohmann::json& j, const std::string& file) {
    if (!j.is_object() || !j.contains("asset") || !j["asset"].is_object()) return;  // the schema says what is wrong
    const nlohmann::json& asset = j["asset"];
    auto major_of = [](const nlohmann::json& v) {
        if (v.is_number()) return v.get<double>() >= 2 ? 2 : 1;  // glTF 1.0 files that wrote 1, not "1.0"
        const std::string text = v.is_string() ? v.get<std::string>() : "";
        return text.empty() || text[0] < '0' || text[0] > '9' ? -1 : std::atoi(text.c_str());
    };
    const int major = asset.contains("version") ? major_of(asset["version"]) : -1;
    if (major >= 0 && major < 2)
        throw InputError(file, "a glTF 1.0 file (asset.version " + asset["version"].dump() +
                                   "): firsthit reads glTF 2.0; convert it first (e.g. with glTF-Pipeline)");
    if (major > 2) throw InputError(file, "asset.version " + asset["version"].dump() + ": firsthit reads glTF 2.0");
    if (asset.contains("minVersion") && asset["minVersion"].is_string() &&
        asset["minVersion"].get<std::string>() != "2.0")
        throw InputError(file, "asset.minVersion " + asset["minVersion"].dump() + ": firsthit reads glTF 2.0");
}

// Checks on the JSON before tinygltf reads it: syntax (with its position),
// nesting, required extensions, uris, and the sizes it asks for.
void check_json(const std::string& json, const std::string& file) {
    if (json.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError(file, "empty glTF file (no JSON)");
    int line, column;
    const JsonExcess excess = json_excess(json);
    if (excess.too_deep != std::string::npos) {
        position_of(json, excess.too_deep, line, column);
        throw InputError(file, line, column,
                         "JSON: nested more than " + std::to_string(kMaxJsonNesting) + " arrays and objects deep");
    }
    if (excess.too_many != std::string::npos) {
        position_of(json, excess.too_many, line, column);
        throw InputError(file, line, column,
                         "JSON: more than " + std::to_string(kMaxGltfJsonValues) + " values (numbers, strings, arrays, objects)");
    }
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(json);
    } catch (const nlohmann::json::parse_error& e) {
        position_of(json, e.byte > 0 ? e.byte - 1 : 0, line, column);
        throw InputError(file, line, column, "JSON: " + json_message(e));
    } catch (const nlohmann::json::exception& e) {
        // A number beyond double's range ("number overflow parsing '1e400'"):
        // nlohmann gives no position, so the number's first place stands in.
        std::string what = json_message(e);
        const size_t open = what.find('\''), close = what.rfind('\'');
        line = column = 0;
        if (open != std::string::npos && close > open)
            if (const size_t at = json.find(what.substr(open + 1, close - open - 1)); at != std::string::npos)
                position_of(json, at, line, column);
        throw InputError(file, line, column, "JSON: " + what);
    }
    check_version(j, file);
    check_gltf_schema(j, file);
    auto strings = [&](const char* key) {
        std::vector<std::string> out;
        if (j.contains(key) && j[key].is_array())
            for (const auto& v : j[key])
                if (v.is_string()) out.push_back(v.get<std::string>());
        return out;
    };
    for (const std::string& ext : strings("extensionsRequired")) {
        const auto& ok = supported_gltf_extensions();
        if (std::find(ok.begin(), ok.end(), ext) == ok.end())
            throw InputError(file, "requires the extension " + ext + ", which firsthit does not implement");
    }
    double buffer_bytes = 0;
    for (const char* list : {"buffers", "images"}) {
        if (!j.contains(list) || !j[list].is_array()) continue;
        for (const auto& item : j[list]) {
            if (!item.is_object()) continue;
            if (item.contains("uri") && item["uri"].is_string())
                if (const std::string why = uri_problem(item["uri"].get<std::string>()); !why.empty())
                    throw InputError(file, std::string(list) + ": " + why);
            if (std::string(list) == "buffers" && item.contains("byteLength") && item["byteLength"].is_number())
                buffer_bytes += item["byteLength"].get<double>();
        }
    }
    if (buffer_bytes > double(kMaxGltfBufferBytes))
        throw InputError(file, "buffers of " + std::to_string(std::uint64_t(buffer_bytes)) +
                                   " bytes in all (the limit is 1 GiB)");
    check_buffers_and_image_views(j, file);
    if (j.contains("nodes") && j["nodes"].is_array() && j["nodes"].size() > kMaxGltfNodes)
        throw InputError(file, std::to_string(j["nodes"].size()) + " nodes (the limit is " +
                                   std::to_string(kMaxGltfNodes) + ")");
}

// tinygltf's error text as one line.
std::string first_line(std::string s) {
    const size_t nl = s.find('\n');
    if (nl != std::string::npos) s.resize(nl);
    while (!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '.')) s.pop_back();
    return s.empty() ? "tinygltf could not read it" : s;
}

}  // namespace

tinygltf::Model parse_gltf_model(const std::string& bytes, const std::string& file, const std::string& folder,
                                 std::vector<std::string>& warnings) {
    if (bytes.size() > kMaxGltfFileBytes)
        throw InputError(file, "file too large: " + std::to_string(bytes.size()) + " bytes (the limit is 1 GiB)");
    const bool glb = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
    check_json(glb ? glb_json(bytes, file) : bytes, file);
    Folder where{fs::path(folder), file, ""};
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({file_exists, expand_file_path, read_whole_file, write_whole_file, &where});
    loader.SetImageLoader(decode_image, &where);
    tinygltf::Model model;
    std::string err, warn;
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const bool ok = glb ? loader.LoadBinaryFromMemory(&model, &err, &warn, data, unsigned(bytes.size()), "")
                        : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), "");
    if (!where.problem.empty()) throw InputError(file, where.problem);
    if (!ok) throw InputError(file, first_line(err));
    for (std::string line; !warn.empty();) {
        const size_t nl = warn.find('\n');
        line = warn.substr(0, nl);
        warn = nl == std::string::npos ? "" : warn.substr(nl + 1);
        if (!line.empty()) warnings.push_back(file + ": warning: " + line);
    }
    return model;
}

tinygltf::Model read_gltf_model(const std::string& path, std::vector<std::string>& warnings) {
    if (const std::string why = why_unreadable(path); !why.empty())
        throw InputError(path, "cannot read file: " + why);
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (ec) throw InputError(path, "cannot read file");
    if (size > kMaxGltfFileBytes)
        throw InputError(path, "file too large: " + std::to_string(size) + " bytes (the limit is 1 GiB)");
    std::string bytes(size, '\0');
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw InputError(path, "cannot read file");
    const size_t n = size ? std::fread(bytes.data(), 1, size, f) : 0;
    std::fclose(f);
    if (n != size) throw InputError(path, "cannot read file whole");
    note_input_file(path);
    return parse_gltf_model(bytes, path, fs::path(path).parent_path().string(), warnings);
}

}  // namespace fh
