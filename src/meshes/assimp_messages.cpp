#include "meshes/assimp_messages.h"

#include <assimp/DefaultLogger.hpp>
#include <assimp/Logger.hpp>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <iterator>
#include <mutex>

#include "meshes/mesh_text.h"

namespace fh {

using mesh_text::contains;
using mesh_text::starts_with;

namespace {

// The messages of the load running on this thread, or null.
thread_local std::vector<std::string>* t_messages = nullptr;

// Prints nothing; keeps warnings and errors for the load on this thread.
class CollectingLogger final : public Assimp::Logger {
public:
    CollectingLogger() : Assimp::Logger(Assimp::Logger::NORMAL) {}
    bool attachStream(Assimp::LogStream*, unsigned int) override { return false; }
    bool detachStream(Assimp::LogStream*, unsigned int) override { return false; }

private:
    void OnDebug(const char*) override {}
    void OnVerboseDebug(const char*) override {}
    void OnInfo(const char*) override {}
    void OnWarn(const char* message) override { keep(message); }
    void OnError(const char* message) override { keep(message); }
    static void keep(const char* message) noexcept {
        if (t_messages == nullptr) return;
        try {
            t_messages->emplace_back(message);
        } catch (...) {
            // Out of memory: the load fails on its own.
        }
    }
};

}  // namespace

AssimpMessages::AssimpMessages() {
    static std::once_flag installed;
    std::call_once(installed, [] { Assimp::DefaultLogger::set(new CollectingLogger); });
    t_messages = &messages_;
}

AssimpMessages::~AssimpMessages() { t_messages = nullptr; }

// assimp 5.2.5's messages, while reading these four formats, that leave the
// geometry as the file has it: materials (ours come from the scene file),
// the validator's warnings (unreferenced vertices, texture coordinates), an
// OBJ `f` line with no vertices (skipped), a polygon that is not simple
// (triangulated as a fan instead), texture coordinates declared 3-D that are
// 2-D (we read none: assimp-testmodels' OBJ/regr01.obj), an STL solid with
// no facets beside others (a file of none still fails: "no triangles").
// Any other message fails the load.
bool harmless_assimp_message(const std::string& m) {
    static const char* const prefixes[] = {
        "Validation warning:",
        "OBJ: failed to locate material",
        "OBJ: no name for material library specified",
        "OBJ: Unable to locate material file",
        "OBJ: Unable to locate fallback material file",
        "OBJ: Unsupported material requested",
        "OBJ: unexpected illumination model",
        "OBJ/MTL:",
        "OBJ: No object detected to attach a new mesh instance",
        "Obj: Ignoring empty face",
        "Failed to triangulate polygon (no ear found)",
        "STL: mesh is empty or invalid; no data loaded",  // an empty solid beside others
    };
    // (assimp puts its own prefix before this one.)
    if (contains(m, "UVs are declared to be 3D but they're obviously not")) return true;
    return std::any_of(std::begin(prefixes), std::end(prefixes), [&](const char* p) { return starts_with(m, p); });
}

MeshMessage clean_assimp_message(const std::string& message, const std::string& path) {
    // One line, single spaces.
    std::string s;
    for (char c : message) {
        const bool space = static_cast<unsigned char>(c) < 0x20 || c == ' ' || c == 0x7f;
        if (!space)
            s += c;
        else if (!s.empty() && s.back() != ' ')
            s += ' ';
    }
    while (!s.empty() && s.back() == ' ') s.pop_back();
    // The error names the file already.
    if (!path.empty()) {
        for (const std::string& p : {" for " + path, " \"" + path + "\"", " " + path}) {
            for (std::size_t at = s.find(p); at != std::string::npos; at = s.find(p)) s.erase(at, p.size());
        }
    }
    static const char* const prefixes[] = {"Validation failed: ", "std::exception: ", "Invalid .ply file: ",
                                           "OBJ: ", "Obj: ", "OFF: ", "STL: ", "PLY: "};
    for (bool stripped = true; stripped;) {
        stripped = false;
        for (const char* p : prefixes) {
            if (starts_with(s, p)) {
                s.erase(0, std::strlen(p));
                stripped = true;
            }
        }
    }
    while (!s.empty() && (s.back() == '.' || s.back() == ' ')) s.pop_back();

    // What the messages mean, said in our words where assimp's mislead.
    if (starts_with(s, "aiMesh::mFaces[")) {
        const std::size_t close = s.find(']');
        const std::string face = s.substr(15, close == std::string::npos ? 0 : close - 15);
        if (contains(s, "is out of range"))
            s = "face " + face + " has a vertex index out of range";
        else if (contains(s, "is a POINT"))  // an OBJ `f` line of one vertex
            s = "face " + face + " has only one vertex";
        else if (contains(s, "is a LINE"))
            s = "face " + face + " has only two vertices";
        else if (contains(s, "mIndices is nullptr") || contains(s, "mNumIndices is 0"))
            s = "face " + face + " has no vertices";
    } else if (s == "vertex index out of range" || s == "Vertex index is out of range") {
        s = "a face has a vertex index out of range";
    } else if (s == "The number of verts in the header is incorrect") {
        s = "fewer vertices than the header declares (a truncated file?)";
    } else if (s == "The number of faces in the header is incorrect") {
        s = "fewer faces than the header declares (a truncated file?)";
    } else if (s == "Faces with zero indices aren't allowed") {
        s = "a face with no vertices, or with more than 9 (the most assimp's OFF reader takes)";
    } else if (s == "unexpected EOF. 'endsolid' keyword was expected") {
        s = "the file ends before 'endsolid' (a truncated file?)";
    } else if (starts_with(s, "Unable to parse property instance") ||
               starts_with(s, "Unable to parse binary property instance")) {
        s = "a value in the data cannot be read (a truncated or corrupt file?)";
    } else if (starts_with(s, "Failed to determine STL storage representation")) {
        s += ": neither ASCII STL (starting 'solid') nor binary STL of 84 + 50 bytes per triangle (a truncated file?)";
    } else if (contains(s, "contains no faces") || contains(s, "contains no vertices") ||
               contains(s, "mNumMeshes is 0") || contains(s, "There are no valid") ||
               contains(s, "There are no facets defined") || s == "no vertices") {
        s = "no triangles";
    }
    if (s.empty()) s = "assimp cannot read the file (no reason given)";
    // "Failed to ..." but not "OBJ-file ...".
    if (s.size() > 1 && std::isupper(static_cast<unsigned char>(s[0])) &&
        std::islower(static_cast<unsigned char>(s[1])))
        s[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(s[0])));

    MeshMessage out;
    out.text = s;
    // "line N", as a word.
    for (std::size_t at = s.find("line "); at != std::string::npos; at = s.find("line ", at + 1)) {
        if (at > 0 && std::isalnum(static_cast<unsigned char>(s[at - 1]))) continue;
        int line = 0;
        const char* begin = s.data() + at + 5;
        const auto [ptr, ec] = std::from_chars(begin, s.data() + s.size(), line);
        if (ec == std::errc() && ptr != begin && line > 0) {
            out.line = line;
            break;
        }
    }
    return out;
}

}  // namespace fh
