// Textures and emission from model files reach the surface points: a texture read at a
// known place on an OBJ + MTL quad and on a glTF quad gives that texel's colour, Ke and
// emissiveFactor become the emitted luminance, and a missing image is listed, not fatal.
#include <gtest/gtest.h>

#include "../test_support.h"
#include "gltf_quad_buffer.h"
#include "skylit/core/base64.h"
#include "skylit/io/image/image_encoders.h"
#include "skylit/io/model/mesh_io.h"
#include "skylit/io/model/texture_file.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/prepared_scene.h"
#include "skylit/spectrum/cie.h"
#include "skylit/spectrum/color_space.h"

namespace skylit {
namespace {

using testing::TempDir;

// 2 × 2 texels, top row red and green, bottom row blue and white (8-bit sRGB).
void write_texture(const TempDir& dir, const std::string& name) {
  const uint8_t rgb[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
  const Bytes png = encode_png_rgb8(2, 2, rgb);
  dir.write(name, std::string(png.begin(), png.end()));
}

// A 2 m quad on the ground, its material "Painted" from quad.mtl, the image across it.
void write_obj_quad(const TempDir& dir) {
  dir.write("quad.obj",
            "mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl Painted\nf 1/1 2/2 3/3 4/4\n");
}

std::string scene_json(const std::string& file, const std::string& up, const std::string& more = "") {
  return R"({"camera": {"position": [0, 0, 10], "look_at": [0, 0.001, 0]},
    "sun": {"altitude_deg": 40, "azimuth_deg": 135},
    "materials": {"white": {"type": "diffuse", "reflectance": 0.8}},
    "objects": [{"type": "mesh", "name": "quad", "file": ")" +
         file + R"(", "up_axis": ")" + up + R"(", "material": "white")" + more + R"(}],
    "render": {"width": 64, "height": 48}})";
}

// The surface point straight below (x, y), seen from 10 m above.
SurfacePoint point_below(const PreparedScene& prepared, double x, double y) {
  const Ray ray{{x, y, 10}, {0, 0, -1}};
  const std::optional<Hit> hit = prepared.tracer().intersect(ray);
  EXPECT_TRUE(hit.has_value());
  return prepared.surface_point(ray, *hit);
}

void expect_color(const SurfacePoint& p, double r, double g, double b) {
  ASSERT_TRUE(p.has_color);
  // Bilinear at a texel's centre with a footprint of 0.01 texels: the texel itself.
  EXPECT_NEAR(p.color[0], r, 1e-4);
  EXPECT_NEAR(p.color[1], g, 1e-4);
  EXPECT_NEAR(p.color[2], b, 1e-4);
}

// As expect_color, where the texture is scaled twice across: the look-up's footprint
// (the test ray's) then spans about a texel of this 2 × 2 image and mixes in up to a
// tenth of its mip level's mean, far from the other texels' colours.
void expect_about_color(const SurfacePoint& p, const std::array<double, 3>& rgb) {
  ASSERT_TRUE(p.has_color);
  for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(p.color[c], rgb[c], 0.15) << c;
}

TEST(ModelTextures, ObjMapKdAtKnownUvs) {
  TempDir dir;
  write_texture(dir, "tex.png");
  // A 2 m quad on the ground with the image across it; OBJ's v runs up from the image's
  // bottom row. Kd 0.5 scales the texels (as glTF's factor does).
  dir.write("quad.mtl", "newmtl Painted\nKd 0.5 1 1\nmap_Kd tex.png\nKe 20 10 5\n");
  write_obj_quad(dir);
  const Scene scene = load_scene(dir.write("scene.json", scene_json("quad.obj", "z")));
  const PreparedScene prepared(scene);
  expect_color(point_below(prepared, -0.5, 0.5), 0.5, 0, 0);  // top left: red
  expect_color(point_below(prepared, 0.5, 0.5), 0, 1, 0);     // top right: green
  expect_color(point_below(prepared, -0.5, -0.5), 0, 0, 1);   // bottom left: blue
  expect_color(point_below(prepared, 0.5, -0.5), 0.5, 1, 1);  // bottom right: white
  // Half way between the left texels' centres: their mean (linear).
  expect_color(point_below(prepared, -0.5, 0.0), 0.25, 0, 0.5);
  // Mirrored left to right (the winding reversed to keep the normal up): the texture
  // follows its corners, so red is now top right.
  const Scene mirrored =
      load_scene(dir.write("mirrored.json", scene_json("quad.obj", "z", R"(, "transform": {"scale": [-1, 1, 1]})")));
  const PreparedScene prepared_mirror(mirrored);
  expect_color(point_below(prepared_mirror, 0.5, 0.5), 0.5, 0, 0);
  expect_color(point_below(prepared_mirror, -0.5, -0.5), 0.5, 1, 1);
  // Ke: 20, 10, 5 cd/m² per channel; the emitted radiance has the colour's luminance.
  const SurfacePoint p = point_below(prepared, 0.2, 0.3);
  ASSERT_TRUE(p.emissive);
  EXPECT_FLOAT_EQ(p.emission_cd_m2[0], 20);
  const double y = xyz_from_linear_srgb({20, 10, 5}).y;
  EXPECT_NEAR(luminance(emitted_radiance(p.emission_cd_m2)), y, 1e-3 * y);
}

// The test texture (red, green / blue, white) as a 24-bit BMP and an uncompressed TGA,
// written here byte by byte from the formats' headers: both store the bottom row
// first, and the texels as blue, green, red; a BMP pads each row to 4 bytes.
// `top_down`: the rows stored top first, as a negative height says (Windows' own
// screenshots and some converters write them so).
std::string bmp_texture(bool top_down = false) {
  const auto u32 = [](uint32_t v) { return std::string{char(v), char(v >> 8), char(v >> 16), char(v >> 24)}; };
  const auto u16 = [](uint32_t v) { return std::string{char(v), char(v >> 8)}; };
  const std::string bottom = std::string("\xFF\x00\x00\xFF\xFF\xFF\x00\x00", 8);  // blue, white, pad
  const std::string top = std::string("\x00\x00\xFF\x00\xFF\x00\x00\x00", 8);     // red, green, pad
  return "BM" + u32(54 + 16) + u32(0) + u32(54) + u32(40) + u32(2) + u32(top_down ? uint32_t(-2) : 2) + u16(1) +
         u16(24) + u32(0) + u32(16) + u32(2835) + u32(2835) + u32(0) + u32(0) +
         (top_down ? top + bottom : bottom + top);
}

std::string tga_texture() {
  // No ID, no colour map, type 2 (true colour), origin (0, 0), 2 × 2, 24 bits, bottom-up.
  const std::string header("\x00\x00\x02\x00\x00\x00\x00\x00\x00\x00\x00\x00\x02\x00\x02\x00\x18\x00", 18);
  return header + std::string("\xFF\x00\x00\xFF\xFF\xFF\x00\x00\xFF\x00\xFF\x00", 12);
}

// A JPEG whose scan decodes with a Huffman table it never defines: Debian 12's
// stb_image 2.27 read such a table from memory it never set, out of bounds at random
// (the texture fuzz target's finding, fuzz/corpus/texture/scan_with_undefined_table.jpg).
// libjpeg-turbo, which now decodes JPEGs, supplies the standard tables of the JPEG
// specification's Annex K for those a file lacks (as Motion-JPEG frames need). Here a
// one-component baseline 8 × 8 JPEG defining DC table 0 and AC table 0 whose scan asks
// for AC table 1 (the standard chrominance table) or 0: both decode to one block of
// coefficients all zero, the level-shifted grey 128.
TEST(ModelTextures, AJpegScanWithAnUndefinedHuffmanTableTakesTheStandardOne) {
  const auto jpeg = [](unsigned char ac_table) {
    const std::string sof("\xFF\xC0\x00\x0B\x08\x00\x08\x00\x08\x01\x01\x11\x00", 13);
    const std::string dqt = std::string("\xFF\xDB\x00\x43\x00", 5) + std::string(64, '\x01');
    // Each table one code of length 1, symbol 0.
    const std::string one_code = std::string("\x01", 1) + std::string(15, '\0') + std::string(1, '\0');
    const std::string dht = std::string("\xFF\xC4\x00\x26\x00", 5) + one_code + std::string("\x10", 1) + one_code;
    const std::string sos =
        std::string("\xFF\xDA\x00\x08\x01\x01", 6) + std::string(1, char(ac_table)) + std::string("\x00\x3F\x00", 3);
    return std::string("\xFF\xD8", 2) + dqt + sof + dht + sos + std::string("\x00\x00\xFF\xD9", 4);
  };
  for (const unsigned char ac_table : {0x01, 0x00}) {
    SCOPED_TRACE(static_cast<int>(ac_table));
    const std::string bytes = jpeg(ac_table);
    const auto texture = decode_texture(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(),
                                        TextureEncoding::srgb, "t.jpg");
    ASSERT_EQ(texture->width(), 8);
    ASSERT_EQ(texture->height(), 8);
    const double grey = std::pow((128.0 / 255 + 0.055) / 1.055, 2.4);  // sRGB 128, linear
    for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(texture->mean()[c], grey, 1e-4);
  }
}

// Older OBJ exports (3ds Max, MilkShape, games) give BMP and TGA textures; a BMP stopped
// the whole scene. Each reads the right way up.
TEST(ModelTextures, BmpAndTgaTexturesAreReadTheRightWayUp) {
  for (const auto& [name, bytes] : {std::pair{"tex.bmp", bmp_texture()}, std::pair{"top_down.bmp", bmp_texture(true)},
                                    std::pair{"tex.tga", tga_texture()}}) {
    SCOPED_TRACE(name);
    TempDir dir;
    dir.write(name, bytes);
    dir.write("quad.mtl", std::string("newmtl Painted\nKd 1 1 1\nmap_Kd ") + name + "\n");
    write_obj_quad(dir);
    const Scene scene = load_scene(dir.write("scene.json", scene_json("quad.obj", "z")));
    const PreparedScene prepared(scene);
    expect_color(point_below(prepared, -0.5, 0.5), 1, 0, 0);
    expect_color(point_below(prepared, 0.5, 0.5), 0, 1, 0);
    expect_color(point_below(prepared, -0.5, -0.5), 0, 0, 1);
    expect_color(point_below(prepared, 0.5, -0.5), 1, 1, 1);
  }
}

// A glTF quad (y up: the file's x–z plane is skylit's ground) with its geometry in
// quad.bin and the texture beside it, emissive by the strength extension.
void write_gltf(const TempDir& dir, const std::string& image_uri) {
  testing::write_quad_bin(dir);
  dir.write("quad.gltf", R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
    "materials": [{"name": "Sign", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1],
      "baseColorTexture": {"index": 0}, "metallicFactor": 0}, "emissiveFactor": [1, 0.5, 0.25],
      "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 40}}}],
    "textures": [{"source": 0}], "images": [{"uri": ")" +
                             image_uri + R"("}],
    "buffers": [{"uri": "quad.bin", "byteLength": 92}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                    {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 0, 1]},
                  {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                  {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}]})");
}

TEST(ModelTextures, GltfBaseColorTextureAndEmissiveStrength) {
  TempDir dir;
  write_texture(dir, "tex.png");
  write_gltf(dir, "tex.png");
  const Scene scene = load_scene(dir.write("scene.json", scene_json("quad.gltf", "y")));
  const PreparedScene prepared(scene);
  expect_color(point_below(prepared, -0.5, 0.5), 1, 0, 0);
  expect_color(point_below(prepared, 0.5, 0.5), 0, 1, 0);
  expect_color(point_below(prepared, -0.5, -0.5), 0, 0, 1);
  const SurfacePoint p = point_below(prepared, 0.5, -0.5);  // white texel: the factor × strength
  ASSERT_TRUE(p.emissive);
  EXPECT_FLOAT_EQ(p.emission_cd_m2[0], 40);
  EXPECT_FLOAT_EQ(p.emission_cd_m2[1], 20);
  EXPECT_FLOAT_EQ(p.emission_cd_m2[2], 10);
}

// KHR_texture_transform (a material's tiling, as Blender exports it) moves the texture:
// uv' = T(offset) R(rotation) S(scale) (u, v, 1). Offset half the image: the top left of
// the quad shows the top right texel, green, and the top right (u 1.25, repeating) red.
// Rotation π/2: (u, v) → (v, −u), so the top left point (u, v) = (0.25, 0.25) reads
// (0.25, 0.75): the bottom left texel, blue. (It was ignored: an outside trial's
// Khronos TextureTransformTest showed its "not supported" panels.)
TEST(ModelTextures, GltfTextureTransformMovesTheTexture) {
  TempDir dir;
  write_texture(dir, "tex.png");
  write_gltf(dir, "tex.png");
  const std::string plain = testing::read_file(dir.path() / "quad.gltf");
  auto with_transform = [&](const std::string& transform) {
    std::string text = plain;
    const std::string from = R"("baseColorTexture": {"index": 0})";
    text.replace(text.find(from), from.size(),
                 R"("baseColorTexture": {"index": 0, "extensions": {"KHR_texture_transform": )" + transform + "}}");
    dir.write("quad.gltf", text);
    return load_scene(dir.write("scene.json", scene_json("quad.gltf", "y")));
  };
  const Scene shifted = with_transform(R"({"offset": [0.5, 0]})");
  const PreparedScene prepared(shifted);
  expect_color(point_below(prepared, -0.5, 0.5), 0, 1, 0);
  expect_color(point_below(prepared, 0.5, 0.5), 1, 0, 0);
  const Scene turned = with_transform(R"({"rotation": 1.5707963267948966})");
  expect_color(point_below(PreparedScene(turned), -0.5, 0.5), 0, 0, 1);
}

// A glTF sampler's wrapS (clamp to edge, mirrored repeat) holds outside [0, 1): with the
// texture scaled twice across (KHR_texture_transform), x 0.25 and 0.75 on the quad read
// u 1.25 and 1.75: repeated, the left and right texels of the top row (red, green);
// clamped, the right edge twice (green, green); mirrored, the right then the left
// (green, red).
TEST(ModelTextures, GltfSamplerWrapModesHoldOutsideTheImage) {
  TempDir dir;
  write_texture(dir, "tex.png");
  write_gltf(dir, "tex.png");
  const std::string plain = testing::read_file(dir.path() / "quad.gltf");
  auto with_sampler = [&](int wrap_s) {
    std::string text = plain;
    const std::string texture = R"("textures": [{"source": 0}])";
    text.replace(text.find(texture), texture.size(),
                 R"("textures": [{"source": 0, "sampler": 0}], "samplers": [{"wrapS": )" + std::to_string(wrap_s) +
                     R"(, "wrapT": 10497}])");
    const std::string from = R"("baseColorTexture": {"index": 0})";
    text.replace(text.find(from), from.size(),
                 R"("baseColorTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"scale": [2, 1]}}})");
    dir.write("quad.gltf", text);
    return load_scene(dir.write("scene.json", scene_json("quad.gltf", "y")));
  };
  struct Case {
    int wrap_s;
    std::array<double, 3> at_quarter, at_three_quarters;
  };
  for (const Case& c :
       {Case{10497, {1, 0, 0}, {0, 1, 0}}, Case{33071, {0, 1, 0}, {0, 1, 0}}, Case{33648, {0, 1, 0}, {1, 0, 0}}}) {
    SCOPED_TRACE(c.wrap_s);
    const Scene scene = with_sampler(c.wrap_s);
    const PreparedScene prepared(scene);
    expect_about_color(point_below(prepared, 0.25, 0.5), c.at_quarter);
    expect_about_color(point_below(prepared, 0.75, 0.5), c.at_three_quarters);
  }
}

// MTL texture options: -s and -o scale and move the texture coordinates (u' = s·u + o,
// Blender's tiling), -clamp on holds the edge texels outside [0, 1). On the quad, u runs
// 0 to 1 from x −1 to 1 (the top row: red, green).
TEST(ModelTextures, MtlScaleOffsetAndClampOptions) {
  struct Case {
    std::string options;
    double x;
    std::array<double, 3> colour;
  };
  for (const Case& c : {Case{"-s 2 1 1", 0.25, {1, 0, 0}}, Case{"-s 2 1 1", 0.75, {0, 1, 0}},
                        Case{"-clamp on -s 2 1 1", 0.25, {0, 1, 0}}, Case{"-o 0.5 0 0", -0.5, {0, 1, 0}},
                        Case{"-o 0.5 0 0", 0.5, {1, 0, 0}}, Case{"", 0.5, {0, 1, 0}}}) {
    SCOPED_TRACE(c.options + " at x " + std::to_string(c.x));
    TempDir dir;
    write_texture(dir, "tex.png");
    dir.write("quad.mtl", "newmtl Painted\nKd 1 1 1\nmap_Kd " + c.options + " tex.png\n");
    write_obj_quad(dir);
    const Scene scene = load_scene(dir.write("scene.json", scene_json("quad.obj", "z")));
    const PreparedScene prepared(scene);
    expect_about_color(point_below(prepared, c.x, 0.5), c.colour);
  }
}

// A texture whose image only EXT_texture_webp (or KHR_texture_basisu) gives is not
// read, and said once; with a PNG fallback as its source the fallback is read.
TEST(ModelTextures, ImagesOnlyAnExtensionGivesAreSaidNotSilentlyDropped) {
  TempDir dir;
  write_texture(dir, "tex.png");
  write_gltf(dir, "tex.png");
  const std::string plain = testing::read_file(dir.path() / "quad.gltf");
  auto with_textures = [&](const std::string& textures) {
    std::string text = plain;
    const std::string from = R"("textures": [{"source": 0}])";
    text.replace(text.find(from), from.size(), R"("textures": )" + textures);
    return load_model_file(dir.write("quad.gltf", text), UpAxis::y);
  };
  const LoadedModel webp_only = with_textures(R"([{"extensions": {"EXT_texture_webp": {"source": 0}}}])");
  EXPECT_EQ(webp_only.materials[0].color_texture, nullptr);
  ASSERT_EQ(webp_only.read_warnings.size(), 1u);
  EXPECT_NE(webp_only.read_warnings[0].find("textures given only by EXT_texture_webp are not read"), std::string::npos)
      << webp_only.read_warnings[0];
  const LoadedModel with_fallback =
      with_textures(R"([{"source": 0, "extensions": {"EXT_texture_webp": {"source": 0}}}])");
  EXPECT_NE(with_fallback.materials[0].color_texture, nullptr);
  EXPECT_TRUE(with_fallback.read_warnings.empty());
}

TEST(ModelTextures, AMissingImageIsListedAndABrokenOneIsAnError) {
  TempDir dir;
  write_gltf(dir, "nowhere.png");
  const Scene scene = load_scene(dir.write("scene.json", scene_json("quad.gltf", "y")));
  ASSERT_TRUE(scene.objects[0].source.has_value());
  EXPECT_EQ(scene.objects[0].source->missing_images, std::vector<std::string>{"nowhere.png"});
  EXPECT_TRUE(scene.objects[0].source->missing_libraries.empty());
  dir.write("broken.png", "\x89PNG\r\n\x1a\nnot really");
  write_gltf(dir, "broken.png");
  const std::string message =
      testing::input_error_of([&] { load_scene(dir.write("broken.json", scene_json("quad.gltf", "y"))); });
  // Named with the model that names it, then the file.
  EXPECT_NE(message.find("quad.gltf: image 0 ("), std::string::npos) << message;
  EXPECT_NE(message.find("broken.png): not a PNG, JPEG, BMP or TGA image"), std::string::npos) << message;
}

// A PNG whose image data chunk claims more bytes than the file holds is refused before
// stb_image reads it: stb grew its buffer to the claim first (an 89-byte file from the
// texture fuzz target asked for 2 GiB).
TEST(ModelTextures, APngChunkClaimingMoreThanTheFileIsRefusedBeforeItIsRead) {
  TempDir dir;
  write_texture(dir, "tex.png");
  std::string png = testing::read_file(dir.path() / "tex.png");
  const size_t idat = png.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  png.replace(idat - 4, 4, std::string("\x40\x00\x00\x00", 4));  // 1 GiB
  dir.write("tex.png", png);
  write_gltf(dir, "tex.png");
  const std::string message =
      testing::input_error_of([&] { load_scene(dir.write("scene.json", scene_json("quad.gltf", "y"))); });
  EXPECT_NE(message.find("claims 1073741824 bytes, more than the file has left"), std::string::npos) << message;
}

// Image addresses as exporters write them: a file name with spaces percent-encoded
// (RFC 3986: "te%20x.png" is the file "te x.png"), and the image inside the file as a
// data URI of a media type tinygltf does not list ("image/jpg", the bytes a PNG's).
// Windows exporters write MTL paths with backslashes ("map_Kd .\maps\tex.png"): read
// as slashes when the name as written is not there (an outside trial's textures were
// reported missing beside their file).
TEST(ModelTextures, ObjTexturePathsWithBackslashesAreFound) {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "maps");
  write_texture(dir, "maps/tex.png");
  dir.write("quad.mtl", "newmtl Painted\nKd 1 1 1\nmap_Kd .\\maps\\tex.png\n");
  write_obj_quad(dir);
  const Scene scene = load_scene(dir.write("scene.json", scene_json("quad.obj", "z")));
  EXPECT_TRUE(scene.objects[0].source->missing_images.empty());
  expect_color(point_below(PreparedScene(scene), 0.5, 0.5), 0, 1, 0);
}

// An absolute path of the exporting machine (Windows' or another's), the image handed
// over beside the model: found by its bare file name, as most importers find it.
TEST(ModelTextures, ObjTexturesNamedByAnotherMachinesPathAreFoundBesideTheModel) {
  for (const std::string path : {"C:\\Users\\arch\\Documents\\tex.png", "/home/arch/project/maps/tex.png"}) {
    SCOPED_TRACE(path);
    TempDir dir;
    write_texture(dir, "tex.png");
    dir.write("quad.mtl", "newmtl Painted\nKd 1 1 1\nmap_Kd " + path + "\n");
    write_obj_quad(dir);
    const Scene scene = load_scene(dir.write("scene.json", scene_json("quad.obj", "z")));
    EXPECT_TRUE(scene.objects[0].source->missing_images.empty());
    expect_color(point_below(PreparedScene(scene), 0.5, 0.5), 0, 1, 0);
  }
  // Not beside it either: listed as missing under the name the file gives.
  TempDir dir;
  dir.write("quad.mtl", "newmtl Painted\nKd 1 1 1\nmap_Kd C:\\maps\\gone.png\n");
  write_obj_quad(dir);
  const Scene scene = load_scene(dir.write("scene.json", scene_json("quad.obj", "z")));
  EXPECT_EQ(scene.objects[0].source->missing_images, std::vector<std::string>{"C:\\maps\\gone.png"});
}

TEST(ModelTextures, PercentEncodedNamesAndDataUrisOfAnyImageTypeAreRead) {
  TempDir dir;
  write_texture(dir, "te x.png");
  write_gltf(dir, "te%20x.png");
  const Scene spaced = load_scene(dir.write("scene.json", scene_json("quad.gltf", "y")));
  EXPECT_TRUE(spaced.objects[0].source->missing_images.empty());
  expect_color(point_below(PreparedScene(spaced), -0.5, 0.5), 1, 0, 0);

  const uint8_t rgb[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
  const Bytes png = encode_png_rgb8(2, 2, rgb);
  write_gltf(dir, "data:image/jpg;base64," + base64_encode(png));
  const Scene inside = load_scene(dir.write("scene.json", scene_json("quad.gltf", "y")));
  EXPECT_TRUE(inside.objects[0].source->missing_images.empty());
  const PreparedScene prepared(inside);
  expect_color(point_below(prepared, 0.5, 0.5), 0, 1, 0);
  expect_color(point_below(prepared, -0.5, -0.5), 0, 0, 1);
  // A data URI that is not base64 is refused, naming the model and the image.
  write_gltf(dir, "data:image/png,not-base64");
  const std::string message =
      testing::input_error_of([&] { load_scene(dir.write("scene.json", scene_json("quad.gltf", "y"))); });
  EXPECT_NE(message.find("quad.gltf: image 0: a data URI that is not base64"), std::string::npos) << message;
}

}  // namespace
}  // namespace skylit
