// Hints on common YAML mistakes (yaml/yaml_hints.h): yaml_hint on mistakes in a
// scene in the report's format, at the places and with the words yaml-cpp 0.7
// reports them, and the loaders' messages that end in the hints.
#include <gtest/gtest.h>

#include <string>

#include "text/input_error.h"
#include "yaml/movie_loader.h"
#include "yaml/scene_error.h"
#include "yaml/yaml_hints.h"

namespace fh {
namespace {

using test::scene_error;

// A correct scene (animations/scene.yaml, shortened). Its comments hold
// quotes, apostrophes and brackets, and a flow map spans lines 5-6: none of
// them is a mistake. Line 4 is "materials:", line 7 the material "red",
// line 12 the first sphere and line 22 the empty one after the last newline.
const std::string kHintScene =
    "# A scene in the report's format (animations/scene.yaml, shortened).\n"
    "# Colours are 0..255; a material's \"one colour\" serves all its terms.\n"
    "\n"
    "materials:\n"
    "  plane: {color: [130, 130, 130], ambient: 0.1, diffuse: 0.5, specular: 10.5, phong_exponent: 100,\n"
    "          glazed: true, reflectivity: 0.05}\n"
    "  red:   {color: [255, 19, 1], ambient: 0.1, diffuse: 0.5, specular: 1.5, phong_exponent: 10}\n"
    "  teal:  {color: [20, 255, 255], ambient: 0.1, diffuse: 0.3, specular: 10, phong_exponent: 100}  # 'teal [sic\n"
    "\n"
    "surfaces:\n"
    "  # Spheres [don't move them] and the plane {z = -1}.\n"
    "  - {type: sphere, center: [-3, 0, 0], radius: 1, material: red}\n"
    "  - {type: sphere, center: [-3, -3, 0.5], radius: 1.5, material: teal}\n"
    "  - {type: plane, normal: [0, 0, 1], distance: -1, material: plane}\n"
    "\n"
    "lights:\n"
    "  ambient: {type: ambient, color: [255, 255, 255], intensity: 0.002}\n"
    "\n"
    "cameras:\n"
    "  perspective: {type: perspective, width: 80, height: 80, view_point: [2, -10, 10],\n"
    "                look_at: [0, 2, -1], up: [0, 0, 1], projection_distance: 10}\n";

// kHintScene with the first `from` replaced by `to`.
std::string edited(const std::string& from, const std::string& to) {
    std::string s = kHintScene;
    const std::size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? s : s.replace(at, from.size(), to);
}

const std::string kSameColumn = "keys of one map, and items of one list, start in the same column";

TEST(YamlHints, NoneForACorrectFile) {
    EXPECT_EQ(yaml_hint(kHintScene, 0, 0, "end of map not found"), "");
    for (int line = 1; line <= 22; ++line)
        for (const char* message : {"end of map flow not found", "illegal flow end", "unknown token"})
            EXPECT_EQ(yaml_hint(kHintScene, line, 1, message), "") << line << " " << message;
    // Tabs inside a flow spanning lines, escaped quotes and apostrophes are
    // fine too; yaml-cpp reads these files.
    const std::string tab_in_flow = edited("          glazed", "\t\tglazed");
    EXPECT_EQ(yaml_hint(tab_in_flow, 22, 1, "end of map flow not found"), "");
    const std::string quotes = edited("material: red}", "material: \"r\\\"e{d\", name: 'it''s', note: don't}");
    EXPECT_EQ(yaml_hint(quotes, 22, 1, "end of map flow not found"), "");
}

TEST(YamlHints, Tab) {
    EXPECT_EQ(yaml_hint(edited("  red:", "\tred:"), 7, 2, "end of map not found"),
              "line 7 is indented with a tab; YAML indents with spaces only");
    EXPECT_EQ(yaml_hint("a:\n  b: 1\n\tc: 2\n", 3, 1, "illegal tab when looking for indentation"),
              "line 3 is indented with a tab; YAML indents with spaces only");
}

TEST(YamlHints, UnclosedQuote) {
    // yaml-cpp reads on to the end of the file, or to the next quote.
    const std::string hint = "the quote opened at line 12, column 61 is not closed on its line";
    EXPECT_EQ(yaml_hint(edited("material: red}", "material: \"red}"), 22, 1, "end of map flow not found"), hint);
    EXPECT_EQ(yaml_hint(edited("material: red}", "material: 'red}"), 22, 1, "end of map flow not found"), hint);
}

TEST(YamlHints, Brackets) {
    EXPECT_EQ(yaml_hint(edited("center: [-3, 0, 0]", "center: [-3, 0, 0"), 12, 63, "illegal flow end"),
              "the '[' at line 12, column 28 is closed by '}' at line 12, column 63");
    EXPECT_EQ(yaml_hint(edited("radius: 1,", "radius: 1],"), 12, 49, "illegal flow end"),
              "the '{' at line 12, column 5 is closed by ']' at line 12, column 49");
    EXPECT_EQ(yaml_hint(edited("material: red}", "material: red}}"), 12, 65, "illegal flow end"),
              "the '}' at line 12, column 65 closes nothing");
    EXPECT_EQ(yaml_hint(edited("material: red}", "material: red"), 14, 3, "illegal block entry"),
              "the '{' at line 12, column 5 is never closed");
    EXPECT_EQ(yaml_hint(kHintScene + "effects: [ambient, diffuse\n", 23, 1, "end of sequence flow not found"),
              "the '[' at line 22, column 10 is never closed");
}

TEST(YamlHints, MissingSpaceAfterColon) {
    EXPECT_EQ(yaml_hint(edited("materials:", "materials:x"), 5, 8, "illegal map value"),
              "line 4: put a space after the colon in 'materials:x' ('materials: x')");
    EXPECT_EQ(yaml_hint("scene:scene.yaml\nfps: 3\n", 2, 4, "illegal map value"),
              "line 1: put a space after the colon in 'scene:scene.yaml' ('scene: scene.yaml')");
    // Only for the messages of block structure.
    EXPECT_EQ(yaml_hint(edited("materials:", "materials:x"), 5, 8, "unknown escape character: q"), "");
}

TEST(YamlHints, MissingColon) {
    EXPECT_EQ(yaml_hint(edited("materials:", "materials"), 5, 8, "illegal map value"),
              "line 4: 'materials' has no colon; write 'materials:'");
    EXPECT_EQ(yaml_hint(edited("red:   {", "red    {"), 7, 30, "end of map not found"),
              "line 7: 'red' has no colon; write 'red:'");
    EXPECT_EQ(yaml_hint("scene: scene.yaml\nfps 3\nseconds: 2\n", 3, 8, "illegal map value"),
              "line 2: 'fps 3' has no colon; write 'fps: 3'");
}

TEST(YamlHints, Indentation) {
    EXPECT_EQ(yaml_hint(edited("  red:", "   red:"), 7, 4, "end of map not found"),
              "line 7 is indented by 3 spaces and line 5 by 2: " + kSameColumn);
    EXPECT_EQ(yaml_hint(edited("  red:", " red:"), 7, 2, "end of map not found"),
              "line 7 is indented by 1 space and line 5 by 2: " + kSameColumn);
    EXPECT_EQ(yaml_hint(edited("  - {type: sphere, center: [-3, -3", "   - {type: sphere, center: [-3, -3"), 13, 4,
                        "end of sequence not found"),
              "line 13 is indented by 3 spaces and line 12 by 2: " + kSameColumn);
    // A key among list items, both at column 3: no two columns to compare.
    EXPECT_EQ(yaml_hint(edited("  - {type: sphere, center: [-3, -3", "  radius: 2\n  - {type: sphere, center: [-3, -3"),
                        13, 3, "end of map not found"),
              "check the indentation of line 13: " + kSameColumn);
}

TEST(YamlHintsInLoader, SceneErrorsEndInTheHint) {
    EXPECT_EQ(scene_error(kHintScene), "(no error)");
    EXPECT_EQ(scene_error(edited("  red:", "\tred:")),
              "FILE:7:2: error: invalid yaml: end of map not found "
              "(line 7 is indented with a tab; YAML indents with spaces only)");
    EXPECT_EQ(scene_error(edited("  red:", "   red:")),
              "FILE:7:4: error: invalid yaml: end of map not found "
              "(line 7 is indented by 3 spaces and line 5 by 2: " + kSameColumn + ")");
    EXPECT_EQ(scene_error(edited("materials:", "materials")),
              "FILE:5:8: error: invalid yaml: illegal map value (line 4: 'materials' has no colon; write 'materials:')");
    EXPECT_EQ(scene_error(edited("materials:", "materials:x")),
              "FILE:5:8: error: invalid yaml: illegal map value "
              "(line 4: put a space after the colon in 'materials:x' ('materials: x'))");
    EXPECT_EQ(scene_error(edited("material: red}", "material: red")),
              "FILE:14:3: error: invalid yaml: illegal block entry (the '{' at line 12, column 5 is never closed)");
    EXPECT_EQ(scene_error(edited("center: [-3, 0, 0]", "center: [-3, 0, 0")),
              "FILE:12:63: error: invalid yaml: illegal flow end "
              "(the '[' at line 12, column 28 is closed by '}' at line 12, column 63)");
    EXPECT_EQ(scene_error(edited("material: red}", "material: \"red}")),
              "FILE:22:1: error: invalid yaml: end of map flow not found "
              "(the quote opened at line 12, column 61 is not closed on its line)");
}

TEST(YamlHintsInLoader, FlowMapKeys) {
    // In a flow map "radius:1" and "radius 1" are keys without a value.
    EXPECT_EQ(scene_error(edited("radius: 1,", "radius:1,")),
              "FILE:12:40: error: unknown key 'radius:1' in sphere (a missing space after the colon? write 'radius: 1')");
    EXPECT_EQ(scene_error(edited("radius: 1,", "radius 1,")),
              "FILE:12:40: error: unknown key 'radius 1' in sphere (a missing colon? write 'radius: 1')");
    EXPECT_EQ(scene_error(edited("radius: 1,", "radus: 1,")),
              "FILE:12:40: error: unknown key 'radus' in sphere (did you mean 'radius'?)");
}

TEST(YamlHintsInLoader, MovieErrorsEndInTheHint) {
    try {
        load_movie_from_string("scene:scene.yaml\nfps: 3\n", "movie.yaml");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.formatted(), "movie.yaml:2:4: error: invalid yaml: illegal map value "
                                 "(line 1: put a space after the colon in 'scene:scene.yaml' ('scene: scene.yaml'))");
    }
}

}  // namespace
}  // namespace fh
