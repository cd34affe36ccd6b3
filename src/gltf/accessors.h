// A glTF accessor's values, read with every bound checked: the accessor,
// its buffer view and buffer exist; its elements lie inside the view and
// the view inside the buffer; its stride holds an element; a sparse
// accessor's indices increase and stay inside it; float values are finite.
// Every component type glTF allows, normalized integers mapped as the
// specification says (e.g. a signed byte c to max(c / 127, -1)). Problems are
// InputError naming the file and the accessor.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gltf/gltf_model.h"

namespace fh {

class AccessorReader {
public:
    AccessorReader(const tinygltf::Model& model, std::string file) : model_(model), file_(std::move(file)) {}

    // Accessor `index` as count x components doubles, element by element.
    // components: what the caller needs (e.g. 3 for a VEC3), checked against
    // the accessor's type; what: its role in messages ("POSITION of mesh 2").
    std::vector<double> numbers(int index, int components, const std::string& what) const;

    // An index accessor (unsigned byte, short or int scalars), each < limit.
    std::vector<std::uint32_t> indices(int index, std::uint32_t limit, const std::string& what) const;

    // How many elements accessor `index` has (checked to exist).
    std::size_t count(int index, const std::string& what) const;
    // How many numbers it holds (count x components); 0 if it does not exist.
    std::size_t values(int index) const;

    [[noreturn]] void fail(const std::string& what) const;
    const std::string& file() const { return file_; }

private:
    const tinygltf::Accessor& accessor(int index, const std::string& what) const;
    // count x components values from a buffer view (dense part).
    void read_view(int view, std::size_t offset, std::size_t count, int components, int component_type,
                   bool normalized, std::vector<double>& out, const std::string& what) const;

    const tinygltf::Model& model_;
    mutable std::size_t values_read_ = 0;  // against kMaxGltfReadValues
    std::string file_;
};

}  // namespace fh
