// glTF's material models as real exporters write them, read onto skylit's kinds: the
// metalness and roughness of a metallicRoughnessTexture, the older specular-glossiness
// extension, and the warnings for what reads as the file's letter but not as its
// author meant (a textured material left a metal by the default metallicFactor, a
// texture on a coordinate set the mesh lacks). Found by rendering Khronos' sample
// models: BoxTextured and TextureCoordinateTest showed no texture at all.
#include <gtest/gtest.h>

#include "../test_support.h"
#include "gltf_quad_buffer.h"
#include "skylit/core/base64.h"
#include "skylit/io/image/image_encoders.h"
#include "skylit/io/model/mesh_io.h"
#include "skylit/material/model_material.h"

namespace skylit {
namespace {

using testing::TempDir;

// A data URI of a 2 × 2 PNG whose four texels are `rgb` (8-bit, row by row).
std::string png_uri(const std::array<uint8_t, 12>& rgb) {
  const Bytes png = encode_png_rgb8(2, 2, rgb);
  return "data:image/png;base64," + base64_encode(png);
}

std::string uniform_png_uri(uint8_t r, uint8_t g, uint8_t b) { return png_uri({r, g, b, r, g, b, r, g, b, r, g, b}); }

// A 2 m quad with TEXCOORD_0 and one material, `material` (a JSON object), whose
// textures refer to `images` (data URIs), texture i to image i.
LoadedModel load_quad(const TempDir& dir, const std::string& material, const std::vector<std::string>& images = {},
                      const std::string& extensions_required = "") {
  testing::write_quad_bin(dir);
  std::string textures, image_list;
  for (size_t i = 0; i < images.size(); ++i) {
    textures += (i ? ", " : "") + std::string(R"({"source": )") + std::to_string(i) + "}";
    image_list += (i ? ", " : "") + std::string(R"({"uri": ")") + images[i] + "\"}";
  }
  const std::string gltf = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0}],)" +
                           extensions_required +
                           R"(
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
    "materials": [)" + material +
                           R"(],
    "textures": [)" + textures +
                           R"(], "images": [)" + image_list +
                           R"(],
    "buffers": [{"uri": "quad.bin", "byteLength": 92}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                    {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 0, 1]},
                  {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                  {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}]})";
  return load_model_file(dir.write("quad.gltf", gltf), UpAxis::y);
}

// Blender writes a metallicRoughnessTexture with metallicFactor left out (1 by the
// spec): the texture's blue channel is the metalness, its green the roughness, each
// times its factor. One kind per material: the texture's mean decides.
TEST(GltfMaterialModels, MetalnessAndRoughnessComeFromTheTexturesMean) {
  TempDir dir;
  const std::string material =
      R"({"name": "Brick", "pbrMetallicRoughness": {"metallicRoughnessTexture": {"index": 0}}})";
  {
    SCOPED_TRACE("no metal in the texture, green 0.6 (linear: data, not colour)");
    const LoadedModel model = load_quad(dir, material, {uniform_png_uri(0, 153, 0)});
    ASSERT_EQ(model.materials.size(), 1u);
    EXPECT_EQ(model.materials[0].kind, ModelMaterial::Kind::coated);
    EXPECT_NEAR(model.materials[0].roughness, beckmann_from_gltf_roughness(0.6), 1e-6);
    EXPECT_TRUE(model.read_warnings.empty());
  }
  {
    SCOPED_TRACE("metal in one texel of four: mean 0.25, not metal");
    const LoadedModel model = load_quad(dir, material, {png_uri({0, 255, 255, 0, 255, 0, 0, 255, 0, 0, 255, 0})});
    EXPECT_EQ(model.materials[0].kind, ModelMaterial::Kind::coated);
    EXPECT_NEAR(model.materials[0].roughness, 1.0, 1e-6);
  }
  {
    SCOPED_TRACE("metal in three texels of four, metallicFactor 0.9: 0.675");
    const std::string factor = R"({"pbrMetallicRoughness": {"metallicFactor": 0.9, "roughnessFactor": 0.5,
                                   "metallicRoughnessTexture": {"index": 0}}})";
    const LoadedModel model = load_quad(dir, factor, {png_uri({0, 255, 255, 0, 255, 255, 0, 255, 255, 0, 255, 0})});
    EXPECT_EQ(model.materials[0].kind, ModelMaterial::Kind::metal);
    EXPECT_NEAR(model.materials[0].roughness, beckmann_from_gltf_roughness(0.5), 1e-6);
  }
}

// KHR_materials_pbrSpecularGlossiness: a dielectric's specular F0 gives the coat's
// index, n = (1 + √F0) / (1 − √F0) (F0 0.04: 1.5); a coloured specular beyond any
// dielectric's is a metal of that colour; roughness 1 − glossiness; the diffuse
// texture is the body's. Read also when the file requires it.
TEST(GltfMaterialModels, SpecularGlossinessBecomesACoatOrAMetal) {
  TempDir dir;
  const std::string required = R"( "extensionsUsed": ["KHR_materials_pbrSpecularGlossiness"],
    "extensionsRequired": ["KHR_materials_pbrSpecularGlossiness"],)";
  {
    const LoadedModel model =
        load_quad(dir, R"({"name": "Plaster", "extensions": {"KHR_materials_pbrSpecularGlossiness":
        {"diffuseFactor": [0.5, 0.4, 0.3, 1], "specularFactor": [0.09, 0.09, 0.09], "glossinessFactor": 0.8,
         "diffuseTexture": {"index": 0}}}})",
                  {uniform_png_uri(200, 100, 50)}, required);
    ASSERT_EQ(model.materials.size(), 1u);
    const ModelMaterial& m = model.materials[0];
    EXPECT_EQ(m.kind, ModelMaterial::Kind::coated);
    EXPECT_NEAR(m.ior, 1.3 / 0.7, 1e-9);  // √0.09 = 0.3
    EXPECT_NEAR(m.roughness, beckmann_from_gltf_roughness(0.2), 1e-9);
    EXPECT_NEAR(m.color_linear[0], 0.5, 1e-12);
    EXPECT_NEAR(m.color_linear[2], 0.3, 1e-12);
    EXPECT_TRUE(m.color_texture != nullptr);
    EXPECT_EQ(describe(m),
              "layered; colour 0.50 0.40 0.30 × texture; m 0.04; n 1.86; one-sided");  // glTF: single-sided by default
    EXPECT_TRUE(model.read_warnings.empty());
  }
  {
    const LoadedModel model = load_quad(dir, R"({"extensions": {"KHR_materials_pbrSpecularGlossiness":
        {"diffuseFactor": [0, 0, 0, 1], "specularFactor": [0.95, 0.64, 0.54], "glossinessFactor": 1}}})");
    const ModelMaterial& m = model.materials[0];
    EXPECT_EQ(m.kind, ModelMaterial::Kind::metal);
    EXPECT_NEAR(m.color_linear[0], 0.95, 1e-12);
    EXPECT_NEAR(m.color_linear[1], 0.64, 1e-12);
    EXPECT_NEAR(m.roughness, 0.0, 1e-12);
  }
}

// KHR_materials_unlit (no reflection model: baked light) reads as a matte body of its
// base colour, whatever its metallicFactor (Blender leaves the default 1), and is said.
TEST(GltfMaterialModels, UnlitMaterialsAreMatteAndSaidSo) {
  TempDir dir;
  const LoadedModel model = load_quad(dir, R"({"name": "Orange", "pbrMetallicRoughness":
      {"baseColorFactor": [1, 0.22, 0, 1]}, "extensions": {"KHR_materials_unlit": {}}})");
  EXPECT_EQ(model.materials[0].kind, ModelMaterial::Kind::diffuse);
  EXPECT_NEAR(model.materials[0].color_linear[1], 0.22, 1e-12);
  ASSERT_EQ(model.read_warnings.size(), 1u);
  EXPECT_NE(model.read_warnings[0].find("material 'Orange' (KHR_materials_unlit) read as matte"), std::string::npos)
      << model.read_warnings[0];
  // Without the extension the same material is the default's metal.
  const LoadedModel lit = load_quad(dir, R"({"pbrMetallicRoughness": {"baseColorFactor": [1, 0.22, 0, 1]}})");
  EXPECT_EQ(lit.materials[0].kind, ModelMaterial::Kind::metal);
}

// By the letter of glTF a material without metallicFactor is a metal, which skylit
// shows by its texture's mean colour: read so, but said.
TEST(GltfMaterialModels, ATexturedMaterialLeftAMetalByTheDefaultIsWarnedOf) {
  TempDir dir;
  const std::vector<std::string> image{uniform_png_uri(200, 100, 50)};
  const LoadedModel by_default =
      load_quad(dir, R"({"name": "Logo", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}})", image);
  EXPECT_EQ(by_default.materials[0].kind, ModelMaterial::Kind::metal);
  ASSERT_EQ(by_default.read_warnings.size(), 1u);
  EXPECT_NE(by_default.read_warnings[0].find("material 'Logo' gives no metallicFactor"), std::string::npos)
      << by_default.read_warnings[0];
  for (const char* given : {R"("metallicFactor": 1)", R"("metallicFactor": 0)"}) {
    SCOPED_TRACE(given);
    const LoadedModel model = load_quad(
        dir, std::string(R"({"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, )") + given + "}}", image);
    EXPECT_TRUE(model.read_warnings.empty());
  }
}

TEST(GltfMaterialModels, ATextureOnACoordinateSetTheMeshLacksIsWarnedOf) {
  TempDir dir;
  const LoadedModel model =
      load_quad(dir, R"({"name": "Sign", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "texCoord": 1},
              "metallicFactor": 0}})",
                {uniform_png_uri(200, 100, 50)});
  ASSERT_EQ(model.read_warnings.size(), 1u);
  EXPECT_NE(model.read_warnings[0].find("'Sign': its texture reads TEXCOORD_1"), std::string::npos)
      << model.read_warnings[0];
}

// alphaMode MASK with the factor's alpha below the cutoff and no texture to raise it:
// the whole material is a hole, and an object of it vanishes (the camera still frames
// it). Said, not refused: a file may mean it.
TEST(GltfMaterialModels, AMaterialCutAwayWholeIsWarnedOf) {
  TempDir dir;
  const auto masked = [&](double alpha) {
    return load_quad(dir, R"({"name": "Veil", "alphaMode": "MASK", "alphaCutoff": 0.5, "pbrMetallicRoughness":
        {"metallicFactor": 0, "baseColorFactor": [1, 1, 1, )" +
                              std::to_string(alpha) + "]}}");
  };
  const LoadedModel cut = masked(0.3);
  ASSERT_EQ(cut.read_warnings.size(), 1u);
  EXPECT_NE(cut.read_warnings[0].find("'Veil' is cut away whole"), std::string::npos) << cut.read_warnings[0];
  EXPECT_TRUE(masked(0.7).read_warnings.empty());
}

}  // namespace
}  // namespace skylit
