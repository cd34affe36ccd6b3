// assimp's log and messages, made ours (meshes/mesh_loader.cpp): what assimp
// logs while a load runs, collected per thread and printed nowhere; which of
// its messages leave the geometry as the file has it; and any other as one
// clean line of an InputError.
#pragma once

#include <string>
#include <vector>

namespace fh {

// Collects assimp's warnings and errors on this thread while it lives. The
// logger is assimp's global one, set once and kept (assimp owns it); loads
// on other threads have their own lists.
class AssimpMessages {
public:
    AssimpMessages();
    ~AssimpMessages();
    AssimpMessages(const AssimpMessages&) = delete;
    AssimpMessages& operator=(const AssimpMessages&) = delete;
    const std::vector<std::string>& messages() const { return messages_; }

private:
    std::vector<std::string> messages_;
};

// Whether a message of assimp 5.2.5, reading OBJ, PLY, STL or OFF, leaves
// the geometry as the file has it (any other fails the load).
bool harmless_assimp_message(const std::string& message);

// One of assimp's error or warning texts as an InputError's message: one
// line, without assimp's prefixes ("Validation failed: ", "OBJ: ", ...) or
// the file's path (the error names the file), and where the text says
// "line N", that line.
struct MeshMessage {
    int line = 0;  // 0: not known
    std::string text;
};
MeshMessage clean_assimp_message(const std::string& message, const std::string& path);

}  // namespace fh
