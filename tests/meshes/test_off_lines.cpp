// The OFF check (meshes/off_lines.h): the whole file read as Debian's
// assimp 5.2.5 reads it, and what it would allocate without bound, write
// past or read past refused with its line; every other file passes.
#include <gtest/gtest.h>

#include <string>

#include "meshes/mesh_loader.h"
#include "meshes/off_lines.h"
#include "test_util.h"

namespace fh {
namespace {

// The formatted error of checking `content` as an .off, the path shown as FILE.
std::string off_check_error(const std::string& content) {
    return test::file_check_error("check.off", content, [](const std::string& path) { check_off_file(path); });
}

const std::string kOffTriangle = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

TEST(OffLines, WellFormedFilesPass) {
    EXPECT_EQ(off_check_error(kOffTriangle), "(no error)");
    EXPECT_EQ(off_check_error("# by hand\nCOFF 3 1 0\r\n0 0 0 1 1 1\r\n1 0 0 1 1 1\r\n0 1 0 1 1 1\r\n9 0 1 2 0 1 2 0 1 2"),
              "(no error)");
    // A UTF-8 byte order mark, which assimp drops: the file loads.
    const MeshData m = load_mesh(test::write_temp_file("bom.off", "\xEF\xBB\xBF" + kOffTriangle));
    EXPECT_EQ(m.triangles.size(), 1u);
    // A line of 4,095 bytes is the longest assimp's buffer takes whole.
    EXPECT_EQ(off_check_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2" + std::string(4095 - 7, ' ') + "\n"),
              "(no error)");
}

TEST(OffLines, CountsAreFoundWhereAssimpFindsThem) {
    // Behind a byte order mark, and behind 64 KiB of comments: an earlier
    // check read the file's first 64 KiB as they are and missed both
    // (a 60-byte file made assimp allocate 11 GB).
    EXPECT_EQ(off_check_error("\xEF\xBB\xBFOFF\n400000000 400000000 0\n0 0 0\n"),
              "FILE: error: the OFF header declares 400000000 vertices and 400000000 faces (at least 3199999999 "
              "bytes) but only 9 bytes follow the counts: a truncated file?");
    EXPECT_EQ(off_check_error("OFF\n#" + std::string(70000, 'x') + "\n400000000 1 0\n" + kOffTriangle.substr(10)),
              "FILE: error: the OFF header declares 400000000 vertices and 1 face (at least 2400000001 bytes) but "
              "only 29 bytes follow the counts: a truncated file?");
}

TEST(OffLines, WhatAssimpWouldReadOrWritePastIsRefused) {
    // Its reader ends the copy of a line of 4,096 bytes one byte past its
    // stack buffer.
    EXPECT_EQ(off_check_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2" + std::string(4096 - 7, ' ') + "\n"),
              "FILE:6:1: error: a line of 4,096 bytes or more: assimp 5.2.5's OFF reader copies each line into "
              "4,096 bytes and would end the copy past them");
    // A face line of no vertex, or more than 9, counts assimp's faces down:
    // past zero, the validator reads past the face array.
    const std::string bad_face = "FILE:6:1: error: a face with no vertices, or with more than 9 (the most assimp's "
                                 "OFF reader takes)";
    EXPECT_EQ(off_check_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n0\n0\n3 0 1 2\n"), bad_face);
    EXPECT_EQ(off_check_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n10 0 1 2 0 1 2 0 1 2 0\n"), bad_face);
    // Lines as assimp splits them: blank lines and "\r" are line ends, so
    // the bad face is still the file's sixth line.
    EXPECT_EQ(off_check_error("OFF\n3 1 0\n0 0 0\r1 0 0\n\n0 1 0\n 0\n"),
              "FILE:6:1: error: a face with no vertices, or with more than 9 (the most assimp's OFF reader "
              "takes)");
    // Lines after the faces the header declares are not read.
    EXPECT_EQ(off_check_error(kOffTriangle + "0\n"), "(no error)");
    // What assimp takes for a UTF-32 byte order mark it converts by reading
    // past the file's end; OFF and STL alike.
    const std::string utf32 = "FILE: error: the file starts with bytes FE FF 00 00, which assimp 5.2.5 takes for a "
                              "UTF-32 byte order mark: converting the text, it would read past the file's end";
    EXPECT_EQ(off_check_error(std::string("\xFE\xFF\0\0", 4) + kOffTriangle), utf32);
    EXPECT_EQ(test::check_error(test::write_temp_file("utf32.stl", std::string("\xFE\xFF\0\0", 4) + "solid x\n"),
                                [](const std::string& path) { load_mesh(path); }),
              utf32);
}

}  // namespace
}  // namespace fh
