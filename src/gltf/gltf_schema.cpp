#include "gltf/gltf_schema.h"

#include <vector>

#include "text/input_error.h"

namespace fh {

namespace {

using json = nlohmann::json;

constexpr std::uint64_t kMaxIndex = 2147483647;

enum class Kind { index, number, string, boolean, object, array, numbers };

struct Field;
using Fields = std::vector<Field>;

// A field of an object: its kind; an object's own fields, or an array's
// items (an object's fields, or a kind); numbers: how many (0: any).
struct Field {
    const char* key;
    Kind kind;
    bool required = false;
    const Fields* fields = nullptr;  // object, or array of objects
    Kind item = Kind::object;        // array: its items' kind
    int count = 0;                   // numbers
};

Field index(const char* k, bool req = false) { return {k, Kind::index, req}; }
Field number(const char* k, bool req = false) { return {k, Kind::number, req}; }
Field string(const char* k, bool req = false) { return {k, Kind::string, req}; }
Field boolean(const char* k) { return {k, Kind::boolean}; }
Field object(const char* k, const Fields& f, bool req = false) { return {k, Kind::object, req, &f}; }
Field objects(const char* k, const Fields& f, bool req = false) { return {k, Kind::array, req, &f, Kind::object}; }
Field indices(const char* k, bool req = false) { return {k, Kind::array, req, nullptr, Kind::index}; }
Field strings(const char* k) { return {k, Kind::array, false, nullptr, Kind::string}; }
Field numbers(const char* k, int n = 0) { return {k, Kind::numbers, false, nullptr, Kind::number, n}; }

const Fields kTextureInfo = {index("index", true), index("texCoord"), number("scale"), number("strength")};
const Fields kPbr = {numbers("baseColorFactor", 4), object("baseColorTexture", kTextureInfo), number("metallicFactor"),
                     number("roughnessFactor"), object("metallicRoughnessTexture", kTextureInfo)};
const Fields kMaterial = {string("name"), object("pbrMetallicRoughness", kPbr), object("normalTexture", kTextureInfo),
                          object("occlusionTexture", kTextureInfo), object("emissiveTexture", kTextureInfo),
                          numbers("emissiveFactor", 3), string("alphaMode"), number("alphaCutoff"), boolean("doubleSided")};
const Fields kPrimitive = {{"attributes", Kind::object, true}, index("indices"), index("material"), index("mode"),
                           {"targets", Kind::array, false, nullptr, Kind::object}};
const Fields kMesh = {objects("primitives", kPrimitive, true), numbers("weights"), string("name")};
const Fields kNode = {index("camera"), indices("children"), index("skin"), numbers("matrix", 16), index("mesh"),
                      numbers("rotation", 4), numbers("scale", 3), numbers("translation", 3), numbers("weights"),
                      string("name")};
const Fields kScene = {indices("nodes"), string("name")};
const Fields kSparseIndices = {index("bufferView", true), index("byteOffset"), index("componentType", true)};
const Fields kSparseValues = {index("bufferView", true), index("byteOffset")};
const Fields kSparse = {index("count", true), object("indices", kSparseIndices, true), object("values", kSparseValues, true)};
const Fields kAccessor = {index("bufferView"), index("byteOffset"), index("componentType", true), boolean("normalized"),
                          index("count", true), string("type", true), numbers("max"), numbers("min"),
                          object("sparse", kSparse), string("name")};
const Fields kBufferView = {index("buffer", true), index("byteOffset"), index("byteLength", true), index("byteStride"),
                            index("target"), string("name")};
const Fields kBuffer = {string("uri"), index("byteLength", true), string("name")};
const Fields kTexture = {index("sampler"), index("source"), string("name")};
const Fields kImage = {string("uri"), string("mimeType"), index("bufferView"), string("name")};
const Fields kSampler = {index("magFilter"), index("minFilter"), index("wrapS"), index("wrapT"), string("name")};
const Fields kPerspective = {number("aspectRatio"), number("yfov", true), number("zfar"), number("znear", true)};
const Fields kOrthographic = {number("xmag", true), number("ymag", true), number("zfar", true), number("znear", true)};
const Fields kCamera = {string("type", true), object("perspective", kPerspective), object("orthographic", kOrthographic),
                        string("name")};
const Fields kTarget = {index("node"), string("path", true)};
const Fields kChannel = {index("sampler", true), object("target", kTarget, true)};
const Fields kAnimationSampler = {index("input", true), index("output", true), string("interpolation")};
const Fields kAnimation = {objects("channels", kChannel, true), objects("samplers", kAnimationSampler, true),
                           string("name")};
const Fields kSkin = {index("inverseBindMatrices"), index("skeleton"), indices("joints", true), string("name")};
const Fields kAsset = {string("version", true), string("generator"), string("minVersion"), string("copyright")};
const Fields kRoot = {object("asset", kAsset, true), index("scene"), objects("scenes", kScene), objects("nodes", kNode),
                      objects("meshes", kMesh), objects("accessors", kAccessor), objects("bufferViews", kBufferView),
                      objects("buffers", kBuffer), objects("materials", kMaterial), objects("textures", kTexture),
                      objects("images", kImage), objects("samplers", kSampler), objects("cameras", kCamera),
                      objects("animations", kAnimation), objects("skins", kSkin), strings("extensionsUsed"),
                      strings("extensionsRequired")};

const char* kind_name(Kind k) {
    switch (k) {
    case Kind::index: return "a whole number >= 0";
    case Kind::number: return "a number";
    case Kind::string: return "a string";
    case Kind::boolean: return "true or false";
    case Kind::object: return "an object";
    case Kind::array:
    case Kind::numbers: return "an array";
    }
    return "";
}

std::string got(const json& v) {
    switch (v.type()) {
    case json::value_t::object: return "an object";
    case json::value_t::array: return "an array";
    case json::value_t::string: return "the string \"" + v.get<std::string>().substr(0, 40) + "\"";
    case json::value_t::boolean: return v.get<bool>() ? "true" : "false";
    case json::value_t::null: return "null";
    default: return v.dump();
    }
}

class Checker {
public:
    explicit Checker(std::string file) : file_(std::move(file)) {}

    void object_of(const json& v, const Fields& fields, const std::string& path) const {
        for (const Field& f : fields) {
            const std::string at = path.empty() ? f.key : path + "." + f.key;
            if (!v.contains(f.key)) {
                if (f.required) fail(at + ": required, and missing");
                continue;
            }
            value(v.at(f.key), f, at);
        }
        if (v.contains("extensions")) {
            const json& ext = v.at("extensions");
            const std::string at = path.empty() ? "extensions" : path + ".extensions";
            if (!ext.is_object()) fail(at + ": expected an object, got " + got(ext));
            for (auto it = ext.begin(); it != ext.end(); ++it)
                if (!it.value().is_object()) fail(at + "." + it.key() + ": expected an object, got " + got(it.value()));
        }
    }

private:
    void value(const json& v, const Field& f, const std::string& at) const {
        if (!is(v, f.kind)) fail(at + ": expected " + kind_name(f.kind) + ", got " + got(v));
        if (f.kind == Kind::index) below_2_31(v, at);
        if (f.kind == Kind::object && f.fields) object_of(v, *f.fields, at);
        if (f.kind == Kind::numbers) {
            for (size_t i = 0; i < v.size(); ++i)
                if (!v[i].is_number()) fail(at + "[" + std::to_string(i) + "]: expected a number, got " + got(v[i]));
            if (f.count > 0 && int(v.size()) != f.count)
                fail(at + ": expected " + std::to_string(f.count) + " numbers, got " + std::to_string(v.size()));
        }
        if (f.kind == Kind::array)
            for (size_t i = 0; i < v.size(); ++i) {
                const std::string item = at + "[" + std::to_string(i) + "]";
                if (!is(v[i], f.item)) fail(item + ": expected " + kind_name(f.item) + ", got " + got(v[i]));
                if (f.item == Kind::index) below_2_31(v[i], item);
                if (f.item == Kind::object && f.fields) object_of(v[i], *f.fields, item);
            }
    }

    // tinygltf keeps indices in an int and wraps larger ones
    // (18446744073709551615 became -1: "no mesh"); no count or length
    // within the documented limits comes near 2^31 either.
    void below_2_31(const json& v, const std::string& at) const {
        if (v.get<std::uint64_t>() > kMaxIndex)
            fail(at + ": " + got(v) + " is larger than 2147483647, the largest index or length a glTF file may give");
    }

    static bool is(const json& v, Kind k) {
        switch (k) {
        case Kind::index: return v.is_number_unsigned() || (v.is_number_integer() && v.get<std::int64_t>() >= 0);
        case Kind::number: return v.is_number();
        case Kind::string: return v.is_string();
        case Kind::boolean: return v.is_boolean();
        case Kind::object: return v.is_object();
        case Kind::array:
        case Kind::numbers: return v.is_array();
        }
        return false;
    }

    [[noreturn]] void fail(const std::string& what) const { throw InputError(file_, what); }

    std::string file_;
};

}  // namespace

void check_gltf_schema(const nlohmann::json& root, const std::string& file) {
    if (!root.is_object()) throw InputError(file, "a glTF file is a JSON object");
    Checker(file).object_of(root, kRoot, "");
    // node.schema.json's one rule beyond types: a matrix or TRS, not both.
    // tinygltf would drop the TRS without a word, placing the node where
    // its author may not have meant.
    if (root.contains("nodes"))
        for (size_t i = 0; i < root["nodes"].size(); ++i) {
            const json& node = root["nodes"][i];
            if (node.contains("matrix") && (node.contains("translation") || node.contains("rotation") || node.contains("scale")))
                throw InputError(file, "nodes[" + std::to_string(i) +
                                           "]: has both 'matrix' and translation, rotation or scale (glTF allows one or the other)");
        }
}

}  // namespace fh
