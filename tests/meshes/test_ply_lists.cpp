// The PLY list check (meshes/ply_lists.h): lengths assimp 5.2.5 would size a
// list by before reading it are refused where they exceed what follows
// them; every file that is well formed passes, with its lines as assimp
// splits them (CRLF, a last line without a line end, elements assimp skips).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "meshes/ply_lists.h"
#include "text/input_error.h"
#include "test_util.h"

namespace fh {
namespace {

// The formatted error of checking `content` as a .ply, the path shown as FILE.
std::string ply_error(const std::string& content) {
    return test::file_check_error("lists.ply", content, [](const std::string& path) { check_ply_lists(path); });
}

const std::string kTriangleHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
const std::string kPlyVertices = "0 0 0\n1 0 0\n0 1 0\n";

std::string le32(std::uint32_t v) {
    std::string s;
    for (int i = 0; i < 4; ++i) s += static_cast<char>(v >> (8 * i) & 0xff);
    return s;
}

TEST(PlyLists, WellFormedFilesPass) {
    EXPECT_EQ(ply_error(kTriangleHeader + kPlyVertices + "3 0 1 2\n"), "(no error)");
    // CRLF lines, and a last line with no line end.
    std::string crlf = kTriangleHeader + kPlyVertices + "3 0 1 2";
    for (size_t at = crlf.find('\n'); at != std::string::npos; at = crlf.find('\n', at + 2)) crlf.insert(at, "\r");
    EXPECT_EQ(ply_error(crlf), "(no error)");
    EXPECT_EQ(ply_error(kTriangleHeader + kPlyVertices + "3 0 1 2"), "(no error)");
    // A polygon of 200 corners: a list as long as its line allows.
    std::string polygon = "ply\nformat ascii 1.0\nelement face 1\nproperty list ushort int vertex_indices\nend_header\n200";
    for (int i = 0; i < 200; ++i) polygon += " " + std::to_string(i);
    EXPECT_EQ(ply_error(polygon + "\n"), "(no error)");
    // Binary, little-endian: three float vertices, one face.
    std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                         "property float y\nproperty float z\nelement face 1\n"
                         "property list uchar uint vertex_indices\nend_header\n";
    binary += std::string(36, '\0') + '\3' + le32(0) + le32(1) + le32(2);
    EXPECT_EQ(ply_error(binary), "(no error)");
}

TEST(PlyLists, AsciiLengthsBeyondTheirLine) {
    // Fuzzing found it: a uchar length that assimp reads as 32 bits (a 34 GB
    // list); 1,500,000,000 took 30 s and 11.7 GB.
    EXPECT_EQ(ply_error(kTriangleHeader + kPlyVertices + "4294967289 0 1 2\n"),
              "FILE:13:1: error: a PLY list of 4294967289 values, but only 6 bytes follow on its line (a corrupt "
              "file?)");
    // A signed length of -1 is 4,294,967,295 to assimp.
    std::string signed_length = kTriangleHeader;
    signed_length.replace(signed_length.find("uchar int"), 9, "int int");
    EXPECT_EQ(ply_error(signed_length + kPlyVertices + "-1 0 1 2\n"),
              "FILE:13:1: error: a PLY list of 4294967295 values, but only 6 bytes follow on its line (a corrupt "
              "file?)");
    // Four values where three follow: short, but not beyond the line.
    EXPECT_EQ(ply_error(kTriangleHeader + kPlyVertices + "4 0 1 2\n"), "(no error)");
}

TEST(PlyLists, ReadWhereAssimpReads) {
    // The fuzzer's file: a garbled property line, which assimp drops (so the
    // vertex has two values, and a face's line with a NUL ends early), then
    // a length glued to a word, which assimp reads up to the word.
    const std::string found =
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nprxperty float z\n"
        "element face 4\nproperty list uchar int vertex_indices\nend_header\n5 0 0\n1nan0\n0 1 0\n0 0 1\n"
        "3 0 2 1%=" + std::string(1, '\0') + "42949672953da-e3 1 2 3\n";
    EXPECT_EQ(ply_error(found),
              "FILE:15:1: error: a PLY list of 4294967289 values, but only 11 bytes follow on its line (a corrupt "
              "file?)");
    // An element of a name assimp does not know has its count read from
    // that name -- 0 -- so its lines are read as the next element's.
    const std::string unknown =
        "ply\nformat ascii 1.0\nelement normals 1\nproperty float w\nelement face 1\n"
        "property list uint int vertex_indices\nend_header\n4000000000\n3 0 1 2\n";
    EXPECT_EQ(ply_error(unknown),
              "FILE:8:1: error: a PLY list of 4000000000 values, but only 0 bytes follow on its line (a corrupt "
              "file?)");
    // A line that runs out of values before its properties do: assimp
    // would read the rest from what an earlier line left in its buffer.
    const std::string short_line =
        "ply\nformat ascii 1.0\nelement face 2\nproperty uchar flags\nproperty list uchar int vertex_indices\n"
        "end_header\n0 3 1 2 3 4294967295 4294967295\n7\n";
    EXPECT_EQ(ply_error(short_line),
              "FILE:8:2: error: a PLY line holds values for only 1 of its 2 properties; assimp would read the "
              "others from an earlier line");
    // A name read as a count ("element 4000000000 1"), for an element assimp skips line by line.
    const std::string named = "ply\nformat ascii 1.0\nelement 4000000000 1\nproperty float x\nend_header\n1\n";
    EXPECT_EQ(ply_error(named), "FILE: error: assimp 5.2.5 would read 4000000000 instances of a PLY element from a "
                            "file of " + std::to_string(named.size()) + " bytes");
}

TEST(PlyLists, BinaryLengthsBeyondTheFile) {
    const std::string header = "ply\nformat binary_little_endian 1.0\nelement face 1\n"
                               "property list uint uint vertex_indices\nend_header\n";
    const std::string after_length = std::to_string(header.size() + 4);
    EXPECT_EQ(ply_error(header + le32(0xffffffffu) + le32(0) + le32(1) + le32(2)),
              "FILE: error: a binary PLY list of 4294967295 values at byte " + after_length +
                  ", but only 12 bytes follow (a corrupt or truncated file?)");
    // Cut short: past its end assimp reads the line ends its buffer was
    // filled with (a length of 0x0a0a0a0a).
    EXPECT_EQ(ply_error(header + le32(3) + le32(0) + le32(1) + le32(2)), "(no error)");
    EXPECT_EQ(ply_error(header + le32(3) + le32(0) + le32(1)),
              "FILE: error: a binary PLY list of 3 values at byte " + after_length +
                  ", but only 8 bytes follow (a corrupt or truncated file?)");
    // Cut before the second face's length: assimp takes the filler for it,
    // 0x0a0a0a0a values (1.3 GB).
    std::string two_faces = header;
    two_faces.replace(two_faces.find("face 1"), 6, "face 2");
    EXPECT_EQ(ply_error(two_faces + le32(3) + le32(0) + le32(1) + le32(2) + std::string(2, '\0')),
              "FILE: error: the binary PLY data ends before its elements do (a truncated file?)");
    const std::string two = "ply\nformat binary_big_endian 1.0\nelement face 2\n"
                            "property list uchar int vertex_indices\nend_header\n";
    std::string big = two + '\3' + std::string("\0\0\0\0\0\0\0\1\0\0\0\2", 12);
    EXPECT_EQ(ply_error(big), "FILE: error: the binary PLY data ends before its elements do (a truncated file?)");
    EXPECT_EQ(ply_error(big + '\1' + std::string("\0\0\0\7", 4)), "(no error)");
}

// Headers whose elements assimp fills its arrays from past their end, or
// reads through a null pointer: a second vertex element longer than the
// first aborted the process in glibc's malloc (found while fuzzing the
// mesh loader with valgrind), a face element of texture coordinates without
// indices crashed it.
TEST(PlyLists, ElementsAssimpWritesPastItsArrays) {
    const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
    const std::string two_vertex_elements =
        "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz + "element vertex 3\n" + xyz +
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n";
    EXPECT_EQ(ply_error(two_vertex_elements),
              "FILE: error: a PLY header with two 'vertex' elements (assimp 5.2.5 would write past the end of its "
              "arrays)");
    std::string face_and_strip = kTriangleHeader;
    face_and_strip.insert(face_and_strip.find("end_header"),
                          "element tristrips 1\nproperty list int int vertex_indices\n");
    EXPECT_EQ(ply_error(face_and_strip + kPlyVertices + "3 0 1 2\n3 0 1 2\n"),
              "FILE: error: a PLY header with two elements of faces ('face' or 'tristrips') (assimp 5.2.5 would write "
              "past the end of its arrays)");
    std::string texcoords_only = kTriangleHeader;
    texcoords_only.replace(texcoords_only.find("vertex_indices"), 14, "texcoord");
    texcoords_only.replace(texcoords_only.find("uchar int"), 9, "uchar float");
    EXPECT_EQ(ply_error(texcoords_only + kPlyVertices + "6 0 0 1 0 0 1\n"),
              "FILE: error: a PLY 'face' element with texture coordinates but no vertex indices (assimp 5.2.5 would "
              "read them through a null pointer)");
    // Texture coordinates beside the indices, and a vertex element beside
    // others of other names, are read as they should be.
    std::string texcoords = kTriangleHeader;
    texcoords.insert(texcoords.find("end_header"), "property list uchar float texcoord\n");
    EXPECT_EQ(ply_error(texcoords + kPlyVertices + "3 0 1 2 6 0 0 1 0 0 1\n"), "(no error)");
    std::string empty_first = two_vertex_elements;
    empty_first.replace(empty_first.find("vertex 1"), 8, "vertex 0");
    empty_first.erase(empty_first.find("0 0 0\n"), 6);
    EXPECT_EQ(ply_error(empty_first), "(no error)");  // an element of no vertices writes none
    std::string with_edges = kTriangleHeader;
    with_edges.insert(with_edges.find("end_header"), "element edge 0\nproperty int vertex1\n");
    EXPECT_EQ(ply_error(with_edges + kPlyVertices + "3 0 1 2\n"), "(no error)");
}

TEST(PlyLists, TextureCoordinatesPastTheIndices) {
    // For a face's list of 6, 7 or 8 texture coordinates assimp reads the
    // vertex index of each two (the fourth for the seventh and eighth),
    // whatever the face's own count: past a triangle's three.
    std::string header = kTriangleHeader;
    header.insert(header.find("end_header"), "property list uchar float texcoord\n");
    EXPECT_EQ(ply_error(header + kPlyVertices + "3 0 1 2 6 0 0 1 0 0 1\n"), "(no error)");
    EXPECT_EQ(ply_error(header + kPlyVertices + "4 0 1 2 2 8 0 0 1 0 0 1 1 1\n"), "(no error)");
    EXPECT_EQ(ply_error(header + kPlyVertices + "3 0 1 2 8 0 0 1 0 0 1 1 1\n"),
              "FILE:14:1: error: a PLY face with 8 texture coordinates but 3 vertex indices: assimp 5.2.5 would "
              "read past the indices (one for each two coordinates)");
    // A list the line ends inside gets a value more: 6 given as 7.
    EXPECT_EQ(ply_error(header + kPlyVertices + "3 0 1 2 6 0 0 1\n"),
              "FILE:14:1: error: a PLY face with 7 texture coordinates but 3 vertex indices: assimp 5.2.5 would "
              "read past the indices (one for each two coordinates)");
    // The coordinates first, the indices after them, in binary.
    std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                         "property float y\nproperty float z\nelement face 1\nproperty list uchar float texcoord\n"
                         "property list uchar uint vertex_indices\nend_header\n";
    binary += std::string(36, '\0') + '\6' + std::string(24, '\0') + '\2' + le32(0) + le32(1);
    EXPECT_EQ(ply_error(binary),
              "FILE: error: a PLY face with 6 texture coordinates but 2 vertex indices: assimp 5.2.5 would read "
              "past the indices (one for each two coordinates) (the face at byte 241)");
}

TEST(PlyLists, LinesThatFillAssimpsBuffer) {
    // A line of 1 MiB - 1 bytes leaves its '\n' on the last byte of
    // assimp's 1 MiB line buffer: the parser's walk past it reads past the
    // buffer, valid values or not (and the error for a value it cannot read
    // quotes the line with strlen, which finds no zero byte in it).
    std::string vertex = "0 0 0";
    vertex += std::string((std::size_t(1) << 20) - 1 - vertex.size(), ' ');
    EXPECT_EQ(ply_error(kTriangleHeader + vertex + "\n1 0 0\n0 1 0\n3 0 1 2\n"),
              "FILE:10:1: error: a PLY line of 1048575 bytes: assimp 5.2.5 would read past its 1 MiB line buffer "
              "after it");
    vertex.pop_back();
    EXPECT_EQ(ply_error(kTriangleHeader + vertex + "\n1 0 0\n0 1 0\n3 0 1 2\n"), "(no error)");
    std::string header = kTriangleHeader;
    header.insert(header.find("end_header"), "property float q\n");
    std::string face = "3 0 1 2 x";
    face += std::string((std::size_t(1) << 20) - 1 - face.size(), 'y');
    EXPECT_EQ(ply_error(header + kPlyVertices + face + "\n"),
              "FILE:14:1: error: a PLY line of 1048575 bytes: assimp 5.2.5 would read past its 1 MiB line buffer "
              "after it");
}

TEST(PlyLists, DataThatEndsBeforeItsElements) {
    // Past the file's end assimp reads its last line again for each instance
    // the header still declares: 1,000 faces of 1,000 indices from one line.
    std::string many = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                       "property float z\nelement face 1000\nproperty list ushort int vertex_indices\n"
                       "end_header\n" + kPlyVertices + "1000";
    for (int i = 0; i < 1000; ++i) many += " 0";
    EXPECT_EQ(ply_error(many + "\n"),
              "FILE: error: the PLY data ends 999 element instances before its header says (a truncated file?); "
              "assimp 5.2.5 would read its last line again for each");
    // A last line without a line end is read once, as it should be.
    EXPECT_EQ(ply_error(kTriangleHeader + kPlyVertices + "3 0 1 2"), "(no error)");
}

// A binary header of exactly `length` bytes: comment lines fill it out.
std::string binary_header_of(std::size_t length) {
    const std::string head = "ply\nformat binary_little_endian 1.0\n";
    const std::string tail = "element face 1\nproperty list uchar uint vertex_indices\nend_header\n";
    std::string header = head;
    for (std::size_t left = length - head.size() - tail.size(); left > 0;) {
        const std::size_t n = left > 65536 + 9 ? 65536 : left;  // never leave a line shorter than "comment \n"
        header += "comment " + std::string(n - 9, 'x') + "\n";
        left -= n;
    }
    return header + tail;
}

TEST(PlyLists, BinaryDataAtTheBufferEnd) {
    // assimp reads the header through a 1 MiB buffer and hands the binary
    // reader what is left of it: nothing, when the header ends on its last
    // byte, and the reader crashes reading that nothing (fuzzing found it).
    const std::string face = '\3' + le32(0) + le32(1) + le32(2);
    constexpr std::size_t kMiB = std::size_t(1) << 20;
    ASSERT_EQ(binary_header_of(kMiB).size(), kMiB);
    EXPECT_EQ(ply_error(binary_header_of(kMiB) + face),
              "FILE: error: the binary PLY header ends at byte 1048576, the end of assimp 5.2.5's 1 MiB buffer, "
              "which makes its reader crash");
    // A byte either way, and the data is read from the buffer or the next block.
    EXPECT_EQ(ply_error(binary_header_of(kMiB - 1) + face), "(no error)");
    EXPECT_EQ(ply_error(binary_header_of(kMiB + 1) + face), "(no error)");
    EXPECT_EQ(ply_error(binary_header_of(kMiB - 1) + face.substr(0, 9)),
              "FILE: error: a binary PLY list of 3 values at byte " + std::to_string(kMiB) +
                  ", but only 8 bytes follow (a corrupt or truncated file?)");
}

}  // namespace
}  // namespace fh
