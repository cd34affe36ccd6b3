// The mesh reader: one cube written in every format (binary ones byte by byte)
// gives the same triangles; each kind of bad file gives its own InputError,
// including the ones assimp 5.2.5 would hang on, abort on, or only log; and
// nothing is printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "text/input_error.h"
#include "meshes/assimp_messages.h"
#include "meshes/mesh_loader.h"
#include "test_util.h"

namespace fh {
namespace {

using test::write_temp_file;

// ---- the cube ----------------------------------------------------------------

// Corner i is (i>>2 & 1, i>>1 & 1, i & 1). Triangles wound counter-clockwise
// seen from outside, two per side.
std::array<int, 3> corner(int i) { return {i >> 2 & 1, i >> 1 & 1, i & 1}; }

const std::array<std::array<int, 3>, 12> kCubeTriangles = {{
    {0, 1, 3}, {0, 3, 2},  // x = 0
    {4, 6, 7}, {4, 7, 5},  // x = 1
    {0, 4, 5}, {0, 5, 1},  // y = 0
    {2, 3, 7}, {2, 7, 6},  // y = 1
    {0, 2, 6}, {0, 6, 4},  // z = 0
    {1, 5, 7}, {1, 7, 3},  // z = 1
}};

// The outward normal of triangle t (unit length: each is half a unit square).
std::array<int, 3> facet_normal(const std::array<int, 3>& t) {
    const auto a = corner(t[0]), b = corner(t[1]), c = corner(t[2]);
    const int u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const int v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

// "x y z". (Appends: GCC 12 warns falsely, -Wrestrict, on operator+ of temporaries.)
std::string xyz(const std::array<int, 3>& p) {
    std::string s = std::to_string(p[0]);
    return s.append(" ").append(std::to_string(p[1])).append(" ").append(std::to_string(p[2]));
}

// A vertex normal per corner, away from the centre (not unit length: the
// files' values are kept as they are).
std::array<int, 3> corner_normal(int i) {
    const auto p = corner(i);
    return {2 * p[0] - 1, 2 * p[1] - 1, 2 * p[2] - 1};
}

std::string cube_obj(bool normals = false) {
    std::string s = "# unit cube\n";
    for (int i = 0; i < 8; ++i) s.append("v ").append(xyz(corner(i))).append("\n");
    if (normals)
        for (int i = 0; i < 8; ++i) s.append("vn ").append(xyz(corner_normal(i))).append("\n");
    for (const auto& t : kCubeTriangles) {
        s += "f";
        for (int i : t) {
            s.append(" ").append(std::to_string(i + 1));
            if (normals) s.append("//").append(std::to_string(i + 1));
        }
        s += "\n";
    }
    return s;
}

// "x y z" or "x y z nx ny nz", one line.
std::string vertex_line(int i, bool normals) {
    std::string s = xyz(corner(i));
    if (normals) s.append(" ").append(xyz(corner_normal(i)));
    return s.append("\n");
}

std::string cube_off(bool normals = false) {
    std::string s = std::string(normals ? "NOFF" : "OFF") + "\n8 12 0\n";
    for (int i = 0; i < 8; ++i) s.append(vertex_line(i, normals));
    for (const auto& t : kCubeTriangles) s.append("3 ").append(xyz(t)).append("\n");
    return s;
}

std::string ply_header(const std::string& format, bool normals = false, int vertices = 8, int faces = 12) {
    std::string s = "ply\nformat " + format + " 1.0\ncomment firsthit test cube\n";
    s.append("element vertex ").append(std::to_string(vertices)).append("\n");
    s.append("property float x\nproperty float y\nproperty float z\n");
    if (normals) s.append("property float nx\nproperty float ny\nproperty float nz\n");
    s.append("element face ").append(std::to_string(faces)).append("\n");
    return s.append("property list uchar int vertex_indices\nend_header\n");
}

std::string cube_ply_ascii(bool normals = false) {
    std::string s = ply_header("ascii", normals);
    for (int i = 0; i < 8; ++i) s.append(vertex_line(i, normals));
    for (const auto& t : kCubeTriangles) s.append("3 ").append(xyz(t)).append("\n");
    return s;
}

// Little-endian values, byte by byte.
void put_u8(std::string& s, unsigned v) { s += static_cast<char>(v & 0xff); }
void put_u16(std::string& s, std::uint16_t v) {
    for (int i = 0; i < 2; ++i) put_u8(s, static_cast<unsigned>(v >> (8 * i)));
}
void put_u32(std::string& s, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) put_u8(s, static_cast<unsigned>(v >> (8 * i)));
}
void put_f32(std::string& s, float v) { put_u32(s, std::bit_cast<std::uint32_t>(v)); }

void put_point(std::string& s, const std::array<int, 3>& p) {
    for (int c : p) put_f32(s, static_cast<float>(c));
}

const std::size_t kPlyBinaryHeader = ply_header("binary_little_endian").size();

// 8 vertices of 12 bytes, then 12 faces of 13 (a uchar count, three int32).
std::string cube_ply_binary() {
    std::string s = ply_header("binary_little_endian");
    for (int i = 0; i < 8; ++i) put_point(s, corner(i));
    for (const auto& t : kCubeTriangles) {
        put_u8(s, 3);
        for (int i : t) put_u32(s, static_cast<std::uint32_t>(i));
    }
    return s;
}

std::string cube_stl_ascii() {
    std::string s = "solid cube\n";
    for (const auto& t : kCubeTriangles) {
        s.append("  facet normal ").append(xyz(facet_normal(t))).append("\n    outer loop\n");
        for (int i : t) s.append("      vertex ").append(xyz(corner(i))).append("\n");
        s += "    endloop\n  endfacet\n";
    }
    return s + "endsolid cube\n";
}

// An 80-byte header (not starting with "solid", which would make assimp try
// ASCII first), the facet count, then 50 bytes per facet: normal, three
// corners, attribute bytes. With `replace`, facet 3's first x is `x3`.
std::string cube_stl_binary(float x3 = 0, bool replace = false) {
    std::string s = "firsthit test cube, binary STL";
    s.resize(80, ' ');
    put_u32(s, static_cast<std::uint32_t>(kCubeTriangles.size()));
    for (std::size_t f = 0; f < kCubeTriangles.size(); ++f) {
        const auto& t = kCubeTriangles[f];
        put_point(s, facet_normal(t));
        for (int k = 0; k < 3; ++k) {
            if (replace && f == 3 && k == 0) {
                put_f32(s, x3);
                put_f32(s, static_cast<float>(corner(t[0])[1]));
                put_f32(s, static_cast<float>(corner(t[0])[2]));
            } else {
                put_point(s, corner(t[k]));
            }
        }
        put_u16(s, 0);
    }
    return s;
}

// ---- comparing meshes ------------------------------------------------------------

using Point = std::array<double, 3>;
using CornerTriple = std::array<Point, 3>;

// The same triangle whichever corner it starts at (the winding is kept).
CornerTriple canonical(CornerTriple t) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
}

std::multiset<CornerTriple> triangles_of(const MeshData& m) {
    std::multiset<CornerTriple> out;
    for (const auto& t : m.triangles) {
        CornerTriple tri;
        for (int k = 0; k < 3; ++k) {
            const dvec3& p = m.positions.at(t[k]);
            tri[k] = {p.x, p.y, p.z};
        }
        out.insert(canonical(tri));
    }
    return out;
}

std::multiset<CornerTriple> cube_triangles() {
    std::multiset<CornerTriple> out;
    for (const auto& t : kCubeTriangles) {
        CornerTriple tri;
        for (int k = 0; k < 3; ++k) {
            const auto c = corner(t[k]);
            tri[k] = {double(c[0]), double(c[1]), double(c[2])};
        }
        out.insert(canonical(tri));
    }
    return out;
}

void expect_cube(const MeshData& m) {
    EXPECT_EQ(m.positions.size(), 8u);
    EXPECT_EQ(m.triangles.size(), 12u);
    EXPECT_EQ(m.degenerate_dropped, 0u);
    EXPECT_EQ(triangles_of(m), cube_triangles());
}

// The formatted error of loading `path`, the path shown as FILE.
std::string mesh_error(const std::string& path, std::size_t max_triangles = kMaxMeshTriangles) {
    return test::check_error(path, [&](const std::string& p) { load_mesh(p, max_triangles); });
}

std::string mesh_error(const std::string& name, const std::string& content) {
    return mesh_error(write_temp_file(name, content));
}

// ---- reading ---------------------------------------------------------------------

TEST(MeshLoader, SameCubeInEveryFormat) {
    const std::vector<std::pair<std::string, std::string>> files = {
        {"cube.obj", cube_obj()},
        {"cube_ascii.ply", cube_ply_ascii()},
        {"cube_binary.ply", cube_ply_binary()},
        {"cube_ascii.stl", cube_stl_ascii()},
        {"cube_binary.stl", cube_stl_binary()},
        {"cube.off", cube_off()},
    };
    for (const auto& [name, content] : files) {
        SCOPED_TRACE(name);
        const MeshData m = load_mesh(write_temp_file(name, content));
        expect_cube(m);
        // None has vertex normals: STL's are per facet (and JoinIdenticalVertices
        // would keep the corners of differently facing facets apart by them: 24
        // vertices, not 8).
        EXPECT_TRUE(m.normals.empty());
    }
}

TEST(MeshLoader, VertexNormalsFromTheFile) {
    const std::vector<std::pair<std::string, std::string>> files = {
        {"normals.obj", cube_obj(true)}, {"normals.ply", cube_ply_ascii(true)}, {"normals.off", cube_off(true)}};
    for (const auto& [name, content] : files) {
        SCOPED_TRACE(name);
        const MeshData m = load_mesh(write_temp_file(name, content));
        expect_cube(m);
        ASSERT_EQ(m.normals.size(), m.positions.size());
        for (std::size_t i = 0; i < m.positions.size(); ++i)
            EXPECT_EQ(m.normals[i], 2.0 * m.positions[i] - dvec3(1)) << "vertex " << i;
    }
}

TEST(MeshLoader, ExtensionInAnyCase) {
    expect_cube(load_mesh(write_temp_file("CUBE.OBJ", cube_obj())));
    expect_cube(load_mesh(write_temp_file("cube.Ply", cube_ply_binary())));
}

TEST(MeshLoader, PolygonsAreTriangulated) {
    for (const auto& [name, content] :
         std::vector<std::pair<std::string, std::string>>{
             {"quad.obj", "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nf 1 2 3 4\n"},
             {"quad.off", "OFF\n4 1 0\n0 0 0\n2 0 0\n2 1 0\n0 1 0\n4 0 1 2 3\n"}}) {
        SCOPED_TRACE(name);
        const MeshData m = load_mesh(write_temp_file(name, content));
        ASSERT_EQ(m.triangles.size(), 2u);
        EXPECT_EQ(m.positions.size(), 4u);
        double area = 0;  // the two halves of the 2 x 1 rectangle, both facing +z
        for (const auto& t : m.triangles) {
            const dvec3 c = glm::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
            EXPECT_GT(c.z, 0);
            area += c.z / 2;
        }
        EXPECT_EQ(area, 2);
    }
}

TEST(MeshLoader, ObjectsAndMaterialsMakeOneMeshWithSharedVertices) {
    // assimp makes a mesh per object and material (two here, of 8 vertices
    // each); a corner shared by both is still one vertex.
    std::string s;
    for (int i = 0; i < 8; ++i) s.append("v ").append(xyz(corner(i))).append("\n");
    for (std::size_t f = 0; f < kCubeTriangles.size(); ++f) {
        if (f == 0) s += "o left\nusemtl red\n";
        if (f == 6) s += "o right\nusemtl blue\n";
        s += "f";
        for (int i : kCubeTriangles[f]) s.append(" ").append(std::to_string(i + 1));
        s += "\n";
    }
    expect_cube(load_mesh(write_temp_file("two_objects.obj", s)));
}

TEST(MeshLoader, ObjMaterialLibrariesAreNotOpened) {
    // An OBJ's `mtllib` names any path; assimp used to open it and parse it
    // as a material library. Naming the folder itself failed the load with
    // "file read error"; an absolute path had that file read; a name ending
    // in "://" crashed it: assimp "cleans up" a path it cannot open, and
    // that walk ran past the name's end. None is opened now: the materials
    // come from the scene.
    for (const std::string library : {".", "/proc/self/status", "missing.mtl", "a://", "b/a://"}) {
        SCOPED_TRACE(library);
        expect_cube(load_mesh(write_temp_file("mtllib.obj", "mtllib " + library + "\n" + cube_obj())));
    }
}

TEST(MeshLoader, PointsAndLinesAreLeftOut) {
    expect_cube(load_mesh(write_temp_file("with_lines.obj", cube_obj() + "l 1 2 3\np 4\n")));
}

TEST(MeshLoader, CoordinatesAreAssimpsFloats) {
    // Debian's assimp reads every coordinate as a 32-bit float, even a PLY
    // double: 0.1 comes out as 0.1f.
    const MeshData m = load_mesh(write_temp_file(
        "double.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n0.1 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
    ASSERT_EQ(m.triangles.size(), 1u);
    EXPECT_EQ(m.positions[m.triangles[0][0]], dvec3(double(0.1f), 0, 0));
    EXPECT_NE(double(0.1f), 0.1);
}

TEST(MeshLoader, DegenerateTrianglesAreDroppedAndCounted) {
    const MeshData m = load_mesh(write_temp_file("degenerate.obj",
                                                 "v 0 0 0\n"
                                                 "v 1 0 0\n"
                                                 "v 0 1 0\n"
                                                 "v 2 0 0\n"     // on the line through 1 and 2
                                                 "v 0 0 0\n"     // where 1 is: joined with it
                                                 "f 1 2 3\n"     // kept
                                                 "f 1 2 4\n"     // collinear
                                                 "f 1 1 3\n"     // a repeated index
                                                 "f 5 2 1\n"     // 5 and 1 the same vertex once joined
                                                 "f 1 3 2\n"));  // kept (the other side)
    EXPECT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.degenerate_dropped, 3u);
    // Vertex 4 was used only by a dropped triangle.
    EXPECT_EQ(m.positions.size(), 3u);
    const std::multiset<CornerTriple> expected = {canonical({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}),
                                              canonical({{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}})};
    EXPECT_EQ(triangles_of(m), expected);
}

TEST(MeshLoader, LimitOnTriangles) {
    static_assert(kMaxMeshTriangles == 5'000'000);
    const std::string path = write_temp_file("limit.obj", cube_obj());
    EXPECT_EQ(mesh_error(path, 11), "FILE: error: 12 triangles is more than the limit of 11");
    EXPECT_EQ(load_mesh(path, 12).triangles.size(), 12u);
    // A polygon counts as the triangles it becomes.
    EXPECT_EQ(mesh_error(write_temp_file("limit_quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"), 1),
              "FILE: error: 2 triangles is more than the limit of 1");
}

// The cube as OFF with an index out of range, which assimp only logs.
std::string off_with_bad_index() {
    std::string off = cube_off();
    off.replace(off.find("3 0 1 3\n"), 8, "3 0 1 8\n");
    return off;
}

TEST(MeshLoader, NothingIsPrinted) {
    const std::string bad_off = write_temp_file("quiet.off", off_with_bad_index());
    const std::string bad_ply = write_temp_file("quiet.ply", cube_ply_binary().substr(0, kPlyBinaryHeader + 100));
    const std::string good = write_temp_file("quiet.obj", cube_obj());
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    EXPECT_NE(mesh_error(bad_off), "(no error)");
    EXPECT_NE(mesh_error(bad_ply), "(no error)");
    EXPECT_EQ(mesh_error(good), "(no error)");
    const std::string out = testing::internal::GetCapturedStdout();
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(out, "");
    EXPECT_EQ(err, "");
}

TEST(MeshLoader, LoadsOnSeveralThreadsKeepTheirOwnMessages) {
    // What assimp logs goes to the load on the thread that logged it.
    const std::string bad = write_temp_file("threads_bad.off", off_with_bad_index());
    const std::string good = write_temp_file("threads_good.off", cube_off());
    int bad_failed = 0, good_loaded = 0;
    std::thread a([&] {
        for (int i = 0; i < 40; ++i)
            bad_failed += mesh_error(bad) == "FILE:11:7: error: a face has a vertex index out of range";
    });
    std::thread b([&] {
        for (int i = 0; i < 40; ++i) good_loaded += mesh_error(good) == "(no error)";
    });
    a.join();
    b.join();
    EXPECT_EQ(bad_failed, 40);
    EXPECT_EQ(good_loaded, 40);
}

// ---- bad files ---------------------------------------------------------------------

TEST(MeshLoaderErrors, MissingFileAndFolder) {
    EXPECT_EQ(mesh_error(test::temp_dir().string() + "/no_such.obj"), "FILE: error: cannot open mesh file: no such file");
    const std::filesystem::path folder = test::temp_dir() / "folder.obj";
    std::filesystem::create_directories(folder);
    EXPECT_EQ(mesh_error(folder.string()), "FILE: error: cannot open mesh file: is a folder");
}

TEST(MeshLoaderErrors, UnknownExtension) {
    EXPECT_EQ(mesh_error("cube.xyz", cube_obj()),
              "FILE: error: unknown mesh format '.xyz' (supported: .obj, .ply, .stl, .off)");
    EXPECT_EQ(mesh_error("cube", cube_obj()), "FILE: error: unknown mesh format '' (supported: .obj, .ply, .stl, .off)");
    // The extension decides, not the content.
    EXPECT_EQ(mesh_error("obj_text.ply", cube_obj()), "FILE: error: incorrect magic number (expected 'ply' or 'PLY')");
}

TEST(MeshLoaderErrors, TruncatedBinaryStl) {
    const std::string stl = cube_stl_binary();
    const std::string expected =
        "FILE: error: failed to determine STL storage representation: neither ASCII STL (starting 'solid') nor "
        "binary STL of 84 + 50 bytes per triangle (a truncated file?)";
    EXPECT_EQ(mesh_error("cut.stl", stl.substr(0, stl.size() - 10)), expected);
    // Cut in the header too: assimp tells binary from ASCII by the size.
    EXPECT_EQ(mesh_error("cut_header.stl", stl.substr(0, 50)), expected);
}

TEST(MeshLoaderErrors, TruncatedAsciiStl) {
    const std::string stl = cube_stl_ascii();
    // Cut between facets: assimp only warns, and keeps the facets before.
    EXPECT_EQ(mesh_error("no_end.stl", stl.substr(0, stl.find("endsolid"))),
              "FILE: error: the file ends before 'endsolid' (a truncated file?)");
}

TEST(MeshLoaderErrors, TruncatedBinaryPly) {
    const std::string ply = cube_ply_binary();
    // In the vertices: the header's counts need more bytes than there are.
    EXPECT_EQ(mesh_error("cut_vertices.ply", ply.substr(0, kPlyBinaryHeader + 60)),
              "FILE: error: the PLY header declares element vertex 8, element face 12 (at least 108 bytes of data) "
              "but only 60 bytes follow it: a truncated file?");
    // In the faces: past the end assimp would read the line ends its buffer
    // was filled with (meshes/ply_lists.h), so the list is refused first.
    EXPECT_EQ(mesh_error("cut_faces.ply", ply.substr(0, ply.size() - 7)),
              "FILE: error: a binary PLY list of 3 values at byte " + std::to_string(ply.size() - 12) +
                  ", but only 5 bytes follow (a corrupt or truncated file?)");
    // In the header: assimp 5.2.5 would loop forever.
    EXPECT_EQ(mesh_error("cut_header.ply", ply.substr(0, 60)),
              "FILE: error: the PLY header has no end_header line (a truncated file?)");
    // A header longer than the 1 MiB read is not called truncated.
    std::string long_header = ply.substr(0, ply.find("element"));
    for (int i = 0; i < 17; ++i) long_header += "comment " + std::string(65536 - 9, 'x') + "\n";
    EXPECT_EQ(mesh_error("long_header.ply", long_header + ply.substr(ply.find("element"))),
              "FILE: error: the PLY header has no end_header line in its first 1 MiB (firsthit reads headers up to "
              "1 MiB)");
}

// Element counts read as assimp reads them, so that none hides from the
// size check. Both files found by fuzz/mesh_fuzzer.cpp.
TEST(MeshLoaderErrors, PlyCountsReadAsAssimpReadsThem) {
    // An unreadable count ("many", 0 to assimp) once stopped the check, and
    // assimp would allocate 48 GB for the vertices.
    EXPECT_EQ(mesh_error("huge.ply",
                         "ply\nformat ascii 1.0\nelement vertex 4294967295\nproperty float x\nproperty float y\n"
                         "element face many\nproperty list uchar int vertex_indices\nend_header\n0 0\n1 0\n0 1\n3 0 1 2\n"),
              "FILE: error: the PLY header declares element vertex 4294967295, element face 0 (at least "
              "17179869179 bytes of data) but only 20 bytes follow it: a truncated file?");
    // A count glued to the next line by a control character: assimp reads
    // its leading digits, wrapped to 32 bits, and looped over them for
    // minutes. 42,949,672,954 mod 2^32 vertices of two ASCII values (x is
    // glued into the element's line), one face: 4,294,967,290 x 4 + 2 - 1.
    EXPECT_EQ(mesh_error("glued.ply",
                         "ply\nformat ascii 1.0\nelement vertex 42949672954\bproperty float x\nproperty float y\n"
                         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                         "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
              "FILE: error: the PLY header declares element vertex 4294967290, element face 1 (at least "
              "17179869161 bytes of data) but only 26 bytes follow it: a truncated file?");
}

TEST(MeshLoaderErrors, OffCountsRightAfterTheHeaderWord) {
    // Found by fuzz/mesh_fuzzer.cpp: assimp reads counts glued to "OFF"
    // (its leading digits, wrapped to 32 bits) and allocated 45 GB for them.
    const std::string off = "OFF" + std::string(46, '5') + "1 4\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    // 555...551 (47 digits) mod 2^32 = 3,817,748,703 vertices of 3
    // coordinates and 4 faces: 6 x 3,817,748,703 + 2 x 4 - 1 bytes at least;
    // after the "4", 1 + 26 bytes.
    EXPECT_EQ(mesh_error("glued.off", off),
              "FILE: error: the OFF header declares 3817748703 vertices and 4 faces (at least 22906492225 bytes) "
              "but only 27 bytes follow the counts: a truncated file?");
    // The header's other forms: a comment first, nOFF's dimension, no "OFF"
    // at all. 9 vertices of 3 coordinates and a face: 6 x 9 + 2 - 1 bytes
    // at least; of 2 (nOFF 2): 4 x 9 + 2 - 1. What follows the face count
    // is counted from it: " 0\n" and the lines.
    EXPECT_EQ(mesh_error("comment.off", "# made by hand\nOFF\n9 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
              "FILE: error: the OFF header declares 9 vertices and 1 face (at least 55 bytes) but only 29 bytes "
              "follow the counts: a truncated file?");
    EXPECT_EQ(mesh_error("dims.off", "nOFF 2\n9 1 0\n0 0\n1 0\n0 1\n3 0 1 2\n"),
              "FILE: error: the OFF header declares 9 vertices and 1 face (at least 37 bytes) but only 23 bytes "
              "follow the counts: a truncated file?");
    EXPECT_EQ(mesh_error("bare.off", "9 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
              "FILE: error: the OFF header declares 9 vertices and 1 face (at least 55 bytes) but only 29 bytes "
              "follow the counts: a truncated file?");
}

TEST(MeshLoaderErrors, PlyEndingOnEndHeader) {
    // Found by fuzz/mesh_fuzzer.cpp: after a line assimp 5.2.5 does not
    // know, a file ending on "end_header" kept it reading for ever.
    EXPECT_EQ(mesh_error("stray.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header"),
              "FILE: error: the PLY header's end_header line has no line end (a truncated file?)");
    EXPECT_EQ(mesh_error("glued.ply", "ply\nformat ascii 1.0\nelement$vertex 4\nend_header"),
              "FILE: error: the PLY header's end_header line has no line end (a truncated file?)");
}

TEST(MeshLoaderErrors, PlyListLongerThanItsLine) {
    // Found by fuzz/mesh_fuzzer.cpp: assimp 5.2.5 sizes a list by its length
    // before reading it (34 GB here); meshes/ply_lists.h says where.
    EXPECT_EQ(mesh_error("list.ply", ply_header("ascii", false, 3, 1) + "0 0 0\n1 0 0\n0 1 0\n4294967289 0 1 2\n"),
              "FILE:14:1: error: a PLY list of 4294967289 values, but only 6 bytes follow on its line (a corrupt "
              "file?)");
}

TEST(MeshLoaderErrors, TruncatedOff) {
    const std::string off = cube_off();
    // assimp only logs it, and keeps faces without indices.
    EXPECT_EQ(mesh_error("cut_faces.off", off.substr(0, off.size() - 16)),
              "FILE: error: fewer faces than the header declares (a truncated file?)");
    EXPECT_EQ(mesh_error("cut_vertices.off", off.substr(0, 30)),
              "FILE: error: the OFF header declares 8 vertices and 12 faces (at least 71 bytes) but only 22 bytes "
              "follow the counts: a truncated file?");
}

TEST(MeshLoaderErrors, HeaderCountsFarBeyondTheFile) {
    // assimp 5.2.5 would allocate them all: 4.7 GB for such a 200-byte file.
    EXPECT_EQ(mesh_error("huge.ply", ply_header("ascii", false, 400000000, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
              "FILE: error: the PLY header declares element vertex 400000000, element face 1 (at least 2400000001 "
              "bytes of data) but only 26 bytes follow it: a truncated file?");
    EXPECT_EQ(mesh_error("huge.off", "OFF\n400000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
              "FILE: error: the OFF header declares 400000000 vertices and 1 face (at least 2400000001 bytes) but "
              "only 29 bytes follow the counts: a truncated file?");
}

TEST(MeshLoaderErrors, FaceIndexOutOfRange) {
    // assimp names no line: the file is scanned again for the first index
    // that names no vertex. The cube's OBJ: a comment, 8 `v`, 12 `f` lines.
    EXPECT_EQ(mesh_error("index.obj", cube_obj() + "f 1 2 9\n"),
              "FILE:22:7: error: a face has a vertex index out of range");
    // A relative index before the first vertex (-4 of 3), after a good one.
    EXPECT_EQ(mesh_error("relative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -3\nf 1 -1 -4\n"),
              "FILE:5:8: error: a face has a vertex index out of range");
    // assimp clamps it to the last vertex and only logs it. OFF: 2 header
    // lines, 8 vertex lines, then the faces; the first one is changed.
    EXPECT_EQ(mesh_error("index.off", off_with_bad_index()),
              "FILE:11:7: error: a face has a vertex index out of range");
    // A negative one, which assimp reads as 0 and says nothing of: alone or
    // among good faces.
    EXPECT_EQ(mesh_error("negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n"),
              "FILE:6:7: error: a face has a vertex index out of range");
    std::string negative = cube_off();
    negative.replace(negative.find("3 0 1 3\n"), 8, "3 0 -1 3\n");
    EXPECT_EQ(mesh_error("negative_cube.off", negative), "FILE:11:5: error: a face has a vertex index out of range");
    // Counts on the keyword's line, comments and blank lines between records.
    EXPECT_EQ(mesh_error("comments.off", "OFF 3 1 0 # counts\n# a comment\n0 0 0\n\n1 0 0\n0 1 0 # last\n3 0 1 3\n"),
              "FILE:7:7: error: a face has a vertex index out of range");
    // PLY: a 10-line header and 8 vertex lines, then face 0.
    std::string ply = cube_ply_ascii();
    ply.replace(ply.find("3 0 1 3\n"), 8, "3 0 1 8\n");
    EXPECT_EQ(mesh_error("index.ply", ply), "FILE:19:7: error: face 0 has a vertex index out of range");
    // A scalar property before the face's index list.
    std::string flagged = ply_header("ascii", false, 3, 1);
    flagged.replace(flagged.find("property list"), 0, "property uchar flags\n");
    EXPECT_EQ(mesh_error("flagged.ply", flagged + "0 0 0\n1 0 0\n0 1 0\n7 3 0 1 3\n"),
              "FILE:15:9: error: face 0 has a vertex index out of range");
}

TEST(MeshLoaderErrors, PlyFaceWithoutVertices) {
    // With a face of no indices assimp's Triangulate aborts the process.
    EXPECT_EQ(mesh_error("empty_face.ply", ply_header("ascii", false, 3, 2) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n0\n"),
              "FILE: error: face 1 has no vertices");
}

TEST(MeshLoaderErrors, BinaryPlyDataStartingWithLineFeed) {
    // x of the first vertex is 1.0000012f: bytes 0a 00 80 3f. assimp 5.2.5
    // skips the 0x0a and misreads the rest (assimp issue #5341).
    std::string ply = cube_ply_binary();
    ply.replace(kPlyBinaryHeader, 4, std::string("\x0a\x00\x80\x3f", 4));
    EXPECT_EQ(mesh_error("line_feed.ply", ply),
              "FILE: error: binary PLY data starting with byte 0x0a: assimp takes it for the header's line end and "
              "misreads everything after it (assimp issue #5341)");
}

TEST(MeshLoaderErrors, NonFiniteCoordinates) {
    // Checked before vertices are joined: assimp's JoinIdenticalVertices can
    // merge a NaN vertex into another one, and the NaN is gone.
    std::string ply = cube_ply_ascii();
    ply.replace(ply.find("1 1 1\n"), 6, "nan 1 1\n");
    // Where the vertex is: its line (a 10-line header, then vertex 7), and
    // the column of the number.
    EXPECT_EQ(mesh_error("nan.ply", ply), "FILE:18:1: error: vertex 7 has a non-finite coordinate: (nan, 1, 1)");
    std::string obj = cube_obj();
    obj.replace(obj.find("v 1 1 1\n"), 8, "v 1 nan 1\n");
    EXPECT_EQ(mesh_error("nan.obj", obj), "FILE:9:5: error: the vertex at (1, nan, 1) has a non-finite coordinate");
    obj = cube_obj();
    obj.replace(obj.find("v 1 1 1\n"), 8, "v 1 1 -inf\n");
    EXPECT_EQ(mesh_error("inf.obj", obj), "FILE:9:7: error: the vertex at (1, 1, -inf) has a non-finite coordinate");
    // OBJ names the vertex by its position, assimp's first in face order:
    // the line is that vertex's, not the first bad one's (line 2). 1e39 is
    // infinite as a float, which is how assimp reads it.
    EXPECT_EQ(mesh_error("two.obj", "v 0 0 0\nv 2 2 nan\nv 1 0 0\nv 0 1 1e39\nf 1 3 4\nf 1 2 3\n"),
              "FILE:4:7: error: the vertex at (0, 1, inf) has a non-finite coordinate");
    // An element after the vertices and faces changes nothing before it (a
    // 13-line header: vertex 2 on line 16).
    std::string edges = ply_header("ascii", false, 3, 1);
    edges.replace(edges.find("end_header"), 0, "element edge 1\nproperty int a\nproperty int b\n");
    EXPECT_EQ(mesh_error("edges.ply", edges + "0 0 0\n1 0 0\n0 nan 0\n3 0 1 2\n0 1\n"),
              "FILE:16:3: error: vertex 2 has a non-finite coordinate: (0, nan, 0)");
    EXPECT_EQ(mesh_error("nan.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                    "vertex 0 nan 0\nendloop\nendfacet\nendsolid t\n"),
              "FILE:6:10: error: a vertex of facet 0 has a non-finite coordinate: (0, nan, 0)");
    const auto c = corner(kCubeTriangles[3][0]);
    EXPECT_EQ(mesh_error("inf.stl", cube_stl_binary(std::numeric_limits<float>::infinity(), true)),
              "FILE: error: a vertex of facet 3 has a non-finite coordinate: (inf, " + std::to_string(c[1]) + ", " +
                  std::to_string(c[2]) + ")");
}

TEST(MeshLoader, NormalsOnlyWhenEveryVertexHasOne) {
    // A face without normals among faces with them: assimp gives its corners
    // zero normals. An object without them beside one with them. A zero normal.
    const std::string tetra = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 -1\n";
    for (const auto& [name, content] : std::vector<std::pair<std::string, std::string>>{
             {"face_without.obj", tetra + "f 1//1 3//1 2//1\nf 1 2 4\n"},
             {"object_without.obj", tetra + "o a\nf 1//1 3//1 2//1\no b\nf 1 2 4\n"},
             {"zero_normal.ply", [] {
                  std::string ply = cube_ply_ascii(true);
                  return ply.replace(ply.find("0 0 0 -1 -1 -1\n"), 15, "0 0 0 0 0 0\n");
              }()}}) {
        SCOPED_TRACE(name);
        const MeshData m = load_mesh(write_temp_file(name, content));
        EXPECT_FALSE(m.triangles.empty());
        EXPECT_TRUE(m.normals.empty());
    }
    // Given for every vertex: kept.
    EXPECT_EQ(load_mesh(write_temp_file("all_normals.obj", tetra + "f 1//1 3//1 2//1\n")).normals,
              std::vector<dvec3>(3, dvec3(0, 0, -1)));
}

// A PLY of one triangle whose vertices carry `type` red, green and blue
// properties with these values (three a vertex).
std::string colored_ply(const std::string& type, const std::string& colors) {
    std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
    for (const char* c : {"red", "green", "blue"}) ply.append("property ").append(type).append(" ").append(c).append("\n");
    ply += "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    std::istringstream values(colors);
    for (const char* p : {"0 0 0", "1 0 0", "0 1 0"}) {
        std::string r, g, b;
        values >> r >> g >> b;
        ply.append(p).append(" ").append(r).append(" ").append(g).append(" ").append(b).append("\n");
    }
    return ply + "3 0 1 2\n";
}

TEST(MeshLoader, VertexColoursWhenEveryVertexHasOne) {
    // OBJ's `v x y z r g b`, as written.
    MeshData m = load_mesh(write_temp_file("colored.obj", "v 0 0 0 1 0 0\nv 1 0 0 0 0.5 0\nv 0 1 0 0 0 0.25\nf 1 2 3\n"));
    EXPECT_EQ(m.colors, (std::vector<dvec3>{{1, 0, 0}, {0, 0.5, 0}, {0, 0, 0.25}}));
    // A PLY's bytes: n / 255.
    m = load_mesh(write_temp_file("colored_bytes.ply", colored_ply("uchar", "255 0 51  0 255 0  102 102 102")));
    ASSERT_EQ(m.colors.size(), 3u);
    auto expect_near = [](const dvec3& got, const dvec3& want) {
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-7);  // assimp divides in float
    };
    expect_near(m.colors[0], {1, 0, 51 / 255.0});
    expect_near(m.colors[2], dvec3(102 / 255.0));
    // Its floats as they are, clamped into [0, 1].
    m = load_mesh(write_temp_file("colored_floats.ply", colored_ply("float", "2 -1 0.5  0 1 0  0 0 1")));
    ASSERT_EQ(m.colors.size(), 3u);
    EXPECT_EQ(m.colors[0], dvec3(1, 0, 0.5));
    // One position in two colours is two vertices, each with its colour.
    m = load_mesh(write_temp_file("two_colors.obj", "v 0 0 0 1 0 0\nv 1 0 0 1 0 0\nv 0 1 0 1 0 0\n"
                                                      "v 0 0 0 0 1 0\nv 0 0 1 0 1 0\nf 1 2 3\nf 4 3 5\n"));
    ASSERT_EQ(m.positions.size(), 5u);
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.colors[m.triangles[0][0]], dvec3(1, 0, 0));
    EXPECT_EQ(m.colors[m.triangles[1][0]], dvec3(0, 1, 0));
    // None: no colours.
    EXPECT_TRUE(load_mesh(write_temp_file("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")).colors.empty());
}

TEST(MeshLoader, VertexColoursNotDrawnWhereAssimpWouldMisreadThem) {
    // An OBJ colouring some vertices only: assimp would give the first
    // colour to the first vertex, whichever line it was on.
    EXPECT_TRUE(load_mesh(write_temp_file("some_colored.obj", "v 0 0 0\nv 1 0 0 1 0 0\nv 0 1 0\nf 1 2 3\n"))
                    .colors.empty());
    // A PLY's int colours (assimp: n / 255 + 0.5), or alpha alone.
    EXPECT_TRUE(load_mesh(write_temp_file("int_colors.ply", colored_ply("int", "255 0 0  0 255 0  0 0 255")))
                    .colors.empty());
    std::string alpha_only = colored_ply("uchar", "1 2 3  4 5 6  7 8 9");
    alpha_only.replace(alpha_only.find("property uchar red\nproperty uchar green\nproperty uchar blue"), 59,
                       "property uchar alpha\nproperty uchar a1\nproperty uchar a2");
    const MeshData a = load_mesh(write_temp_file("alpha_only.ply", alpha_only));
    EXPECT_EQ(a.triangles.size(), 1u);
    EXPECT_TRUE(a.colors.empty());
    // An OFF's (COFF) colours, often 0-255 integers, which assimp takes as they are.
    const MeshData off = load_mesh(write_temp_file("colored.off", "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n"
                                                                  "0 1 0 0 0 255 255\n3 0 1 2\n"));
    EXPECT_EQ(off.triangles.size(), 1u);
    EXPECT_TRUE(off.colors.empty());
}

TEST(MeshLoaderErrors, NonFiniteVertexColour) {
    // The vertex named as its coordinates are, the number by line and column.
    EXPECT_EQ(mesh_error("nan_color.ply", colored_ply("float", "0 0 0  nan 1 0  0 0 1")),
              "FILE:14:7: error: vertex 1 has a non-finite colour: (nan, 1, 0)");
    EXPECT_EQ(mesh_error("inf_color.obj", "v 0 0 0 1 0 0\nv 1 0 0 0 inf 0\nv 0 1 0 0 0 1\nf 1 2 3\n"),
              "FILE:2:11: error: the vertex at (1, 0, 0) has a non-finite colour: (0, inf, 0)");
}

TEST(MeshLoaderErrors, NonFiniteNormals) {
    std::string ply = cube_ply_ascii(true);
    ply.replace(ply.find("0 0 0 -1 -1 -1\n"), 15, "0 0 0 nan -1 -1\n");
    EXPECT_EQ(mesh_error("nan_normal.ply", ply), "FILE:14:7: error: vertex 0 has a non-finite normal: (nan, -1, -1)");
    EXPECT_EQ(mesh_error("inf_normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 inf 1\nf 1//1 2//1 3//1\n"),
              "FILE:4:6: error: the vertex at (0, 0, 0) has a non-finite normal: (0, inf, 1)");
}

TEST(MeshLoaderErrors, NoTriangles) {
    EXPECT_EQ(mesh_error("vertices_only.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"), "FILE: error: no triangles");
    EXPECT_EQ(mesh_error("lines_only.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\n"),
              "FILE: error: no triangles, only points and lines");
    std::string stl(80, ' ');
    put_u32(stl, 0);
    EXPECT_EQ(mesh_error("no_facets.stl", stl), "FILE: error: no triangles");
    EXPECT_EQ(mesh_error("all_degenerate.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 1 4\n"),
              "FILE: error: no triangles: 2 triangles, all of zero area");
}

TEST(MeshLoaderErrors, AssimpMessagesCleaned) {
    const std::string path = "/meshes/a b.stl";
    auto text = [&](const std::string& m) { return clean_assimp_message(m, path).text; };
    EXPECT_EQ(text("Validation failed: aiMesh::mFaces[3]::mIndices[1] is out of range"),
              "face 3 has a vertex index out of range");
    EXPECT_EQ(text("Failed to open STL file /meshes/a b.stl."), "failed to open STL file");
    EXPECT_EQ(text("File /meshes/a b.stl is empty."), "file is empty");
    EXPECT_EQ(text("OBJ: vertex index out of range"), "a face has a vertex index out of range");
    EXPECT_EQ(text("OBJ-file is too small."), "OBJ-file is too small");
    EXPECT_EQ(text("STL: two\nlines\r\n  and\tspaces "), "two lines and spaces");
    EXPECT_EQ(text(""), "assimp cannot read the file (no reason given)");
    // A line number, where assimp gives one, becomes the error's line.
    const MeshMessage m = clean_assimp_message("OBJ: bad token at line 12 (after 'f')", path);
    EXPECT_EQ(m.line, 12);
    EXPECT_EQ(m.text, "bad token at line 12 (after 'f')");
    EXPECT_EQ(clean_assimp_message("an outline 5 away", path).line, 0);
    EXPECT_EQ(clean_assimp_message("no number", path).line, 0);
}

}  // namespace
}  // namespace fh
