// Whole-file bad input, before any value is read: unreadable, folder, device,
// too large, binary, not UTF-8, nested thousands deep, several documents; and
// the regression inputs the fuzzer found (tests/yaml/fuzz_regressions/).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "text/input_error.h"
#include "yaml/movie_loader.h"
#include "yaml/scene_loader.h"
#include "text/text_input.h"
#include "yaml/scene_error.h"
#include "test_util.h"

namespace fh {
namespace {

using test::write_temp_file;

const std::string kInputCamera =
    "cameras:\n"
    "  cam: {type: perspective, width: 10, height: 10, view_point: [0, 0, 5], look_at: [0, 0, -1],\n"
    "        up: [0, 1, 0], projection_distance: 1}\n";

std::string input_error(const std::string& text) { return test::scene_error(text, "input.yaml"); }
using test::error_of_file;

TEST(InputFiles, EmptyFile) {
    EXPECT_EQ(input_error(""), "FILE: error: empty scene file");
    EXPECT_EQ(input_error("\n\n   \n"), "FILE: error: empty scene file");
}

TEST(InputFiles, DirectoryGivenAsFile) {
    EXPECT_EQ(error_of_file(test::temp_dir().string()), "FILE: error: cannot read file: is a folder");
}

TEST(InputFiles, DeviceOrPipeIsNotRead) {
    // /dev/zero would never end; it is refused without reading.
    EXPECT_EQ(error_of_file("/dev/zero"), "FILE: error: cannot read file: not a regular file");
    EXPECT_EQ(error_of_file("/dev/null"), "FILE: error: cannot read file: not a regular file");
}

TEST(InputFiles, FileOfSeveralMegabytesIsRefusedUnread) {
    // 20 MB of valid YAML: refused by its size, before parsing.
    std::string text = kInputCamera;
    while (text.size() < 20'000'000) text += "# padding padding padding padding padding padding padding\n";
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(input_error(text), "FILE: error: file too large: " + std::to_string(text.size()) +
                                     " bytes (the limit is 16777216 bytes, 16 MiB)");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    EXPECT_THROW(load_scene_from_string(text, "x.yaml"), InputError);
}

TEST(InputFiles, JustUnderTheLimitLoads) {
    // Exactly 16 MiB loads; one byte more does not.
    std::string text = kInputCamera;
    const std::string pad = "# padding\n";
    while (text.size() + pad.size() <= kMaxInputBytes) text += pad;
    text += std::string(kMaxInputBytes - text.size() - 1, '#') + "\n";
    ASSERT_EQ(text.size(), kMaxInputBytes);
    const Scene s = load_scene(write_temp_file("big_ok.yaml", text)).scene;
    EXPECT_EQ(s.cameras.size(), 1u);
    EXPECT_EQ(input_error(text + "\n"), "FILE: error: file too large: 16777217 bytes (the limit is 16777216 bytes, 16 MiB)");
}

TEST(InputFiles, BinaryFile) {
    // A PNG's first bytes, and a NUL inside otherwise valid text.
    EXPECT_EQ(input_error(std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16)),
              "FILE:1:1: error: not UTF-8 text: byte 0x89 (scene and movie files are UTF-8 text)");
    EXPECT_EQ(input_error(kInputCamera + std::string("render: {max_depth: 1\0}\n", 24)),
              "FILE:4:22: error: binary data, not text: control byte 0x00 (scene and movie files are UTF-8 text)");
    EXPECT_EQ(input_error("a: \x1b[31m\n"),
              "FILE:1:4: error: binary data, not text: control byte 0x1b (scene and movie files are UTF-8 text)");
}

TEST(InputFiles, NotUtf8) {
    EXPECT_EQ(input_error("# caf\xe9 in Latin-1\n" + kInputCamera),
              "FILE:1:6: error: not UTF-8 text: byte 0xe9 (scene and movie files are UTF-8 text)");
    // Overlong form of '/', and a UTF-16 surrogate.
    EXPECT_EQ(input_error("a: \xc0\xaf\n"),
              "FILE:1:4: error: not UTF-8 text: byte 0xc0 (scene and movie files are UTF-8 text)");
    EXPECT_EQ(input_error("a: \xed\xa0\x80\n"),
              "FILE:1:4: error: not UTF-8 text: byte 0xed (scene and movie files are UTF-8 text)");
}

TEST(InputFiles, MessagesKeepWhatTheTextCheckCallsCharacters) {
    // One UTF-8 decoder (text/utf8.h) for both: a character the file
    // check lets through is kept whole in a message; what it refuses
    // (overlong, surrogate, past U+10FFFF, cut short) is escaped byte by
    // byte; C1 controls are escaped as their code.
    EXPECT_EQ(printable("\xc3\xa9\xe2\x9c\x93\xf0\x9f\x8e\xa5"), "\xc3\xa9\xe2\x9c\x93\xf0\x9f\x8e\xa5");
    EXPECT_EQ(printable("\xe0\x80\xaf"), "\\xe0\\x80\\xaf");
    EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");
    EXPECT_EQ(printable("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");
    EXPECT_EQ(printable("a\xe2\x9c"), "a\\xe2\\x9c");
    EXPECT_EQ(printable("\xc2\x85\xc2\x9f\xc2\xa0"), "\\x85\\x9f\xc2\xa0");
    for (const std::string character : {"\xc3\xa9", "\xe0\x80\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80", "\xc2\x9f"}) {
        const bool kept = printable(character) == character;
        const bool passes = utf8_length(character, 0) == character.size();
        EXPECT_EQ(kept, passes) << printable(character);
    }
    EXPECT_EQ(utf8_length("\xc2\x85", 0), 2u);  // NEL: YAML allows it, a message escapes it
}

TEST(InputFiles, Utf8TextIsFine) {
    const Scene s = load_scene(write_temp_file("utf8.yaml", "\xef\xbb\xbf# caf\xc3\xa9 \xe2\x9c\x93 \xf0\x9f\x8e\xa5\r\n" +
                                                                kInputCamera + "materials:\n  \xc3\xa9t\xc3\xa9: {color: [1, 2, 3],"
                                                                          " ambient: 0, diffuse: 0, specular: 0, phong_exponent: 1}\n")).scene;
    ASSERT_EQ(s.material_names.size(), 1u);
    EXPECT_EQ(s.material_names[0], "\xc3\xa9t\xc3\xa9");
}

TEST(InputFiles, NestedThousandsDeep) {
    // Flow style, block sequences on one line, and block maps: all refused
    // at the first level past the limit, without deep recursion.
    EXPECT_EQ(input_error("a: " + std::string(5000, '[') + std::string(5000, ']') + "\n"),
              "FILE:1:67: error: maps and lists nested more than 64 levels deep");
    EXPECT_EQ(input_error("a: " + std::string(100000, '{') + "\n"),
              "FILE:1:67: error: maps and lists nested more than 64 levels deep");
    std::string dashes;
    for (int i = 0; i < 3000; ++i) dashes += "- ";
    EXPECT_EQ(input_error(dashes + "x\n"), "FILE:1:129: error: maps and lists nested more than 64 levels deep");
    std::string block;
    for (int i = 0; i < 200; ++i) block += std::string(size_t(i), ' ') + "k:\n";
    EXPECT_EQ(input_error(block), "FILE:65:65: error: maps and lists nested more than 64 levels deep");
}

TEST(InputFiles, NestingUpToTheLimitIsParsed) {
    // The top-level map is level 1: 63 brackets inside it are fine (and then
    // the key is unknown); 64 are one too many.
    EXPECT_EQ(input_error("x: " + std::string(63, '[') + std::string(63, ']') + "\n"),
              "FILE:1:1: error: unknown key 'x' in scene");
    EXPECT_EQ(input_error("x: " + std::string(64, '[') + std::string(64, ']') + "\n"),
              "FILE:1:67: error: maps and lists nested more than 64 levels deep");
}

TEST(InputFiles, FlowListsThatNeverCloseAreRefusedBeforeYamlCppScansThem) {
    // yaml-cpp scanned all of an unclosed flow list into tokens before the
    // nesting check saw its first event: 16 MiB of '[' took 28 s and 4 GB (15 MiB here: the limit is 16).
    EXPECT_EQ(input_error("surfaces: " + std::string(std::size_t(15) << 20, '[') + "\n"),
              "FILE:1:74: error: maps and lists nested more than 64 levels deep");
    // Brackets in quotes and comments are text, not lists.
    EXPECT_EQ(input_error("# " + std::string(100, '[') + "\nx: '" + std::string(100, '{') + "'\n"),
              "FILE:2:1: error: unknown key 'x' in scene");
    EXPECT_EQ(input_error("x: \"" + std::string(100, '[') + "\\\"\"\n"), "FILE:1:1: error: unknown key 'x' in scene");
}

TEST(InputFiles, AliasesCountAsWhatTheyStandFor) {
    // yaml-cpp shares an aliased node, but the readers walk it once for each
    // alias. A group holding an alias of itself recursed until the stack ran
    // out (a crash); a chain of groups each holding the one before nests as
    // deep as the chain is long.
    EXPECT_EQ(input_error(kInputCamera + "surfaces:\n  - &g {type: group, surfaces: [*g]}\n"),
              "FILE:5:33: error: an alias inside the map or list it names");
    std::string chain = kInputCamera + "surfaces:\n  - &g0 {type: sphere, center: [0, 0, 0], radius: 1}\n";
    for (int i = 1; i < 100; ++i)
        chain += "  - &g" + std::to_string(i) + " {type: group, surfaces: [*g" + std::to_string(i - 1) + "]}\n";
    // g_i is 2 i + 2 levels deep; its alias stands 4 levels down: g30's is the 65th.
    EXPECT_EQ(input_error(chain), "FILE:36:35: error: maps and lists nested more than 64 levels deep");
    // Aliases of a colour or a list of keys read as copies would.
    EXPECT_EQ(input_error(kInputCamera + "a: &v [1, 2, 3]\nb: *v\nc: &n 3\nd: *n\n"),
              "FILE:4:1: error: unknown key 'a' in scene");
}

TEST(InputFiles, SeveralDocuments) {
    EXPECT_EQ(input_error(kInputCamera + "---\n" + kInputCamera), "FILE:4:1: error: expected a single yaml document");
    EXPECT_EQ(input_error(kInputCamera + "---\n"), "FILE:4:1: error: expected a single yaml document");
}

TEST(InputFiles, AliasesOfAliasesAreCountedNotExpanded) {
    // A "billion laughs": each level refers to the one before ten times.
    std::string text = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
    for (int i = 1; i < 30; ++i) {
        const std::string prev = "*a" + std::to_string(i - 1);
        text += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [" + prev;
        for (int k = 1; k < 10; ++k) text += ", " + prev;
        text += "]\n";
    }
    // a_k stands for about 11 x 10^k values: the eighth alias of a4 passes a million.
    EXPECT_EQ(input_error(text),
              "FILE:6:45: error: aliases standing for more than 1000000 values in all (each alias is read as a copy)");
}

TEST(InputFiles, MessagesAreOneShortLine) {
    // A value with a line break and a control character (YAML escapes),
    // and a name of 100 kB: the message stays one line and short.
    EXPECT_EQ(input_error("cameras:\n  c: {type: \"persp\\nective\\x07\"}\n"),
              "FILE:2:13: error: unknown camera type 'persp\\x0aective\\x07' (did you mean 'perspective'?)");
    // yaml-cpp 0.7 turns the escape "\N" into the lone byte 0x85, which is
    // not UTF-8: escaped too (UTF-8 letters are kept).
    EXPECT_EQ(input_error("cameras:\n  c: {type: \"\xc3\xa9\\N\"}\n"),
              "FILE:2:13: error: unknown camera type '\xc3\xa9\\x85' (expected perspective or orthographic)");
    const std::string message = input_error("cameras:\n  c: {type: " + std::string(100000, 'p') + "}\n");
    EXPECT_LT(message.size(), 500u);
    EXPECT_EQ(message.find('\n'), std::string::npos);
    EXPECT_EQ(message.rfind("FILE:2:13: error: unknown camera type 'ppp", 0), 0u) << message;
}

TEST(InputFiles, LongNamesGetNoQuadraticSuggestion) {
    // An undefined material name of 400 kB next to a defined one of 1000
    // bytes (YAML keys stop at 1024): no "did you mean", which would compare
    // them at quadratic cost (400 million cells).
    const std::string defined(1000, 'm'), used = std::string(400000, 'm') + "n";
    const auto start = std::chrono::steady_clock::now();
    const std::string message =
        input_error(kInputCamera + "materials:\n  " + defined +
                    ": {color: [1, 1, 1], ambient: 0, diffuse: 0, specular: 0, phong_exponent: 1}\n"
                    "surfaces:\n  - {type: sphere, center: [0, 0, 0], radius: 1, material: " + used + "}\n");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
    EXPECT_EQ(message.rfind("FILE:7:", 0), 0u) << message.substr(0, 100);
    EXPECT_NE(message.find("error: undefined material 'mmmm"), std::string::npos) << message.substr(0, 100);
    EXPECT_EQ(message.find("did you mean"), std::string::npos);
}

TEST(InputFiles, ManyKeysAreCheckedInLinearTime) {
    // 60000 names in one map, the last one repeated: found without comparing
    // every pair (which took seconds).
    std::string text = kInputCamera + "lights:\n";
    for (int i = 0; i < 60000; ++i) text += "  l" + std::to_string(i) + ": 0\n";
    text += "  l7: 0\n";
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(input_error(text), "FILE:60005:3: error: duplicate key 'l7' in 'lights'");
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
}

TEST(InputFiles, FromStringEqualsFromFile) {
    const Scene a = load_scene(std::string(FIRSTHIT_SOURCE_DIR) + "/animations/scene.yaml").scene;
    std::ifstream in(std::string(FIRSTHIT_SOURCE_DIR) + "/animations/scene.yaml", std::ios::binary);
    const std::string content{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const Scene b = load_scene_from_string(content, "scene.yaml").scene;
    EXPECT_EQ(a.material_names, b.material_names);
    EXPECT_EQ(a.spheres().size(), b.spheres().size());
    EXPECT_EQ(a.cameras.size(), b.cameras.size());
    try {
        load_scene_from_string("cameras: {}\n", "in memory.yaml");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.formatted(), "in memory.yaml:1:10: error: 'cameras' must name at least one camera");
    }
}

// Inputs the fuzzer found (scripts/fuzz.sh); each hung or crashed once.
std::string regression(const std::string& name) {
    return std::string(FIRSTHIT_SOURCE_DIR) + "/tests/yaml/fuzz_regressions/" + name;
}

TEST(FuzzRegressions, StrayCommaNoLongerHangsTheYamlParser) {
    // yaml-cpp 0.7 loops forever (allocating) on a ',' that cannot start a
    // value (jbeder/yaml-cpp#1040); the loader stops at the second document.
    EXPECT_EQ(input_error(","), "FILE:1:1: error: invalid yaml: unexpected ','");
    EXPECT_EQ(input_error("- a\n, b\n"), "FILE:2:1: error: invalid yaml: unexpected ','");
    EXPECT_EQ(input_error("--- ,\n"), "FILE:1:5: error: invalid yaml: unexpected ','");
    EXPECT_EQ(error_of_file(regression("scene-timeout-stray-comma.yaml")),
              "FILE:3:4: error: invalid yaml: unexpected ','");
    const std::string movie = regression("movie-timeout-comma-at-top-level.yaml");
    EXPECT_FALSE(is_movie_file(movie));
    try {
        load_movie(movie);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.formatted(), movie + ":1:1: error: invalid yaml: unexpected ','");
    }
}

}  // namespace
}  // namespace fh
