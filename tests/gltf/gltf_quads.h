// Textured glTF quads for the tests (test_gltf_textures.cpp,
// test_gltf_emission.cpp): images made here (PNGs by the PNG writer's
// encoder for RGB, stb_image_write for RGBA), quads facing up with their
// materials, textures, images and samplers, lit and seen straight down.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <stb_image_write.h>

#include "gltf/gltf_load.h"
#include "images/image_writer.h"
#include "images/png_writer.h"
#include "render/effect_plan.h"
#include "render/flat_scene.h"
#include "render/render.h"

namespace fh::gltf_test {

using Bytes4 = std::array<std::uint8_t, 4>;
using Rgb = std::array<int, 3>;

constexpr double kPi = 3.14159265358979323846;

inline double srgb_to_linear(int byte) {
    const double c = byte / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// A number as JSON, to the last bit.
inline std::string num(double x) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

// Numbers as a JSON array.
inline std::string numbers(const std::vector<double>& xs) {
    std::string s = "[";
    for (size_t k = 0; k < xs.size(); ++k) s += (k ? ", " : "") + num(xs[k]);
    return s + "]";
}

// ------------------------------------------------------------------ images

inline std::string as_string(const std::vector<std::uint8_t>& v) { return std::string(v.begin(), v.end()); }

// A PNG of w x h RGBA texels, rows from the top.
inline std::string rgba_png(int w, int h, const std::vector<Bytes4>& texels) {
    std::vector<std::uint8_t> px;
    for (const Bytes4& t : texels) px.insert(px.end(), t.begin(), t.end());
    std::string out;
    auto append = [](void* ctx, void* data, int size) {
        static_cast<std::string*>(ctx)->append(static_cast<const char*>(data), size_t(size));
    };
    EXPECT_TRUE(stbi_write_png_to_func(append, &out, w, h, 4, px.data(), 4 * w));
    return out;
}

// An RGB image of one colour.
inline Image flat_image(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image im(w, h);
    for (size_t i = 0; i < im.rgb.size(); i += 3) im.rgb[i] = r, im.rgb[i + 1] = g, im.rgb[i + 2] = b;
    return im;
}

// A PNG of w x h RGB texels of one colour (the project's encode_png).
inline std::string rgb_png(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    return as_string(encode_png(flat_image(w, h, r, g, b)));
}

inline std::string png_uri(const std::string& png) { return "data:image/png;base64," + base64(png); }

// An image member: the bytes as a data: uri.
inline std::string image_json(const std::string& png, const std::string& more = "") {
    return "{\"uri\": \"" + png_uri(png) + "\"" + more + "}";
}

// A PNG's signature and IHDR chunk (CRC included) claiming w x h texels of
// colour type `color` (0 grey, 2 RGB, 6 RGBA), and nothing after it.
inline std::string png_header(std::uint32_t w, std::uint32_t h, int color) {
    auto be32 = [](std::uint32_t v) {
        return std::string{char(v >> 24), char((v >> 16) & 0xff), char((v >> 8) & 0xff), char(v & 0xff)};
    };
    std::string chunk = "IHDR" + be32(w) + be32(h) + std::string{char(8), char(color), 0, 0, 0};
    const std::uint32_t crc = png_crc32(reinterpret_cast<const unsigned char*>(chunk.data()), chunk.size());
    return std::string("\x89PNG\r\n\x1a\n", 8) + be32(13) + chunk + be32(crc);
}

// ------------------------------------------------------------------ files

// A quad facing up in the world (z up), x in [x0, x1], y in [y0, y1], at
// height z; its TEXCOORD_0 has (0, 0) at (x0, y1) -- the image's top left
// seen from above -- u along +x and v along -y. Written y-up for the file:
// the world's (x, y, z) is glTF's (x, z, -y). Its triangles wind
// counter-clockwise seen from above, unless `down`.
struct Quad {
    double x0, x1, y0, y1, z;
    int material = -1;
    double scale = 1;                // its node's scale (the positions are divided by it)
    double stretch = 1;              // and its node's further scale along x (x divided by it too)
    double lift = 1;                 // and along its normal (z divided by it too)
    double tilt = 0;                 // its node's turn about x, degrees: the y1 edge up, for tilt > 0
    std::vector<double> matrix;      // or its node's matrix (16 numbers, the file's, column by column)
    bool uvs = true;                 // TEXCOORD_0
    std::vector<float> uv1;          // TEXCOORD_1 (8 numbers), or none
    bool normals = false;            // NORMAL: up, at every vertex
    std::vector<float> tangents;     // TANGENT (16 numbers, the file's axes; fewer: a bad count), or none
    bool degenerate_first = false;   // a zero-area triangle before its two
    bool down = false;               // wound facing down: seen from above, its back
    int layers = 1;                  // copies of it in the same primitive, each layer_step higher
    double layer_step = 0.01;
    // COLOR_0, component by component for its 4 vertices a layer, or none:
    // `color_kind` VEC3 or VEC4 of `color_type` (normalized when an integer,
    // unless `color_normalized` is false).
    std::vector<double> colors;
    std::string color_kind = "VEC3";
    int color_type = kFloat;
    bool color_normalized = true;
};

// The members (no braces) holding each quad as a mesh on a node of its
// own, followed by `rest` (materials, textures, ...).
inline std::string quads_body(Bin& bin, const std::vector<Quad>& quads, const std::string& rest) {
    std::string nodes, meshes, accessors, scene;
    int a = 0;
    for (size_t k = 0; k < quads.size(); ++k) {
        const Quad& q = quads[k];
        const double s = q.scale;
        std::vector<float> p, uv;
        std::vector<int> index;
        if (q.degenerate_first) index = {0, 0, 1};
        for (int layer = 0; layer < q.layers; ++layer) {
            const double z = q.z + q.layer_step * layer;
            auto at = [&](double x, double y) {
                return std::vector<float>{float(x / (s * q.stretch)), float(z / (s * q.lift)), float(-y / s)};
            };
            for (const auto& v : {at(q.x0, q.y1), at(q.x1, q.y1), at(q.x1, q.y0), at(q.x0, q.y0)})
                p.insert(p.end(), v.begin(), v.end());
            uv.insert(uv.end(), {0, 0, 1, 0, 1, 1, 0, 1});
            for (const int i : q.down ? std::vector<int>{0, 1, 2, 0, 2, 3} : std::vector<int>{0, 2, 1, 0, 3, 2})
                index.push_back(4 * layer + i);
        }
        const size_t n = p.size() / 3;
        std::string attributes = "\"POSITION\": " + std::to_string(a);
        accessors += std::string(accessors.empty() ? "" : ", ") + accessor(bin.f32(p), kFloat, n, "VEC3");
        ++a;
        if (q.uvs) {
            accessors += ", " + accessor(bin.f32(uv), kFloat, n, "VEC2");
            attributes += ", \"TEXCOORD_0\": " + std::to_string(a++);
        }
        if (!q.uv1.empty()) {
            accessors += ", " + accessor(bin.f32(q.uv1), kFloat, 4, "VEC2");
            attributes += ", \"TEXCOORD_1\": " + std::to_string(a++);
        }
        if (q.normals) {
            std::vector<float> up;
            for (size_t v = 0; v < n; ++v) up.insert(up.end(), {0, 1, 0});  // the file's +y: the world's +z
            accessors += ", " + accessor(bin.f32(up), kFloat, n, "VEC3");
            attributes += ", \"NORMAL\": " + std::to_string(a++);
        }
        if (!q.tangents.empty()) {
            accessors += ", " + accessor(bin.f32(q.tangents), kFloat, q.tangents.size() / 4, "VEC4");
            attributes += ", \"TANGENT\": " + std::to_string(a++);
        }
        if (!q.colors.empty()) {
            std::vector<float> f;
            std::vector<int> i;
            for (const double c : q.colors) f.push_back(float(c)), i.push_back(int(c));
            const int view = q.color_type == kFloat ? bin.f32(f) : q.color_type == kUnsignedByte ? bin.u8(i) : bin.u16(i);
            const bool normalized = q.color_type != kFloat && q.color_normalized;
            accessors += ", " + accessor(view, q.color_type, n, q.color_kind, normalized ? ", \"normalized\": true" : "");
            attributes += ", \"COLOR_0\": " + std::to_string(a++);
        }
        accessors += ", " + accessor(bin.u16(index), kUnsignedShort, index.size(), "SCALAR");
        const int indices = a++;
        meshes += std::string(meshes.empty() ? "" : ", ") + "{\"primitives\": [{\"attributes\": {" + attributes +
                  "}, \"indices\": " + std::to_string(indices) +
                  (q.material >= 0 ? ", \"material\": " + std::to_string(q.material) : "") + "}]}";
        // (The file's x turned towards its y: the world's y towards z.)
        const double half = q.tilt * kPi / 360;
        nodes += std::string(nodes.empty() ? "" : ", ") + "{\"mesh\": " + std::to_string(k) +
                 (s != 1 || q.stretch != 1 || q.lift != 1
                      ? ", \"scale\": [" + num(s * q.stretch) + ", " + num(s * q.lift) + ", " + num(s) + "]"
                      : "") +
                 (q.tilt != 0 ? ", \"rotation\": [" + num(std::sin(half)) + ", 0, 0, " + num(std::cos(half)) + "]" : "") +
                 (q.matrix.empty() ? "" : ", \"matrix\": " + numbers(q.matrix)) + "}";
        scene += std::string(scene.empty() ? "" : ", ") + std::to_string(k);
    }
    return "\"scenes\": [{\"nodes\": [" + scene + "]}], \"nodes\": [" + nodes + "],\n\"meshes\": [" + meshes +
           "],\n\"accessors\": [" + accessors + "]" + (rest.empty() ? "" : ",\n" + rest);
}

inline std::string quads_file(const std::vector<Quad>& quads, const std::string& rest) {
    Bin bin;
    const std::string body = quads_body(bin, quads, rest);
    return gltf_json(body, bin);
}

// A matte non-metal material of base colour factor `color` ("[r, g, b, a]"),
// its baseColorTexture `texture` (a textureInfo's JSON, or none) and more
// members (", \"alphaMode\": ...").
inline std::string material(const std::string& color, const std::string& texture = "", const std::string& more = "") {
    return "{\"pbrMetallicRoughness\": {\"baseColorFactor\": " + color +
           ", \"metallicFactor\": 0, \"roughnessFactor\": 1" +
           (texture.empty() ? "" : ", \"baseColorTexture\": " + texture) + "}" + more + "}";
}
inline std::string tex(int index) { return "{\"index\": " + std::to_string(index) + "}"; }

// glTF's sampler constants.
constexpr int kRepeat = 10497, kMirrored = 33648, kClamp = 33071, kNearest = 9728, kLinear = 9729;

inline std::string sampler_json(int wrap_s, int wrap_t, int mag = -1, int min = -1) {
    return "{\"wrapS\": " + std::to_string(wrap_s) + ", \"wrapT\": " + std::to_string(wrap_t) +
           (mag >= 0 ? ", \"magFilter\": " + std::to_string(mag) : "") +
           (min >= 0 ? ", \"minFilter\": " + std::to_string(min) : "") + "}";
}

// "materials", "textures" (each {"sampler": i, "source": i}, -1: left out),
// "images" and "samplers" members.
struct TextureRef {
    int sampler, source;
};
inline std::string surfaces(const std::vector<std::string>& materials, const std::vector<TextureRef>& textures = {},
                     const std::vector<std::string>& images = {}, const std::vector<std::string>& samplers = {}) {
    auto list = [](const std::vector<std::string>& items) {
        std::string s;
        for (const std::string& i : items) s += (s.empty() ? "" : ", ") + i;
        return "[" + s + "]";
    };
    std::string out = "\"materials\": " + list(materials);
    if (!textures.empty()) {
        std::vector<std::string> t;
        for (const TextureRef& r : textures) {
            std::string j;
            if (r.sampler >= 0) j += "\"sampler\": " + std::to_string(r.sampler);
            if (r.source >= 0) j += std::string(j.empty() ? "" : ", ") + "\"source\": " + std::to_string(r.source);
            t.push_back("{" + j + "}");
        }
        out += ",\n\"textures\": " + list(t);
    }
    if (!images.empty()) out += ",\n\"images\": " + list(images);
    if (!samplers.empty()) out += ",\n\"samplers\": " + list(samplers);
    return out;
}

// ----------------------------------------------------------------- render

struct Lighting {
    double ambient = 0.2, sun = 0.6;
    dvec3 direction{0, 0, -1};  // the way the sun's light travels
};

// The file placed z-up, lit.
inline Scene lit(const std::string& json, const Lighting& l = {}) {
    Scene s = z_up(json);
    s.ambient_lights.push_back({"ambient", dvec3(255), l.ambient / 0.1 / 255});
    DirectionalLight<double> sun;
    sun.name = "sun";
    sun.color = dvec3(255);
    sun.intensity = l.sun / 255;
    sun.direction = glm::normalize(l.direction);
    s.directional_lights.push_back(sun);
    return s;
}

// Looking straight down from (cx, 0, 10), orthographic, +x to the right
// and +y up in the image: pixel (i, j) sees x = cx - hw + (2 hw / w)(i + 1/2),
// y = hh - (2 hh / h)(j + 1/2), hw = hh w / h. cx = 0.05 keeps every pixel
// centre off the quads' edges and diagonals.
// Perspective: the eye at (cx, 0, 10), the image plane at distance 9, so
// that the plane z = 1 is seen as the orthographic camera sees it.
inline Camera top_camera(int w = 8, int h = 8, double half_height = 1, double cx = 0.05,
                         Projection projection = Projection::orthographic) {
    Camera c;
    c.projection = projection;
    c.projection_distance = 9;
    c.width = w;
    c.height = h;
    c.view_point = {cx, 0, 10};
    c.look_at = {0, 0, -1};
    c.up = {0, 1, 0};
    c.half_height = half_height;
    return c;
}

// What top_camera sees of s. counts: where to put the frame's ray counts,
// if anywhere.
inline Image top_view(const Scene& s, Precision precision, int w = 8, int h = 8, double half_height = 1, double cx = 0.05,
               Projection projection = Projection::orthographic, RayCounts* counts = nullptr) {
    RenderSettings settings;
    settings.precision = precision;
    const FrameResult r = render_frame(s, top_camera(w, h, half_height, cx, projection), settings, nullptr);
    EXPECT_EQ(r.counts.nonfinite_samples, 0u) << precision_name(precision);
    if (counts) *counts = r.counts;
    return r.image;
}

// That material 0's texture `texture` (a MaterialShading member) is read,
// as texture `index`, and the FlatScene's `flag` set, when the frame has
// every effect, and neither when its ambient light alone shows it.
template <typename Texture, typename Flag>
void expect_read_only_when_lit(const Scene& s, Texture texture, Flag flag, int index) {
    Effects ambient_only;
    ambient_only.diffuse = ambient_only.specular = ambient_only.shadows = ambient_only.glazing = false;
    const auto dark = FlatScene<double>::build(s, plan_effects(s, ambient_only, 5));
    EXPECT_EQ(dark.shading[0].*texture, -1);
    EXPECT_FALSE(dark.*flag);
    const auto lit = FlatScene<double>::build(s, plan_effects(s, Effects{}, 5));
    EXPECT_EQ(lit.shading[0].*texture, index);
    EXPECT_TRUE(lit.*flag);
}

inline Rgb pixel(const Image& im, int i, int j) {
    const size_t at = 3 * (size_t(j) * size_t(im.width) + size_t(i));
    return {im.rgb[at], im.rgb[at + 1], im.rgb[at + 2]};
}

inline std::string show(const Rgb& c) {
    return "(" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) + ")";
}

// Pixel (i, j) within `tol` of `want` in each channel.
inline void expect_pixel(const Image& im, int i, int j, const Rgb& want, const std::string& what, int tol = 1) {
    const Rgb got = pixel(im, i, j);
    for (size_t k = 0; k < 3; ++k)
        EXPECT_NEAR(got[k], want[k], tol) << what << ": pixel (" << i << ", " << j << ") is " << show(got)
                                          << ", wanted " << show(want);
}

// Every pixel of columns [i0, i1) is `want`.
inline void expect_columns(const Image& im, int i0, int i1, const Rgb& want, const std::string& what, int tol = 1) {
    for (int j = 0; j < im.height; ++j)
        for (int i = i0; i < i1; ++i) expect_pixel(im, i, j, want, what, tol);
}

inline const Precision kPrecisions[] = {Precision::float64, Precision::float32};

// The two-colour texture: red on the left, blue on the right, opaque.
inline const std::vector<Bytes4> kRedBlue = {{255, 0, 0, 255}, {0, 0, 255, 255}};

}  // namespace fh::gltf_test
