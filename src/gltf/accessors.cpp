#include "gltf/accessors.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "text/input_error.h"

namespace fh {

namespace {

int components_of(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
    }
}

int bytes_of(int component_type) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return 8;
    default: return 0;
    }
}

template <typename V>
V load(const unsigned char* p) {
    V v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// One component, as the specification maps a normalized integer.
double component(const unsigned char* p, int type, bool normalized) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const double c = load<std::int8_t>(p);
        return normalized ? std::max(c / 127.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
        const double c = load<std::uint8_t>(p);
        return normalized ? c / 255.0 : c;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        const double c = load<std::int16_t>(p);
        return normalized ? std::max(c / 32767.0, -1.0) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        const double c = load<std::uint16_t>(p);
        return normalized ? c / 65535.0 : c;
    }
    case TINYGLTF_COMPONENT_TYPE_INT: return load<std::int32_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load<std::uint32_t>(p);
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
    default: return load<double>(p);
    }
}

}  // namespace

void AccessorReader::fail(const std::string& what) const { throw InputError(file_, what); }

const tinygltf::Accessor& AccessorReader::accessor(int index, const std::string& what) const {
    if (index < 0 || size_t(index) >= model_.accessors.size())
        fail(what + ": accessor " + std::to_string(index) + " does not exist (the file has " +
             std::to_string(model_.accessors.size()) + ")");
    return model_.accessors[size_t(index)];
}

std::size_t AccessorReader::count(int index, const std::string& what) const { return accessor(index, what).count; }

std::size_t AccessorReader::values(int index) const {
    if (index < 0 || size_t(index) >= model_.accessors.size()) return 0;
    const tinygltf::Accessor& a = model_.accessors[size_t(index)];
    // At most half of size_t's range: a sum with a small total cannot wrap.
    constexpr std::size_t most = std::numeric_limits<std::size_t>::max() / 32;
    return std::min(a.count, most) * std::size_t(std::max(components_of(a.type), 0));
}

void AccessorReader::read_view(int view, std::size_t offset, std::size_t count, int components, int component_type,
                               bool normalized, std::vector<double>& out, const std::string& what) const {
    if (view < 0 || size_t(view) >= model_.bufferViews.size())
        fail(what + ": buffer view " + std::to_string(view) + " does not exist");
    const tinygltf::BufferView& bv = model_.bufferViews[size_t(view)];
    if (bv.buffer < 0 || size_t(bv.buffer) >= model_.buffers.size())
        fail(what + ": buffer " + std::to_string(bv.buffer) + " does not exist");
    const std::vector<unsigned char>& data = model_.buffers[size_t(bv.buffer)].data;
    if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
        fail(what + ": buffer view " + std::to_string(view) + " (" + std::to_string(bv.byteOffset) + " + " +
             std::to_string(bv.byteLength) + " bytes) runs past its buffer (" + std::to_string(data.size()) +
             " bytes)");
    const std::size_t element = std::size_t(components) * std::size_t(bytes_of(component_type));
    const std::size_t stride = bv.byteStride ? bv.byteStride : element;
    if (stride < element) fail(what + ": byte stride " + std::to_string(stride) + " is shorter than an element");
    if (count > 0 && (offset > bv.byteLength || (count - 1) > (bv.byteLength - offset) / stride ||
                      (count - 1) * stride + element > bv.byteLength - offset))
        fail(what + ": " + std::to_string(count) + " elements from byte " + std::to_string(offset) +
             " run past buffer view " + std::to_string(view) + " (" + std::to_string(bv.byteLength) + " bytes)");
    const unsigned char* base = data.data() + bv.byteOffset + offset;
    const int size = bytes_of(component_type);
    const std::size_t first = out.size();
    out.resize(first + count * std::size_t(components));
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < components; ++c)
            out[first + i * std::size_t(components) + std::size_t(c)] =
                component(base + i * stride + std::size_t(c * size), component_type, normalized);
}

std::vector<double> AccessorReader::numbers(int index, int components, const std::string& what) const {
    const tinygltf::Accessor& a = accessor(index, what);
    const std::string named = what + " (accessor " + std::to_string(index) + ")";
    if (components_of(a.type) != components)
        fail(named + ": expected " + std::to_string(components) + " components an element, got " +
             std::to_string(components_of(a.type)));
    if (bytes_of(a.componentType) == 0 || a.componentType == TINYGLTF_COMPONENT_TYPE_DOUBLE)
        fail(named + ": component type " + std::to_string(a.componentType) + " is not glTF's");
    // Refused before anything is allocated: a sparse accessor without a
    // buffer view is zeros of any count, whatever the file's size.
    if (a.count > kMaxGltfAccessorValues / std::size_t(components))
        fail(named + ": " + std::to_string(a.count) + " elements of " + std::to_string(components) +
             " numbers are more than one accessor may hold (" + std::to_string(kMaxGltfAccessorValues) + " numbers)");
    values_read_ += a.count * std::size_t(components);
    if (values_read_ > kMaxGltfReadValues)
        fail(named + ": the file's accessors, as its meshes, skins and animations read them, come to more than " +
             std::to_string(kMaxGltfReadValues) + " numbers");
    std::vector<double> out;
    if (a.bufferView >= 0) {
        read_view(a.bufferView, a.byteOffset, a.count, components, a.componentType, a.normalized, out, named);
    } else {
        if (!a.sparse.isSparse) fail(named + ": no buffer view and not sparse");
        out.assign(a.count * std::size_t(components), 0.0);
    }
    if (a.sparse.isSparse) {
        const std::size_t n = std::size_t(std::max(a.sparse.count, 0));
        if (a.sparse.count < 1 || n > a.count) fail(named + ": sparse count " + std::to_string(a.sparse.count));
        std::vector<double> where, values;
        read_view(a.sparse.indices.bufferView, std::size_t(std::max(a.sparse.indices.byteOffset, 0)), n, 1,
                  a.sparse.indices.componentType, false, where, named + " sparse indices");
        read_view(a.sparse.values.bufferView, std::size_t(std::max(a.sparse.values.byteOffset, 0)), n, components,
                  a.componentType, a.normalized, values, named + " sparse values");
        for (std::size_t k = 0; k < n; ++k) {
            if (!(where[k] >= 0 && where[k] < double(a.count)) || (k > 0 && !(where[k] > where[k - 1])))
                fail(named + ": sparse index " + std::to_string(std::int64_t(where[k])) +
                     " is out of range or out of order");
            std::copy_n(values.begin() + std::ptrdiff_t(k * std::size_t(components)), components,
                        out.begin() + std::ptrdiff_t(std::size_t(where[k]) * std::size_t(components)));
        }
    }
    for (const double v : out)
        if (!std::isfinite(v)) fail(named + ": a value is not finite (NaN or infinite)");
    return out;
}

std::vector<std::uint32_t> AccessorReader::indices(int index, std::uint32_t limit, const std::string& what) const {
    const tinygltf::Accessor& a = accessor(index, what);
    const std::string named = what + " (accessor " + std::to_string(index) + ")";
    if (a.type != TINYGLTF_TYPE_SCALAR) fail(named + ": indices must be scalars");
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(named + ": indices must be unsigned byte, short or int");
    const std::vector<double> values = numbers(index, 1, what);
    std::vector<std::uint32_t> out(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!(values[i] < double(limit)))
            fail(named + ": index " + std::to_string(std::uint64_t(values[i])) + " is out of range (" +
                 std::to_string(limit) + " vertices)");
        out[i] = std::uint32_t(values[i]);
    }
    return out;
}

}  // namespace fh
