// The OBJ line-statement check (meshes/obj_lines.h): a line statement
// that makes Debian's assimp 5.2.5 write past its vertex array, or read on
// past its line, is refused with its line; every other file passes, its
// lines split as assimp splits them ("\" before a line end joins them).
#include <gtest/gtest.h>

#include <string>

#include "meshes/mesh_loader.h"
#include "meshes/obj_lines.h"
#include "text/input_error.h"
#include "test_util.h"

namespace fh {
namespace {

// The formatted error of checking `content` as an .obj, the path shown as FILE.
std::string obj_error(const std::string& content) {
    return test::file_check_error("lines.obj", content, [](const std::string& path) { check_obj_lines(path); });
}

const std::string kObjVertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
const std::string kOneVertex =
    "error: a line statement of one vertex, for which assimp 5.2.5 writes past the end of its vertex array "
    "(firsthit draws no lines)";

TEST(ObjLines, WellFormedFilesPass) {
    EXPECT_EQ(obj_error(kObjVertices + "f 1 2 3\n"), "(no error)");
    EXPECT_EQ(obj_error(kObjVertices + "l 1 2 3\nl 2 3\nf 1 2 3\n"), "(no error)");
    EXPECT_EQ(obj_error(kObjVertices + "vt 0 0\nvn 0 0 1\nl 1/1 2/1\nl 1/1/1 2/1/1\nl 1//1 3//1\nf 1 2 3"), "(no error)");
    // A line joined to the next by "\": two vertices.
    EXPECT_EQ(obj_error(kObjVertices + "l 1 \\\n2\n"), "(no error)");
    // A zero index: assimp refuses the file itself ("Invalid face index").
    EXPECT_EQ(obj_error(kObjVertices + "l 0\n"), "(no error)");
}

TEST(ObjLines, OneVertexIsRefused) {
    EXPECT_EQ(obj_error(kObjVertices + "l 1\nl 1\nl 1 2 3\n"), "FILE:4:1: " + kOneVertex);
    EXPECT_EQ(obj_error(kObjVertices + "f 1 2 3\r\nl -1/1\r\n"), "FILE:5:1: " + kOneVertex);
    // The statement's own line, where a "\" joins two.
    EXPECT_EQ(obj_error(kObjVertices + "l \\\n1\nl 1 2\n"), "FILE:4:1: " + kOneVertex);
    // After "\" and a carriage return assimp skips to the next '\n' and takes
    // the character after it: "l 1 \\\r 2\n" is one vertex, "l 1 \\\r\n2" two.
    EXPECT_EQ(obj_error(kObjVertices + "l 1 \\\r 2\n"), "FILE:4:1: " + kOneVertex);
    EXPECT_EQ(obj_error(kObjVertices + "l 1 \\\r\n2\n"), "(no error)");
    // atoi's value, stepped over by its digits: "0012" is 12, then "12"
    // again (two vertices); "12" alone is one.
    EXPECT_EQ(obj_error(kObjVertices + "l 0012\n"), "(no error)");
    EXPECT_EQ(obj_error(kObjVertices + "l 12\n"), "FILE:4:1: " + kOneVertex);
}

TEST(ObjLines, ReadingPastTheLineIsRefused) {
    // "l" alone is an empty face to assimp, whatever its buffer holds beyond.
    EXPECT_EQ(obj_error(kObjVertices + "# 5\nl\n"), "(no error)");
    EXPECT_EQ(obj_error(kObjVertices + "l 1/1/1/1 2\n"),
              "FILE:4:1: error: a line statement with a vertex of more than three indices, which assimp 5.2.5 "
              "reads on past its line (firsthit draws no lines)");
    // Faces and points too: a one-line file is read past the buffer's end.
    EXPECT_EQ(obj_error("f 1/1/1/1      \n"),
              "FILE:1:1: error: a face statement with a vertex of more than three indices, which assimp 5.2.5 "
              "reads on past its line");
    EXPECT_EQ(obj_error(kObjVertices + "f 1 2 3\np 1/1/1/1\n"),
              "FILE:5:1: error: a point statement with a vertex of more than three indices, which assimp 5.2.5 "
              "reads on past its line (firsthit draws no points)");
    EXPECT_EQ(obj_error(kObjVertices + "vt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\np 2\n"), "(no error)");
}

TEST(ObjLines, VerticalTabsInFacesAreRefused) {
    // atoi skips a vertical tab and the line's end after it, and reads on
    // past the end of assimp's line buffer where the statement fills it.
    const std::string refused = "error: a vertical tab (byte 0x0b) in a face statement, which assimp 5.2.5 reads "
                                "past (its atoi skips it and the line's end)";
    EXPECT_EQ(obj_error("f 1 2 3 4 5 6 7\v\n"), "FILE:1:1: " + refused);
    EXPECT_EQ(obj_error(kObjVertices + "p 1\n# \v\nl 1 2\v3\n"), "FILE:6:1: " + refused);
    EXPECT_EQ(obj_error(kObjVertices + "# \v\nf 1 2 3\n"), "(no error)");
}

TEST(ObjLines, BackslashesAtTheCachesEndAreRefused) {
    // assimp reads an OBJ file in blocks of 16 MiB: a "\\" on a block's last
    // byte makes it look at the byte after its cache, and one before a "\r"
    // makes it look for the next '\n' -- past the cache where none follows
    // in the block.
    constexpr std::size_t kBlock = std::size_t(1) << 24;
    auto obj_with_backslash_at = [](std::size_t at, const std::string& after) {
        std::string obj = kObjVertices + "f 1 2 3\n# ";
        obj += std::string(at - obj.size(), 'x') + "\\" + after + "f 1 2 3\n";
        return obj;
    };
    const std::string refused = "FILE:5:1: error: a '\\' before a line end that makes assimp 5.2.5 read past the end "
                                "of its 16 MiB line cache";
    EXPECT_EQ(obj_error(obj_with_backslash_at(kBlock - 1, "\n")), refused);
    EXPECT_EQ(obj_error(obj_with_backslash_at(kBlock - 2, "\r\n")), refused);  // the '\n' in the next block
    EXPECT_EQ(obj_error(obj_with_backslash_at(kBlock - 2, "\n")), "(no error)");
    EXPECT_EQ(obj_error(obj_with_backslash_at(kBlock - 3, "\r\n")), "(no error)");
}

// At the loader: the 54-byte file that aborted the process in glibc's malloc.
TEST(ObjLines, TheLoaderRefusesBeforeAssimpReads) {
    const std::string path = test::write_temp_file("overflow.obj", kObjVertices + "l 1\nl 1\nl 1 2 3\n");
    try {
        load_mesh(path);
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 4);
        EXPECT_NE(std::string(e.what()).find("one vertex"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace fh
