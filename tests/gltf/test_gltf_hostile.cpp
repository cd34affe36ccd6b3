// Bad glTF files (docs/gltf.md, "Hostile files"): each is exactly one
// InputError naming the file, on one line, saying what is wrong -- broken
// JSON (with its line and column), fields missing or of the wrong type,
// accessors, views and indices out of their bounds, nodes that do not form a
// tree, values that are not finite, GLB lengths that lie, counts past the
// limits (refused before anything is allocated for them), uris that would
// read other files, extensions firsthit lacks, buffers that are not there.
// And the good case beside it: a .gltf with its .bin, and the same as a .glb.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>

#include "gltf/gltf_builder.h"
#include "gltf/gltf_loader.h"

namespace fh {
namespace {

using namespace gltf_test;

InputError refused(const std::string& bytes, const std::string& phrase) {
    return expect_input_error([&] { load_gltf_from_memory(bytes, "bad.gltf", "/nonexistent-folder"); }, "bad.gltf",
                              phrase);
}

// The triangle (0,0,0) (1,0,0) (0,1,0), with accessor 0 given its extra members.
std::string triangle_with(const std::string& more) {
    Bin bin;
    const int view = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0});
    return one_mesh(bin, R"({"attributes": {"POSITION": 0}})", accessor(view, kFloat, 3, "VEC3", more));
}

// Loads `json` in a process whose address space may grow by at most 256 MiB
// more, and ends it: 0, refused with exactly `line`; 1, another message; 2,
// out of memory (something was allocated for a count the file only claims);
// 3, it loaded.
[[noreturn]] void load_in_bounded_memory(const std::string& json, const std::string& line) {
    long pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    const rlim_t limit = rlim_t(pages) * rlim_t(::sysconf(_SC_PAGESIZE)) + (rlim_t(256) << 20);
    const rlimit r{limit, limit};
    ::setrlimit(RLIMIT_AS, &r);
    try {
        load_gltf_from_memory(json, "bad.gltf", "/nonexistent-folder");
    } catch (const InputError& e) {
        std::_Exit(e.formatted() == line ? 0 : 1);
    } catch (const std::bad_alloc&) {
        std::_Exit(2);
    }
    std::_Exit(3);
}

// In a child process (so the machine is safe whatever the loader does).
void refused_in_bounded_memory(const std::string& json, const std::string& line) {
    EXPECT_EXIT(load_in_bounded_memory(json, line), ::testing::ExitedWithCode(0), "");
}

// ------------------------------------------------------------------- JSON

TEST(GltfHostile, JsonSyntaxErrorGivesItsLineAndColumn) {
    // Line 2 is `"scenes": [}`: the '}' is its 12th character.
    const InputError e = refused("{\"asset\": {\"version\": \"2.0\"},\n\"scenes\": [}", "JSON: syntax error");
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 12);
}

TEST(GltfHostile, RequiredFieldMissing) {
    Bin bin;
    const int view = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0});
    refused(one_mesh(bin, R"({"attributes": {"POSITION": 0}})",
                     R"({"bufferView": )" + std::to_string(view) + R"(, "count": 3, "type": "VEC3"})"),
            "accessors[0].componentType: required, and missing");
}

TEST(GltfHostile, FieldOfTheWrongType) {
    Bin bin;
    const int view = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0});
    refused(one_mesh(bin, R"({"attributes": {"POSITION": 0}})",
                     R"({"bufferView": )" + std::to_string(view) + R"(, "componentType": 5126, "count": "3", "type": "VEC3"})"),
            "accessors[0].count: expected a whole number >= 0, got the string \"3\"");
}

// Another version than 2.0 is named as such, before any field of its own
// shape is taken for a mistake; an empty file is called empty.
TEST(GltfHostile, VersionsOtherThan2AndEmptyFiles) {
    Bin bin;
    std::string good = gltf_json(triangle_body(bin), bin);
    auto with_asset = [&](const std::string& asset) {
        std::string j = good;
        j.replace(j.find(R"({"version": "2.0"})"), 18, asset);
        return j;
    };
    refused(with_asset(R"({"version": "1.0"})"), "a glTF 1.0 file (asset.version \"1.0\"): firsthit reads glTF 2.0");
    refused(with_asset(R"({"version": 1})"), "a glTF 1.0 file (asset.version 1)");
    refused(with_asset(R"({"version": "3.0"})"), "asset.version \"3.0\": firsthit reads glTF 2.0");
    refused(with_asset(R"({"version": "2.1", "minVersion": "2.1"})"), "asset.minVersion \"2.1\": firsthit reads glTF 2.0");
    EXPECT_NO_THROW(load_gltf_from_memory(with_asset(R"({"version": "2.1", "minVersion": "2.0"})"), "ok.gltf", "/nonexistent"));
    refused("", "empty glTF file (no JSON)");
    refused(" \n\t", "empty glTF file (no JSON)");
}

TEST(GltfHostile, RequiredExtensionNotImplementedIsNamed) {
    Bin bin;
    refused(gltf_json(triangle_body(bin) + R"(, "extensionsUsed": ["KHR_draco_mesh_compression"],
        "extensionsRequired": ["KHR_draco_mesh_compression"])", bin),
            "requires the extension KHR_draco_mesh_compression, which firsthit does not implement");
}

// ----------------------------------------------------------------- bounds

TEST(GltfHostile, AccessorPastItsBufferView) {
    // From byte 12, 3 elements of 12 bytes need 48 of the view's 36.
    refused(triangle_with(", \"byteOffset\": 12"), "3 elements from byte 12 run past buffer view 0 (36 bytes)");
}

TEST(GltfHostile, BufferViewPastItsBuffer) {
    Bin bin;
    bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const std::string json = R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 36, "uri": ")" +
                             data_uri(bin.bytes()) + R"("}], "bufferViews": [{"buffer": 0, "byteOffset": 12, "byteLength": 36}],
        "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [)" + accessor(0, kFloat, 3, "VEC3") + "]}";
    refused(json, "buffer view 0 (12 + 36 bytes) runs past its buffer (36 bytes)");
}

TEST(GltfHostile, ImageInABufferViewPastItsBuffer) {
    // tinygltf hands an image's bytes to the decoder before any check of
    // ours, from wherever its view says: 1 MiB past the buffer crashed.
    const std::string png16 = R"({"uri": "data:application/octet-stream;base64,iVBORw0KGgoAAAAAAAAAAA==", "byteLength": 16})";
    auto image_in = [&](const std::string& view) {
        return R"({"asset": {"version": "2.0"}, "buffers": [)" + png16 + R"(], "bufferViews": [)" + view +
               R"(], "images": [{"bufferView": 0, "mimeType": "image/png"}]})";
    };
    refused(image_in(R"({"buffer": 0, "byteOffset": 4096, "byteLength": 64})"),
            "images[0]: buffer view 0 (4096 + 64 bytes) runs past its buffer (16 bytes)");
    refused(image_in(R"({"buffer": 0, "byteLength": 17})"),
            "images[0]: buffer view 0 (0 + 17 bytes) runs past its buffer (16 bytes)");
    refused(image_in(R"({"buffer": 1, "byteLength": 16})"), "images[0]: buffer 1 does not exist");
    std::string no_view = image_in(R"({"buffer": 0, "byteLength": 16})");
    no_view.replace(no_view.find("\"bufferView\": 0"), 15, "\"bufferView\": 1");
    refused(no_view, "images[0]: buffer view 1 does not exist");
}

TEST(GltfHostile, BufferOfNoBytes) {
    // tinygltf 2.7 copies a GLB buffer of none from its first byte: an
    // exception of the standard library's, not one line saying why.
    refused(R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 0}]})",
            "buffers[0].byteLength: must be at least 1, got 0");
}

TEST(GltfHostile, IndexPastWhatTinygltfKeeps) {
    // tinygltf keeps indices in an int: 2^64 - 1 became -1, "no mesh", and
    // the file loaded.
    refused(R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": 18446744073709551615}]})",
            "nodes[0].mesh: 18446744073709551615 is larger than 2147483647, the largest index or length a glTF "
            "file may give");
    refused(R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [2147483648]}]})",
            "scenes[0].nodes[0]: 2147483648 is larger than 2147483647");
}

TEST(GltfHostile, IndexOutOfRange) {
    Bin bin;
    const int p = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0}), i = bin.u16({0, 1, 3});
    refused(one_mesh(bin, R"({"attributes": {"POSITION": 0}, "indices": 1})",
                     accessor(p, kFloat, 3, "VEC3") + ", " + accessor(i, kUnsignedShort, 3, "SCALAR")),
            "index 3 is out of range (3 vertices)");
}

TEST(GltfHostile, SparseIndicesOutOfOrder) {
    Bin bin;
    const int p = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0}), where = bin.u8({2, 1}), values = bin.f32({0, 0, 1, 0, 0, 2});
    refused(one_mesh(bin, R"({"attributes": {"POSITION": 0}})",
                     accessor(p, kFloat, 3, "VEC3", sparse(2, where, kUnsignedByte, values))),
            "sparse index 1 is out of range or out of order");
}

TEST(GltfHostile, CountPastTheLimitIsRefusedBeforeAllocating) {
    // 1,999,999,998 positions (a multiple of 3) claimed over a view of 36
    // bytes: 48 GB as doubles, were it read. The child may grow 256 MiB.
    // (A count of 2^31 or more the schema refuses: tinygltf keeps it in an int.)
    Bin bin;
    const int view = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0});
    refused_in_bounded_memory(
        one_mesh(bin, R"({"attributes": {"POSITION": 0}})", accessor(view, kFloat, 1999999998u, "VEC3")),
        "bad.gltf: error: mesh 0 primitive 0 POSITION (accessor 0): 1999999998 elements of 3 numbers are more than "
        "one accessor may hold (67108864 numbers)");
}

// A sparse accessor without a buffer view starts from zeros: its count is
// bounded by no buffer. 999,999,999 positions from a 200-byte file would be
// 24 GB of zeros: one accessor holds at most 2^26 numbers (docs/gltf.md).
TEST(GltfHostile, SparseCountWithoutABufferViewIsBoundedBeforeAllocating) {
    Bin bin;
    const int where = bin.u8({0}), values = bin.f32({1, 0, 0});
    refused_in_bounded_memory(
        one_mesh(bin, R"({"attributes": {"POSITION": 0}})",
                 R"({"componentType": 5126, "count": 999999999, "type": "VEC3")" + sparse(1, where, kUnsignedByte, values) + "}"),
        "bad.gltf: error: mesh 0 primitive 0 POSITION (accessor 0): 999999999 elements of 3 numbers are more than "
        "one accessor may hold (67108864 numbers)");
}

// One sparse accessor of 2^24 zero positions (50,331,648 numbers, within
// one accessor's limit) costs the file nothing, but each primitive that reads
// it is a copy: three are more than 2^27 numbers, refused before any is read.
TEST(GltfHostile, PrimitivesSharingAHugeSparseAccessorAreBoundedBeforeAllocating) {
    Bin bin;
    const int where = bin.u8({0}), values = bin.f32({1, 0, 0});
    const std::string position = R"({"attributes": {"POSITION": 0}})";
    refused_in_bounded_memory(
        one_mesh(bin, position + ", " + position + ", " + position,
                 R"({"componentType": 5126, "count": 16777216, "type": "VEC3")" + sparse(1, where, kUnsignedByte, values) + "}"),
        "bad.gltf: error: its meshes' accessors hold more than 134217728 numbers, counted for each primitive that "
        "reads them");
}

// Parsed twice (checked, then read), a JSON value costs 100-300 bytes: more
// than 2^22 of them are refused before parsing, with the place of the first
// one too many (past the extras' first few).
TEST(GltfHostile, JsonOfTooManyValuesIsRefusedBeforeParsing) {
    std::string zeros = "[0";
    for (size_t i = 1; i < (size_t(1) << 22); ++i) zeros += ",0";
    zeros += "]";
    const InputError e = refused(gltf_json(R"("scenes": [{"nodes": [0]}], "nodes": [{}], "extras": )" + zeros),
                                 "JSON: more than 4194304 values (numbers, strings, arrays, objects)");
    EXPECT_GT(e.column(), 8'000'000);
}

// ------------------------------------------------------------------ nodes

const std::string kScene0 = R"("scenes": [{"nodes": [0]}], )";

TEST(GltfHostile, NodeCycle) {
    // 0 -> 1 -> 0: node 0's parent is 1, whose parent is 0.
    refused(gltf_json(kScene0 + R"("nodes": [{"children": [1]}, {"children": [0]}])"),
            "node 0 is its own ancestor (a cycle)");
    // Below the top, 1 -> 2 -> 1: node 1 is reached from 0 and from 2.
    refused(gltf_json(kScene0 + R"("nodes": [{"children": [1]}, {"children": [2]}, {"children": [1]}])"),
            "node 1 has two parents (0 and 2)");
}

TEST(GltfHostile, NodeWithTwoParents) {
    refused(gltf_json(R"("scenes": [{"nodes": [0, 1]}], "nodes": [{"children": [2]}, {"children": [2]}, {}])"),
            "node 2 has two parents (0 and 1)");
    refused(gltf_json(kScene0 + R"("nodes": [{"children": [5]}])"), "node 0 has child 5, which does not exist");
}

// docs/gltf.md: "nodes form a tree", shown or not: a cycle among nodes no
// scene shows is refused too.
TEST(GltfHostile, CycleOutsideTheSceneShown) {
    refused(gltf_json(kScene0 + R"("nodes": [{}, {"children": [2]}, {"children": [1]}])"),
            "node 1 is its own ancestor (a cycle)");
}

// ------------------------------------------------------------- not finite

TEST(GltfHostile, PositionsNotFinite) {
    for (const float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        Bin bin;
        const int view = bin.f32({0, 0, 0, 1, bad, 0, 0, 1, 0});
        refused(one_mesh(bin, R"({"attributes": {"POSITION": 0}})", accessor(view, kFloat, 3, "VEC3")),
                "mesh 0 primitive 0 POSITION (accessor 0): a value is not finite (NaN or infinite)");
    }
}

TEST(GltfHostile, NodeTranslationNotFinite) {
    // JSON has no NaN or infinity: the literal is a syntax error, and a
    // number past double's range is refused where it stands (line 2, column 56).
    refused(gltf_json(kScene0 + R"("nodes": [{"translation": [NaN, 0, 0]}])"), "JSON: syntax error");
    const InputError e = refused(gltf_json(kScene0 + R"("nodes": [{"translation": [1e400, 0, 0]}])"),
                                 "JSON: number overflow parsing '1e400'");
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 56);
}

// Each node's own transform is finite, but their product is not: scale
// 1e200 under scale 1e200 would place the mesh by infinities.
TEST(GltfHostile, WorldTransformOverflowingIsRefused) {
    Bin bin;
    std::string nested = gltf_json(triangle_body(bin), bin);
    nested.replace(nested.find(R"("nodes": [{"mesh": 0}])"), 22,
                   R"("nodes": [{"scale": [1e200,1e200,1e200], "children": [1]}, {"mesh": 0, "scale": [1e200,1e200,1e200]}])");
    expect_input_error(
        [&] {
            Scene s;
            add_gltf(s, load_gltf_from_memory(nested, "bad.gltf", "/nonexistent-folder"), "m", Transform{});
        },
        "bad.gltf", "node 1: its transform times its parents' is not finite (past a double's range)");
}

// EXT_mesh_gpu_instancing's row of scale 3e38 under a node scaled 1e300:
// each finite, their product not.
TEST(GltfHostile, InstancingRowOverflowingIsRefused) {
    Bin bin;
    const int sc = bin.f32({3e38f, 3e38f, 3e38f});
    const std::string more = ", " + accessor(sc, kFloat, 1, "VEC3");
    refused(gltf_json(triangle_mesh(bin, more) + R"(, "extensionsUsed": ["EXT_mesh_gpu_instancing"],
        "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "scale": [1e300,1e300,1e300], "extensions":
        {"EXT_mesh_gpu_instancing": {"attributes": {"SCALE": 1}}}}])", bin),
            "node 0: an EXT_mesh_gpu_instancing row times the node's transform is not finite");
}

// glTF allows a node a matrix or TRS, never both (node.schema.json); tinygltf
// would keep the matrix and drop the rest without a word.
TEST(GltfHostile, MatrixBesideTranslationRotationOrScale) {
    const std::string identity = R"("matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1])";
    for (const std::string trs : {R"("translation": [1,0,0])", R"("rotation": [0,0,0,1])", R"("scale": [2,2,2])"})
        refused(gltf_json(kScene0 + R"("nodes": [{"name": "arm", )" + identity + ", " + trs + "}]"),
                "nodes[0]: has both 'matrix' and translation, rotation or scale (glTF allows one or the other)");
}

// A quaternion near zero has no rotation to normalize to; a near-unit one
// (as exporters round) is normalized: [0, 0, 0, 2] is the identity.
TEST(GltfHostile, RotationOfLengthZeroIsRefusedAndANearUnitOneNormalized) {
    refused(gltf_json(kScene0 + R"("nodes": [{"rotation": [0,0,0,0]}])"),
            "node 0: 'rotation' is not a rotation (a quaternion of length 0; glTF's are of length 1)");
    refused(gltf_json(kScene0 + R"("nodes": [{"rotation": [1e-9,0,0,0]}])"),
            "node 0: 'rotation' is not a rotation (a quaternion of length 1e-09; glTF's are of length 1)");
    const GltfFile f = load_gltf_from_memory(gltf_json(kScene0 + R"("nodes": [{"rotation": [0,0,0,2]}])"), "t.gltf",
                                             "/nonexistent-folder");
    ASSERT_EQ(f.scene.nodes.size(), 1u);
    const glm::dmat4 local = f.scene.nodes[0].local();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_EQ(local[c][r], c == r ? 1.0 : 0.0) << c << "," << r;
}

// The same for EXT_mesh_gpu_instancing's rows, named by row.
TEST(GltfHostile, InstancingRotationOfLengthZeroIsRefused) {
    Bin bin;
    const int rot = bin.f32({0, 0, 0, 1, 0, 0, 0, 0});
    const std::string more = ", " + accessor(rot, kFloat, 2, "VEC4");
    refused(gltf_json(triangle_mesh(bin, more) + R"(, "extensionsUsed": ["EXT_mesh_gpu_instancing"],
        "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "extensions":
        {"EXT_mesh_gpu_instancing": {"attributes": {"ROTATION": 1}}}}])", bin),
            "node 0: EXT_mesh_gpu_instancing's ROTATION row 1 is not a rotation (a quaternion of length 0; glTF's are of length 1)");
}

// -------------------------------------------------------------------- GLB

std::string triangle_glb() {
    Bin bin;
    const std::string body = triangle_body(bin);  // before bin.bytes() is read
    return glb(gltf_json(body, bin, in_glb()), bin.bytes());
}

void set_u32(std::string& bytes, size_t at, std::uint32_t v) { bytes.replace(at, 4, le32(v)); }

TEST(GltfHostile, GlbChunkRunningPastTheFile) {
    std::string g = triangle_glb();
    const std::uint32_t size = std::uint32_t(g.size());
    set_u32(g, 12, size);  // the JSON chunk as long as the whole file
    refused(g, "GLB's JSON chunk of " + std::to_string(size) + " bytes runs past the file (" + std::to_string(size) + " bytes)");
    // The binary chunk: its length sits right after the padded JSON.
    g = triangle_glb();
    std::uint32_t json_length;
    std::memcpy(&json_length, g.data() + 12, 4);
    set_u32(g, 20 + json_length, 40);  // 36 bytes there
    refused(g, "GLB's binary chunk of 40 bytes runs past the file (" + std::to_string(size) + " bytes)");
}

TEST(GltfHostile, GlbHeaderLengthOtherThanTheFiles) {
    std::string g = triangle_glb();
    const size_t size = g.size();
    set_u32(g, 8, std::uint32_t(size + 4));
    refused(g, "GLB header says " + std::to_string(size + 4) + " bytes, the file has " + std::to_string(size));
    // Bytes after the last chunk.
    refused(triangle_glb() + std::string(4, '\0'),
            "GLB header says " + std::to_string(size) + " bytes, the file has " + std::to_string(size + 4));
    // Cut short: the header's length no longer there.
    refused(triangle_glb().substr(0, size - 8),
            "GLB header says " + std::to_string(size) + " bytes, the file has " + std::to_string(size - 8));
}

// ----------------------------------------------------------------- lights

TEST(GltfHostile, LightValuesOutOfRange) {
    auto with_light = [](const std::string& light) {
        return gltf_json(R"("extensionsUsed": ["KHR_lights_punctual"],
            "extensions": {"KHR_lights_punctual": {"lights": [)" + light + R"(]}},
            "scenes": [{"nodes": [0]}], "nodes": [{"extensions": {"KHR_lights_punctual": {"light": 0}}}])");
    };
    refused(with_light(R"({"type": "point", "intensity": -1})"), "light 0: intensity must be >= 0");
    refused(with_light(R"({"type": "spot", "spot": {"outerConeAngle": 0}})"),
            "light 0: outerConeAngle must be in (0, pi/2]");
    refused(with_light(R"({"type": "spot", "name": "wide", "spot": {"outerConeAngle": 1.6}})"),
            "wide: outerConeAngle must be in (0, pi/2]");
    refused(with_light(R"({"type": "spot", "spot": {"innerConeAngle": 0.5, "outerConeAngle": 0.5}})"),
            "light 0: innerConeAngle must be in [0, outerConeAngle)");
    refused(with_light(R"({"type": "spot", "spot": {"innerConeAngle": -0.1, "outerConeAngle": 0.5}})"),
            "light 0: innerConeAngle must be in [0, outerConeAngle)");
    // pi/2 as a float (1.5707963705...) is the widest cone the extension allows.
    const GltfFile f = load_gltf_from_memory(with_light(R"({"type": "spot", "spot": {"outerConeAngle": 1.5707963705062866}})"),
                                             "ok.gltf", "/nonexistent-folder");
    ASSERT_EQ(f.scene.spot_lights.size(), 1u);
    EXPECT_DOUBLE_EQ(f.scene.spot_lights[0].max_angle, 1.5707963705062866);
}

// ------------------------------------------------------------------- uris

TEST(GltfHostile, UrisThatWouldReadOtherFiles) {
    auto with_uri = [](const std::string& uri) {
        return gltf_json(R"("buffers": [{"byteLength": 4, "uri": ")" + uri + R"("}], "scenes": [{"nodes": [0]}], "nodes": [{}])");
    };
    refused(with_uri("/etc/passwd"), "buffers: uri '/etc/passwd' is absolute (a model reads only its own files)");
    refused(with_uri("http://x/a.bin"), "uri 'http://x/a.bin' has a scheme other than data:");
    refused(with_uri("file:///etc/passwd"), "uri 'file:///etc/passwd' has a scheme other than data:");
    refused(with_uri("../a.bin"), "uri '../a.bin' climbs out of the model's folder");
    refused(with_uri("in/../../a.bin"), "uri 'in/../../a.bin' climbs out of the model's folder");
    refused(gltf_json(R"("images": [{"uri": "/etc/passwd"}], "scenes": [{"nodes": [0]}], "nodes": [{}])"),
            "images: uri '/etc/passwd' is absolute");
}

// A folder holding secret.bin (a triangle's buffer) and model/m.gltf, whose
// buffer's uri is `uri`: the path of m.gltf.
std::string model_beside_a_secret(const TempFolder& dir, const std::string& uri) {
    Bin bin;
    const std::string body = triangle_body(bin);
    dir.write("secret.bin", bin.bytes());
    return dir.write("model/m.gltf", gltf_json(body, bin, in_file(uri)));
}

TEST(GltfHostile, PercentEncodedClimbReadsNothingOutside) {
    // tinygltf decodes %2E%2E to "..": the file beside the model's folder
    // exists, and must still not be read.
    TempFolder dir("percent");
    const std::string path = model_beside_a_secret(dir, "%2E%2E/secret.bin");
    expect_input_error([&] { load_gltf(path); }, path, "climbs out of the model's folder");
}

// A symbolic link inside the model's folder to a file outside it: the uri
// is harmless as text, but the model must still not read that file.
TEST(GltfHostile, ALinkOutOfTheFolderReadsNothingOutside) {
    TempFolder dir("link");
    const std::string path = model_beside_a_secret(dir, "data.bin");
    std::filesystem::create_symlink(dir.path / "secret.bin", dir.path / "model" / "data.bin");
    expect_input_error([&] { load_gltf(path); }, path,
                       "uri 'data.bin' leads out of the model's folder (through a symbolic link)");
    // A link that stays inside is read.
    std::filesystem::copy_file(dir.path / "secret.bin", dir.path / "model" / "real.bin");
    std::filesystem::remove(dir.path / "model" / "data.bin");
    std::filesystem::create_symlink("real.bin", dir.path / "model" / "data.bin");
    EXPECT_EQ(load_gltf(path).scene.meshes.size(), 1u);
}

TEST(GltfHostile, BufferFileMissing) {
    TempFolder dir("missing");
    Bin bin;
    const std::string path = dir.write("m.gltf", gltf_json(triangle_body(bin), bin, in_file("missing.bin")));
    expect_input_error([&] { load_gltf(path); }, path, "cannot find 'missing.bin' beside the model (named by a uri)");
}

// -------------------------------------------------------------- animation

TEST(GltfHostile, AnimationTimesNotIncreasingOrOnAMatrix) {
    Bin bin;
    const int p = bin.f32({0, 0, 0, 1, 0, 0, 0, 1, 0}), t = bin.f32({0, 1, 1}), v = bin.f32({0, 0, 0, 1, 0, 0, 2, 0, 0});
    const std::string accessors = accessor(p, kFloat, 3, "VEC3") + ", " + accessor(t, kFloat, 3, "SCALAR") + ", " +
                                  accessor(v, kFloat, 3, "VEC3");
    const std::string animation = R"("animations": [{"channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}],
        "samplers": [{"input": 1, "output": 2}]}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "accessors": [)" +
                                  accessors + "]";
    refused(gltf_json(kScene0 + R"("nodes": [{"mesh": 0}], )" + animation, bin),
            "animation 0 channel 0: its key times do not increase (key 2)");
    refused(gltf_json(kScene0 + R"("nodes": [{"mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}], )" + animation, bin),
            "animation 0 channel 0: node 0 has a 'matrix', which cannot be animated");
}

// ------------------------------------------------------- the good files

TEST(GltfHostile, GltfWithItsBinBesideItAndTheSameAsGlbLoadAlike) {
    TempFolder dir("good");
    Bin bin;
    const std::string body = triangle_body(bin);
    dir.write("tri.bin", bin.bytes());
    const std::string gltf = dir.write("tri.gltf", gltf_json(body, bin, in_file("tri.bin")));
    const std::string glb_path = dir.write("tri.glb", glb(gltf_json(body, bin, in_glb()), bin.bytes()));
    for (const std::string& path : {gltf, glb_path}) {
        const GltfFile f = load_gltf(path);
        ASSERT_EQ(f.scene.meshes.size(), 1u) << path;
        const Mesh& m = *f.scene.meshes[0].mesh;
        EXPECT_EQ(m.positions, (std::vector<dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})) << path;
        EXPECT_EQ(m.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}})) << path;
        EXPECT_EQ(f.scene.instances.size(), 1u) << path;
        EXPECT_TRUE(f.warnings.empty()) << path << ": " << (f.warnings.empty() ? "" : f.warnings[0]);
    }
}

}  // namespace
}  // namespace fh
