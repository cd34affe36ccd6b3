// Mesh files through assimp (Debian 12: libassimp 5.2.5), made strict. assimp
// reads; this file checks what it read and what it only logged, and works
// around what 5.2.5 gets wrong on bad input, each seen on this machine:
//   - it reports some problems only to its log, which is off by default: an
//     OFF face index out of range (clamped to the last vertex), a file that
//     ends early (OFF, ASCII STL), a PLY value it cannot parse (read as 0). We
//     install a logger that prints nothing and collects them per thread; any
//     message not known to be harmless fails the load (meshes/assimp_messages.h).
//   - an OFF index "-1" it reads as 0 and reports nowhere: the face comes out
//     degenerate, so an OFF file with degenerate faces is read again for it.
//   - it names no line for what it read wrong (a NaN, a clamped index): the
//     file is read again for that vertex or face (meshes/mesh_records.h).
//   - JoinIdenticalVertices takes any vertex with a NaN coordinate for equal to
//     another vertex it shares a hash bucket with, so the NaN can vanish:
//     coordinates are checked before joining (the file is read, checked, then
//     post-processed).
//   - its PLY reader loops forever on a header without end_header, and it and
//     the OFF reader allocate whatever count the header declares (400 million
//     vertices in a 200-byte PLY: 4.7 GB): their headers' counts are checked
//     against the file's size first, read as assimp reads them -- leading
//     digits wrapped to 32 bits, "OFF" glued to the counts, a UTF-8 byte
//     order mark dropped -- so that no garbled header hides a count it will
//     use (src/meshes/mesh_file_headers.cpp, off_lines.cpp; upstream has
//     since fixed the loop and the OFF allocation).
//   - its OFF reader writes one byte past its line buffer for a line of 4,096
//     bytes, and reads past its face array after a face line of no vertices
//     or more than 9; OFF and STL text it reads past the file's end when it
//     starts with what it takes for a UTF-32 byte order mark: the OFF file is
//     read first as assimp will (meshes/off_lines.h), the STL's start checked.
//   - a PLY face with no indices (a file cut short after its header) makes
//     Triangulate abort the process on an assertion (assimp issue #5684): such
//     faces are refused before triangulating.
//   - binary PLY data whose first byte is 0x0a loses that byte (assimp issue
//     #5341): refused with that reason rather than misread.
//   - its PLY reader sizes each list by the length it reads before reading
//     the list (34 GB for one length in a 200-byte file; 1.3 GB for a binary
//     file cut short, whose end it reads as the 0x0a bytes its buffer was
//     filled with): the data is walked first as assimp will read it, and a
//     list longer than what follows it is refused (src/meshes/ply_lists.h).
//   - a second PLY vertex element (or face element) writes past the arrays the
//     first sized (heap corruption), and a face element of texture
//     coordinates without vertex indices is read through a null pointer:
//     refused by the same walk.
//   - a binary PLY header that ends on the last byte of its 1 MiB line buffer
//     leaves its binary reader an empty block, read through a null pointer (a
//     crash): refused by the same walk.
//   - its OBJ importer writes past its vertex array for a line statement of
//     one vertex (heap corruption; fixed in 5.3.0), reads past its line
//     buffer for a vertical tab or a vertex of four indices in a face, line
//     or point statement, and past its 16 MiB cache for a "\" before a line
//     end at a block's end: refused first (src/meshes/obj_lines.h).
//   - a PLY face of 6 to 8 texture coordinates has them read through the
//     vertex index of each two, past the indices of a triangle; a line of
//     1 MiB - 1 bytes fills its line buffer, and the parser reads past it;
//     past the data's end it reads the last line again for each instance the
//     header still declares (n^2 values from a list of n): refused by the
//     PLY walk.
//   - an OBJ file's `mtllib` makes it open any path the file names (an
//     absolute one, a folder, /dev/..., the other mesh files beside it) and
//     parse it as a material library, a second parser on bytes nobody meant
//     for it: assimp opens only the mesh file itself (OnlyThisFile), any
//     other path as an empty file -- a path it could not open, it would
//     "clean up", reading past the end of a name that ends in "://" (a
//     crash). The materials come from the scene; a mesh never reads other
//     files.
#include "meshes/mesh_loader.h"

#include <assimp/DefaultIOSystem.h>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <new>
#include <sstream>
#include <unordered_map>
#include <utility>

#include <glm/common.hpp>

#include "files/file_names.h"
#include "files/input_files.h"
#include "text/input_error.h"
#include "meshes/assimp_messages.h"
#include "meshes/mesh_file_headers.h"
#include "meshes/obj_lines.h"
#include "meshes/off_lines.h"
#include "meshes/ply_lists.h"
#include "meshes/mesh_records.h"
#include "meshes/mesh_text.h"

namespace fh {

namespace {

namespace fs = std::filesystem;
using mesh_text::contains;
using mesh_text::lowercase;
using mesh_text::plural;
using mesh_text::starts_with;

using Format = MeshFormat;

// assimp's file access, limited to the one file being loaded.
class OnlyThisFile final : public Assimp::DefaultIOSystem {
public:
    explicit OnlyThisFile(std::string path) : path_(std::move(path)) {}
    using DefaultIOSystem::Exists;
    using DefaultIOSystem::Open;
    bool Exists(const char* file) const override { return path_ == file && DefaultIOSystem::Exists(file); }
    // Any other path opens as an empty file. Refusing it (nullptr) would
    // send assimp's FileSystemFilter on to "clean up" the name, which reads
    // past the end of one ending in "://" (a crash: `mtllib a://`).
    Assimp::IOStream* Open(const char* file, const char* mode) override {
        static const std::uint8_t kNothing = 0;
        return path_ == file ? DefaultIOSystem::Open(file, mode) : new Assimp::MemoryIOStream(&kNothing, 0);
    }

private:
    std::string path_;
};



// The file must exist, be a regular file and be readable; returns its size.
std::uintmax_t check_file(const std::string& path) {
    if (const std::string why = why_unreadable(path); !why.empty())
        throw InputError(path, "cannot open mesh file: " + why);
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) throw InputError(path, "cannot open mesh file: " + lowercase(ec.message()));
    note_input_file(path);
    return size;
}

Format format_of(const std::string& path) {
    const std::string ext = fs::path(path).extension().string();
    const std::string lower = lowercase_extension(path);
    if (lower == ".obj") return Format::obj;
    if (lower == ".ply") return Format::ply;
    if (lower == ".stl") return Format::stl;
    if (lower == ".off") return Format::off;
    throw InputError(path, "unknown mesh format '" + ext + "' (supported: .obj, .ply, .stl, .off)");
}

// ---- messages ----------------------------------------------------------------

std::string number(float v) {
    char buf[32];
    const auto result = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, result.ptr);
}

std::string triple(const aiVector3D& v) { return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")"; }

[[noreturn]] void fail(const std::string& path, Format format, const std::string& assimp_message, bool binary_ply) {
    MeshMessage m = clean_assimp_message(assimp_message, path);
    if (binary_ply && contains(m.text, "out of range")) m.text += " (truncated or corrupt binary data?)";
    if (m.line == 0 && contains(m.text, "vertex index out of range")) {
        const TextPosition at = bad_face_index_position(path, format);
        throw InputError(path, at.line, at.column, m.text);
    }
    throw InputError(path, m.line, 0, m.text);
}

// A failed read, or one assimp logged a problem with: InputError.
void check_result(const std::string& path, Format format, const AssimpMessages& log, const aiScene* scene,
                  const Assimp::Importer& importer, bool binary_ply) {
    for (const std::string& m : log.messages())
        if (!harmless_assimp_message(m)) fail(path, format, m, binary_ply);
    if (scene == nullptr) fail(path, format, importer.GetErrorString(), binary_ply);
}

bool finite(const aiVector3D& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// How a message names vertex `v` of a mesh as read, before joining: by its
// index where the file numbers its vertices (PLY, OFF: from 0), by its facet
// (STL, from 0, `first_facet` being the facets of the solids before), else
// (OBJ: assimp gives a vertex per face corner) by its position.
std::string vertex_name(Format format, const aiMesh& mesh, unsigned v, std::size_t first_facet) {
    switch (format) {
        case Format::ply:
        case Format::off: return "vertex " + std::to_string(v);
        case Format::stl: return "a vertex of facet " + std::to_string(first_facet + v / 3);
        case Format::obj: break;
    }
    return "the vertex at " + triple(mesh.mVertices[v]);
}

std::array<float, 3> floats(const aiVector3D& v) { return {v.x, v.y, v.z}; }

// Where vertex `v` of a mesh as read is in a text file (vertex_name's vertex):
// the first non-finite number of its `part` (OBJ: a normal in the `vn`
// record of that normal, a colour in the `v` record at its position).
TextPosition nonfinite_position(const std::string& path, Format format, const aiMesh& mesh, unsigned v,
                                std::size_t first_facet, VertexPart part) {
    if (format == Format::obj) {
        const std::array<float, 3> p = floats(part == VertexPart::normal ? mesh.mNormals[v] : mesh.mVertices[v]);
        return nonfinite_vertex_position(path, format, part, -1, &p);
    }
    const long long record = format == Format::stl ? 3 * static_cast<long long>(first_facet) + v : v;
    return nonfinite_vertex_position(path, format, part, record);
}

// The file as read, before post-processing: faces with vertices, finite
// coordinates and normals, not too many triangles. Returns whether every
// vertex a face uses has a normal (a non-zero one: assimp gives the corners of
// an OBJ face that names no normals zero ones when other faces name some).
bool check_read(const std::string& path, Format format, const aiScene& scene, std::size_t max_triangles) {
    std::uint64_t triangles = 0;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh& mesh = *scene.mMeshes[m];
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const unsigned n = mesh.mFaces[f].mNumIndices;
            if (n == 0) throw InputError(path, "face " + std::to_string(f) + " has no vertices");
            if (n >= 3) triangles += n - 2;
        }
    }
    if (triangles > max_triangles)
        throw InputError(path, std::to_string(triangles) + " triangles is more than the limit of " +
                                   std::to_string(max_triangles));
    std::size_t first_facet = 0;
    bool all_normals = format != Format::stl;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh& mesh = *scene.mMeshes[m];
        all_normals = all_normals && mesh.HasNormals();
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            if (finite(mesh.mVertices[v])) continue;
            std::string what = vertex_name(format, mesh, v, first_facet) + " has a non-finite coordinate";
            if (format != Format::obj) what += ": " + triple(mesh.mVertices[v]);
            const TextPosition at = nonfinite_position(path, format, mesh, v, first_facet, VertexPart::coordinates);
            throw InputError(path, at.line, at.column, what);
        }
        if (mesh.HasNormals() && format != Format::stl) {
            for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
                const aiFace& face = mesh.mFaces[f];
                for (unsigned k = 0; k < face.mNumIndices; ++k) {
                    const aiVector3D& n = mesh.mNormals[face.mIndices[k]];
                    if (!finite(n)) {
                        std::string what = vertex_name(format, mesh, face.mIndices[k], first_facet);
                        const TextPosition at =
                            nonfinite_position(path, format, mesh, face.mIndices[k], first_facet, VertexPart::normal);
                        throw InputError(path, at.line, at.column,
                                         what.append(" has a non-finite normal: ").append(triple(n)));
                    }
                    if (n.x == 0 && n.y == 0 && n.z == 0) all_normals = false;
                }
            }
        }
        first_facet += mesh.mNumFaces;
    }
    return all_normals;
}

// Whether every mesh of the file has vertex colours (a PLY's red, green and
// blue, an OBJ's `v x y z r g b`): kept then, else dropped.
bool every_mesh_colored(const aiScene& scene) {
    if (scene.mNumMeshes == 0) return false;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m)
        if (!scene.mMeshes[m]->HasVertexColors(0)) return false;
    return true;
}

// Where colours are drawn: each vertex's colour finite, else one error
// naming the vertex and, in a text file, the number's line and column.
void check_colours(const std::string& path, Format format, const aiScene& scene) {
    std::size_t first_facet = 0;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh& mesh = *scene.mMeshes[m];
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiColor4D& c = mesh.mColors[0][v];
            if (std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b)) continue;
            const TextPosition at = nonfinite_position(path, format, mesh, v, first_facet, VertexPart::colour);
            throw InputError(path, at.line, at.column,
                             vertex_name(format, mesh, v, first_facet) + " has a non-finite colour: " +
                                 triple(aiVector3D(c.r, c.g, c.b)));
        }
        first_facet += mesh.mNumFaces;
    }
}

// A vertex as joined across the file's meshes: its position, its normal
// when normals are kept, its colour when colours are.
struct VertexKey {
    std::array<double, 9> v;
    bool operator==(const VertexKey& o) const { return v == o.v; }
};

struct VertexKeyHash {
    std::size_t operator()(const VertexKey& k) const {
        std::size_t h = 0;
        for (double x : k.v) h = h * 1000003u ^ std::hash<double>()(x);
        return h;
    }
};

// A vertex colour as the tracer takes it: each channel clamped into [0, 1]
// (a PLY's bytes come as n / 255; its floats, and an OBJ's numbers, as they are).
// Finite: check_colours has seen to that.
dvec3 vertex_color(const aiColor4D& c) { return glm::clamp(dvec3(c.r, c.g, c.b), 0.0, 1.0); }

// The post-processed scene as one mesh: vertices joined across meshes (assimp
// joins within each), triangles of zero area dropped, unused vertices gone;
// normals kept when `all_normals` (check_read), colours when `keep_colors`
// (every mesh has them, and the format's check says they are drawn).
MeshData collect(const std::string& path, const aiScene& scene, bool all_normals, bool keep_colors) {
    bool keep_normals = all_normals && scene.mNumMeshes > 0;
    std::size_t vertex_count = 0, face_count = 0;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        keep_normals = keep_normals && scene.mMeshes[m]->HasNormals();
        vertex_count += scene.mMeshes[m]->mNumVertices;
        face_count += scene.mMeshes[m]->mNumFaces;
    }
    // One mesh without colours: JoinIdenticalVertices has joined it already
    // (what it compares beyond the position and normal, RemoveComponent
    // took away). With colours it is not run: assimp 5.2.5's joins vertices
    // of different colours.
    const bool join = scene.mNumMeshes > 1 || keep_colors;
    std::unordered_map<VertexKey, std::uint32_t, VertexKeyHash> ids;
    if (join) ids.reserve(vertex_count);
    std::vector<dvec3> positions, normals, colors;
    positions.reserve(vertex_count);
    if (keep_normals) normals.reserve(vertex_count);
    if (keep_colors) colors.reserve(vertex_count);
    MeshData out;
    out.triangles.reserve(face_count);
    std::size_t points_and_lines = 0;
    std::vector<std::uint32_t> id;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh& mesh = *scene.mMeshes[m];
        id.assign(mesh.mNumVertices, 0);
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D& p = mesh.mVertices[v];
            const aiVector3D n = keep_normals ? mesh.mNormals[v] : aiVector3D(0, 0, 0);
            const dvec3 color = keep_colors ? vertex_color(mesh.mColors[0][v]) : dvec3(0);
            if (positions.size() >= std::numeric_limits<std::uint32_t>::max())
                throw InputError(path, "more than 2^32 - 1 vertices");
            const auto next = static_cast<std::uint32_t>(positions.size());
            if (join) {
                // + 0.0: -0 and 0 are one value.
                const VertexKey key{{p.x + 0.0, p.y + 0.0, p.z + 0.0, n.x + 0.0, n.y + 0.0, n.z + 0.0, color.r + 0.0,
                                     color.g + 0.0, color.b + 0.0}};
                const auto [it, added] = ids.try_emplace(key, next);
                id[v] = it->second;
                if (!added) continue;
            } else {
                id[v] = next;
            }
            positions.emplace_back(p.x, p.y, p.z);
            if (keep_normals) normals.emplace_back(n.x, n.y, n.z);
            if (keep_colors) colors.push_back(color);
        }
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3) {
                ++points_and_lines;
                continue;
            }
            const std::array<std::uint32_t, 3> t{id[face.mIndices[0]], id[face.mIndices[1]], id[face.mIndices[2]]};
            const dvec3 c = glm::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]);
            if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || (c.x == 0 && c.y == 0 && c.z == 0)) {
                ++out.degenerate_dropped;
                continue;
            }
            out.triangles.push_back(t);
        }
    }
    if (out.triangles.empty()) {
        std::string what = "no triangles";
        if (out.degenerate_dropped > 0)
            what += ": " + plural(out.degenerate_dropped, "triangle", "triangles") + ", all of zero area";
        else if (points_and_lines > 0)
            what += ", only points and lines";
        throw InputError(path, what);
    }
    // Vertices only points, lines or dropped triangles used.
    constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> renumber(positions.size(), kUnused);
    for (const auto& t : out.triangles)
        for (std::uint32_t i : t) renumber[i] = 0;
    std::uint32_t used = 0;
    for (std::uint32_t& r : renumber)
        if (r != kUnused) r = used++;
    if (used == positions.size()) {
        out.positions = std::move(positions);
        out.normals = std::move(normals);
        out.colors = std::move(colors);
        return out;
    }
    out.positions.resize(used);
    if (keep_normals) out.normals.resize(used);
    if (keep_colors) out.colors.resize(used);
    for (std::size_t i = 0; i < renumber.size(); ++i) {
        if (renumber[i] == kUnused) continue;
        out.positions[renumber[i]] = positions[i];
        if (keep_normals) out.normals[renumber[i]] = normals[i];
        if (keep_colors) out.colors[renumber[i]] = colors[i];
    }
    for (auto& t : out.triangles)
        for (std::uint32_t& i : t) i = renumber[i];
    return out;
}

}  // namespace

MeshData load_mesh(const std::string& path, std::size_t max_triangles) {
    const std::uintmax_t size = check_file(path);
    const Format format = format_of(path);
    bool binary_ply = false;
    // Whether the file's vertex colours may be drawn (OBJ and PLY: the
    // checks below say; OFF's and STL's are not: a COFF's are often 0-255
    // integers, which assimp takes as they are, and a binary STL's are
    // per facet, often junk in its attribute bytes).
    bool colors_drawn = false;
    if (format == Format::ply) {
        const PlyHeader header = check_ply_header(path, size);
        binary_ply = header.binary;
        colors_drawn = header.colors;
        check_ply_lists(path);
    }
    if (format == Format::off) check_off_file(path);
    if (format == Format::stl) check_stl_start(path, size);
    if (format == Format::obj) colors_drawn = check_obj_lines(path);
    try {
        AssimpMessages log;
        Assimp::Importer importer;
        importer.SetIOHandler(new OnlyThisFile(path));  // the importer owns it
        // Read and validated only, so coordinates are checked before
        // JoinIdenticalVertices can merge a NaN away. STL is not validated:
        // assimp makes its faces itself (always whole), and the validator
        // refuses a file for one empty solid among others.
        const unsigned validate = format == Format::stl ? 0u : unsigned(aiProcess_ValidateDataStructure);
        const aiScene* scene = importer.ReadFile(path, validate);
        check_result(path, format, log, scene, importer, binary_ply);
        const bool all_normals = check_read(path, format, *scene, max_triangles);
        // Vertices that differ only in what we do not keep are one vertex.
        // STL's normals are its facets', not its vertices'. Vertex colours
        // are kept where every mesh has them, and then joined by collect():
        // assimp 5.2.5's JoinIdenticalVertices joins vertices of different
        // colours.
        const bool colors = colors_drawn && every_mesh_colored(*scene);
        if (colors) check_colours(path, format, *scene);
        int drop = aiComponent_TEXCOORDS | aiComponent_TANGENTS_AND_BITANGENTS;
        if (!colors) drop |= aiComponent_COLORS;
        if (format == Format::stl) drop |= aiComponent_NORMALS;
        importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, drop);
        scene = importer.ApplyPostProcessing(aiProcess_RemoveComponent | aiProcess_Triangulate |
                                             (colors ? 0u : unsigned(aiProcess_JoinIdenticalVertices)));
        check_result(path, format, log, scene, importer, binary_ply);
        // assimp reads an OFF index "-1" as 0, silently: the face comes out
        // degenerate and is dropped. So where one was, the faces are read again.
        auto check_off_indices = [&] {
            if (format != Format::off) return;
            const TextPosition at = bad_face_index_position(path, format);
            if (at.line > 0) throw InputError(path, at.line, at.column, "a face has a vertex index out of range");
        };
        MeshData mesh;
        try {
            mesh = collect(path, *scene, all_normals, colors);
        } catch (const InputError&) {
            check_off_indices();  // "no triangles": all of them dropped
            throw;
        }
        if (mesh.degenerate_dropped > 0) check_off_indices();
        return mesh;
    } catch (const InputError&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw InputError(path, "out of memory reading the mesh");
    } catch (const std::exception& e) {
        fail(path, format, e.what(), binary_ply);
    }
}

}  // namespace fh
