// Inputs the glTF fuzzer (fuzz/gltf_fuzzer.cpp) found to escape as crashes,
// each now one InputError line: a number beyond double's range, JSON nested
// deeper than the stack should go, and a data: uri tinygltf does not decode
// (once looked up as a file name too long for the file system).
#include <gtest/gtest.h>

#include <string>

#include "gltf/gltf_loader.h"
#include "text/input_error.h"

namespace fh {
namespace {

std::string fuzz_error(const std::string& json) {
    try {
        load_gltf_from_memory(json, "fuzz.gltf", "/nonexistent-folder");
    } catch (const InputError& e) {
        return e.formatted();
    }
    return "(loaded)";
}

TEST(GltfFuzzFinds, NumberBeyondDoubleIsOneLineWithItsPlace) {
    EXPECT_EQ(fuzz_error("{\"asset\":{\"version\":\"2.0\"},\n \"scene\":1e3080}"),
              "fuzz.gltf:2:10: error: JSON: number overflow parsing '1e3080'");
}

TEST(GltfFuzzFinds, NestingDeeperThan64IsRefusedBeforeParsing) {
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    EXPECT_EQ(fuzz_error("{\"asset\":{\"version\":\"2.0\"},\"extras\":" + deep + "}"),
              "fuzz.gltf:1:100: error: JSON: nested more than 64 arrays and objects deep");
    // 64 deep in all (the top object is one) is fine; brackets in strings do not count.
    const std::string ok = std::string(63, '[') + std::string(63, ']');
    EXPECT_EQ(fuzz_error("{\"asset\":{\"version\":\"2.0\",\"x\":\"[[[\\\"[[[\"},\"extras\":" + ok + "}"),
              "fuzz.gltf: error: the file has no scene to show (no 'scenes')");
}

TEST(GltfFuzzFinds, UndecodableDataUriIsNamedShort) {
    const std::string uri = "data:applica" + std::string(5000, 'A');
    EXPECT_EQ(fuzz_error("{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":4,\"uri\":\"" + uri +
                       "\"}],\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{}]}"),
              "fuzz.gltf: error: a data: uri that is not base64 of a glTF media type ('data:applica" +
                  std::string(45, 'A') + "...')");
}

}  // namespace
}  // namespace fh
