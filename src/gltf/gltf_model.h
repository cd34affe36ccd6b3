// A glTF 2.0 file read by tinygltf (Debian's libtinygltf-dev), and nothing
// else: a .gltf with its files or data: URIs, or a .glb. Before tinygltf sees
// a byte the file is checked -- its size, a GLB's header and chunk lengths
// against the file, the JSON's required extensions, every buffer's and
// image's uri (relative, no scheme but data:, never out of the model's
// folder) -- and tinygltf reads other files only through callbacks that
// apply the same rules. Images are decoded here, by stb_image, within the
// limits below. Every problem is an InputError naming the file
// (with the JSON's line and column where tinygltf's parser gives them).
// Only the .cpp files of src/gltf include this header (tinygltf's types).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "core/vec.h"

namespace fh {

// Documented limits, checked before anything is allocated for them.
inline constexpr std::size_t kMaxGltfFileBytes = std::size_t(1) << 30;    // the .gltf or .glb itself
inline constexpr std::size_t kMaxGltfBufferBytes = std::size_t(1) << 30;  // all its buffers together
// All the files its uris name, read together: tinygltf reads a file again
// for each image that names it (1,000 images of one 64 MiB file took 9 s).
inline constexpr std::size_t kMaxGltfUriReadBytes = std::size_t(1) << 31;
inline constexpr std::size_t kMaxGltfNodes = 1'000'000;
// Numbers one accessor may hold (components x count: 2^26, 512 MiB read as doubles).
inline constexpr std::size_t kMaxGltfAccessorValues = std::size_t(1) << 26;
// Numbers read from all accessors together, an accessor counted each time a
// primitive, channel or skin reads it (2^27: 1 GiB read as doubles), so
// that many primitives sharing one huge sparse accessor -- zeros that cost
// the file nothing -- cannot multiply it.
inline constexpr std::size_t kMaxGltfReadValues = std::size_t(1) << 27;
// JSON values (numbers, strings, arrays, objects...) in the file's JSON:
// each costs about 100-200 bytes once parsed twice (nlohmann, then tinygltf's
// copy of `extras` and `extensions`).
inline constexpr std::size_t kMaxGltfJsonValues = std::size_t(1) << 22;
// Vertices of all the morphed and skinned copies (each node deforms its own;
// 2^22: about 250 MB of copies at most).
inline constexpr std::size_t kMaxGltfDeformedVertices = std::size_t(1) << 22;

// Images (PNG or JPEG, decoded by stb_image to 8-bit RGBA): at most 16,384
// texels a side and 2^26 texels each (256 MiB decoded), 1 GiB decoded in all.
inline constexpr int kMaxGltfImageSide = 16384;
inline constexpr std::size_t kMaxGltfImageTexels = std::size_t(1) << 26;
inline constexpr std::size_t kMaxGltfImageBytes = std::size_t(1) << 30;

// A glTF member of three numbers (a colour, a translation, a scale) as a
// vector; `fallback`, its default, when the file leaves it out.
inline dvec3 vec3_or(const std::vector<double>& v, dvec3 fallback) {
    return v.size() == 3 ? dvec3(v[0], v[1], v[2]) : fallback;
}

// A value of an extension object, or null.
inline const tinygltf::Value* extension_value(const tinygltf::ExtensionMap& extensions, const std::string& name,
                                              const std::string& key) {
    const auto it = extensions.find(name);
    if (it == extensions.end() || !it->second.IsObject() || !it->second.Has(key)) return nullptr;
    return &it->second.Get(key);
}

// The extensions firsthit implements; a file that requires any other is
// refused, naming it.
const std::vector<std::string>& supported_gltf_extensions();

// Reads the file at `path` (.gltf or .glb, by content: a GLB starts with
// "glTF"); bad files throw InputError. `warnings` gets tinygltf's warnings.
tinygltf::Model read_gltf_model(const std::string& path, std::vector<std::string>& warnings);

// The same from bytes in memory (the fuzzer); external files are looked for
// in `folder`.
tinygltf::Model parse_gltf_model(const std::string& bytes, const std::string& file, const std::string& folder,
                                 std::vector<std::string>& warnings);

}  // namespace fh
