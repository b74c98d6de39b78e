// Materials in scene files: presets by name, presets with values replaced, the new
// types, and the errors a user can make, each naming its JSON path.
#include <gtest/gtest.h>

#include "../test_support.h"

#include <string>

#include "skylit/core/error.h"
#include "skylit/io/scene/scene_parts.h"
#include "skylit/material/presets.h"
#include "skylit/material/reflection.h"
#include "skylit/spectrum/cie.h"
#include "skylit/spectrum/color_space.h"

namespace skylit {
namespace {

std::vector<NamedMaterial> read(const std::string& materials_json) {
  const nlohmann::json json = parse_json_text(materials_json, "scene.json");
  return read_materials(JsonReader(json, "scene.json", "materials"));
}

Material read_one(const std::string& material_json) {
  return read("{\"walls\": " + material_json + "}").at(0).material;
}

// The message of the InputError that reading `material_json` as materials.walls throws.
std::string error_of(const std::string& material_json) {
  return testing::input_error_of([&] { read_one(material_json); });
}

const Vec3 kNormal{0, 0, 1};

TEST(Preset, EveryPresetLoadsByName) {
  for (const MaterialPreset& preset : material_presets()) {
    SCOPED_TRACE(std::string(preset.name));
    // Appended, not `"\"" + std::string(...)`: that trips GCC 12's false -Wrestrict (bug 105329).
    const Material m = read_one(std::string("\"").append(preset.name).append("\""));
    // Every preset reflects something and no more than it receives at normal view.
    const double albedo = diffuse_albedo(m, 1.0).max_value();
    EXPECT_LE(albedo, 1.0);
    EXPECT_TRUE(albedo > 0 || has_specular(m));
  }
  EXPECT_EQ(material_preset_names(), "tile, aluminium, glass, concrete, asphalt, grass");
}

TEST(Preset, ValuesAreTheDocumentedOnes) {
  const auto aluminium = std::get<CookTorranceMaterial>(read_one("\"aluminium\""));
  EXPECT_DOUBLE_EQ(aluminium.roughness(), 0.15);
  EXPECT_TRUE(aluminium.ior().is_conductor());
  const auto tile = std::get<CookTorranceMaterial>(read_one("\"tile\""));
  EXPECT_DOUBLE_EQ(tile.roughness(), 0.2);
  EXPECT_FLOAT_EQ(tile.ior().n[10], 1.5f);
  const auto glass = std::get<GlassMaterial>(read_one("\"glass\""));
  EXPECT_TRUE(glass.is_mirror());
  EXPECT_DOUBLE_EQ(glass.thickness_m(), 0.006);
  EXPECT_FLOAT_EQ(glass.interior_reflectance()[20], 0.05f);
  EXPECT_FLOAT_EQ(std::get<DiffuseMaterial>(read_one("\"concrete\"")).reflectance[20], 0.35f);
  EXPECT_FLOAT_EQ(std::get<DiffuseMaterial>(read_one("\"asphalt\"")).reflectance[20], 0.08f);
}

TEST(Preset, GrassIsGreenAndDark) {
  // Under an equal-energy light: luminous reflectance Y and linear sRGB.
  const Spectrum grass = std::get<DiffuseMaterial>(read_one("\"grass\"")).reflectance;
  const Xyz c = xyz_from_spectrum(grass), white = xyz_from_spectrum(Spectrum(1.0f));
  const double y = c.y / white.y;
  std::printf("grass: luminous reflectance Y = %.3f\n", y);
  EXPECT_NEAR(y, 0.13, 0.01);
  const Rgb rgb = linear_srgb_from_xyz(c);
  EXPECT_GT(rgb[1], rgb[0]);
  EXPECT_GT(rgb[1], rgb[2]);
}

TEST(Preset, TileHasASmallSpecularPart) {
  const Material tile = read_one("\"tile\"");
  const Vec3 v{0, -std::sin(0.5), std::cos(0.5)};
  EXPECT_NEAR(specular_weight(tile, kNormal, mirror_direction(kNormal, v), v) /
                  specular_weight(read_one("\"aluminium\""), kNormal, mirror_direction(kNormal, v), v),
              0.04 / 0.92 * (0.15 * 0.15) / (0.2 * 0.2), 0.01);
  EXPECT_GT(diffuse_albedo(tile, 1.0).max_value(), 0.3);
}

TEST(Preset, OverridesReplaceTheGivenValues) {
  const auto al = std::get<CookTorranceMaterial>(read_one(R"({"preset": "aluminium", "roughness": 0.1})"));
  EXPECT_DOUBLE_EQ(al.roughness(), 0.1);
  EXPECT_TRUE(al.ior().is_conductor());
  // Giving an index replaces the preset's metal.
  const auto coated = std::get<CookTorranceMaterial>(read_one(R"({"preset": "aluminium", "ior": 1.6})"));
  EXPECT_FALSE(coated.ior().is_conductor());
  EXPECT_FLOAT_EQ(coated.ior().n[0], 1.6f);
  const auto glass = std::get<GlassMaterial>(read_one(R"({"preset": "glass", "interior_reflectance": 0.1})"));
  EXPECT_FLOAT_EQ(glass.interior_reflectance()[3], 0.1f);
  EXPECT_DOUBLE_EQ(glass.thickness_m(), 0.006);
  const auto concrete = std::get<DiffuseMaterial>(read_one(R"({"preset": "concrete", "reflectance": 0.25})"));
  EXPECT_FLOAT_EQ(concrete.reflectance[3], 0.25f);
}

TEST(Preset, UnknownPresetListsTheKnownOnes) {
  EXPECT_EQ(error_of("\"marble\""),
            "scene.json: materials.walls: unknown material preset 'marble'; known presets: "
            "tile, aluminium, glass, concrete, asphalt, grass");
  EXPECT_EQ(error_of(R"({"preset": "steel"})"),
            "scene.json: materials.walls.preset: unknown material preset 'steel'; known presets: "
            "tile, aluminium, glass, concrete, asphalt, grass");
}

TEST(Preset, BadOverridesNameTheirPath) {
  EXPECT_EQ(error_of(R"({"preset": "aluminium", "roughness": 2})"),
            "scene.json: materials.walls.roughness: expected a number from 0 to 1, found 2");
  EXPECT_EQ(error_of(R"({"preset": "concrete", "roughness": 0.1})"),
            "scene.json: materials.walls.roughness: unknown key; expected one of: preset, reflectance");
  EXPECT_EQ(error_of(R"({"preset": "glass", "ior": 1.5, "dielectric": "glass"})"),
            "scene.json: materials.walls: give only one of ior, dielectric");
  EXPECT_EQ(error_of(R"({"preset": "tile", "type": "diffuse"})"),
            "scene.json: materials.walls.type: give either type or preset, not both");
  EXPECT_EQ(error_of(R"({"preset": "aluminium", "diffuse_reflectance": 0.3})"),
            "scene.json: materials.walls.diffuse_reflectance: a metal has no diffuse base: diffuse_reflectance "
            "needs a dielectric (ior or dielectric)");
  EXPECT_EQ(error_of("3"),
            "scene.json: materials.walls: expected a material: an object with a type, a preset's name (tile, "
            "aluminium, glass, concrete, asphalt, grass), or {\"preset\": name, …}, found 3");
}

TEST(MaterialReader, CookTorranceTakesAMetalAnIorOrADielectric) {
  const auto al =
      std::get<CookTorranceMaterial>(read_one(R"({"type": "cook_torrance", "roughness": 0.2, "metal": "aluminium"})"));
  EXPECT_TRUE(al.ior().is_conductor());
  const auto custom = std::get<CookTorranceMaterial>(read_one(
      R"({"type": "cook_torrance", "roughness": 0.2, "metal": {"wavelength_nm": [400, 700], "n": [1, 2], "k": 7}})"));
  EXPECT_NEAR(custom.ior().n[0], 1.0, 0.02);    // held below 400 nm
  EXPECT_NEAR(custom.ior().n[15], 1.45, 1e-3);  // 530–540 nm: linear between, 1 + 135/300
  EXPECT_FLOAT_EQ(custom.ior().k[39], 7.0f);
  const auto constant = std::get<CookTorranceMaterial>(
      read_one(R"({"type": "cook_torrance", "roughness": 0.2, "metal": {"n": 1.2, "k": 7}})"));
  EXPECT_FLOAT_EQ(constant.ior().k[5], 7.0f);
  const auto paint = std::get<CookTorranceMaterial>(
      read_one(R"({"type": "cook_torrance", "roughness": 0.3, "ior": 1.5, "diffuse_reflectance": [0.8, 0.1, 0.1]})"));
  EXPECT_TRUE(paint.has_diffuse());
  const auto glassy = std::get<CookTorranceMaterial>(
      read_one(R"({"type": "cook_torrance", "roughness": 0.05, "dielectric": "glass"})"));
  EXPECT_NEAR(glassy.ior().n[17], 1.516, 0.002);
}

TEST(MaterialReader, LayeredAndGlassHaveDefaults) {
  const auto layered = std::get<CookTorranceMaterial>(read_one(R"({"type": "layered", "reflectance": 0.5})"));
  EXPECT_FLOAT_EQ(layered.ior().n[0], 1.5f);
  EXPECT_DOUBLE_EQ(layered.roughness(), 0.2);
  const auto glass = std::get<GlassMaterial>(read_one(R"({"type": "glass"})"));
  EXPECT_TRUE(glass.is_mirror());
  EXPECT_DOUBLE_EQ(glass.thickness_m(), 0.006);
  EXPECT_FLOAT_EQ(glass.interior_reflectance()[0], 0.05f);
  EXPECT_NEAR(glass.ior().n[17], 1.516, 0.002);
}

TEST(MaterialReader, MistakesNameTheirPath) {
  EXPECT_EQ(
      error_of(R"({"type": "cook_torrance", "roughness": 0.2})"),
      "scene.json: materials.walls: missing the interface's refractive index: give one of metal, ior, dielectric");
  EXPECT_EQ(error_of(R"({"type": "cook_torrance", "roughness": 0.2, "metal": "aluminium", "ior": 1.5})"),
            "scene.json: materials.walls: give only one of metal, ior, dielectric");
  EXPECT_EQ(error_of(R"({"type": "cook_torrance", "roughness": 0.2, "metal": "steel"})"),
            "scene.json: materials.walls.metal: expected one of: aluminium, found \"steel\"");
  EXPECT_EQ(error_of(R"({"type": "cook_torrance", "metal": "aluminium"})"),
            "scene.json: materials.walls: missing required key 'roughness'");
  EXPECT_EQ(
      error_of(
          R"({"type": "cook_torrance", "roughness": 0.2, "metal": {"wavelength_nm": [400, 700], "n": [1], "k": 7}})"),
      "scene.json: materials.walls.metal.n: needs as many values as wavelength_nm has (2)");
  EXPECT_EQ(
      error_of(
          R"({"type": "cook_torrance", "roughness": 0.2, "metal": {"wavelength_nm": [700, 400], "n": 1, "k": [7, 6]}})"),
      "scene.json: materials.walls.metal.wavelength_nm[1]: wavelengths must increase");
  EXPECT_EQ(error_of(R"({"type": "glass", "thickness_mm": -1})"),
            "scene.json: materials.walls.thickness_mm: expected a number from 0 to 100, found -1");
  EXPECT_EQ(error_of(R"({"type": "glass", "dielectric": "quartz"})"),
            "scene.json: materials.walls.dielectric: expected one of: glass, found \"quartz\"");
  EXPECT_EQ(error_of(R"({"type": "layered", "reflectance": 0.5, "metal": "aluminium"})"),
            "scene.json: materials.walls.metal: unknown key; expected one of: type, reflectance, roughness, ior, "
            "dielectric");
  EXPECT_EQ(error_of(R"({"type": "plastic"})"),
            "scene.json: materials.walls.type: expected one of: diffuse, cook_torrance, layered, glass, road, found "
            "\"plastic\"");
  EXPECT_EQ(error_of(R"({"type": "road", "r_table": "R5"})"),
            "scene.json: materials.walls.r_table: unknown r-table 'R5'; known: R1, R2, R3, R4, C1, C2");
  EXPECT_EQ(error_of(R"({"type": "road", "r_table": "R3", "q0": 0.5})"),
            "scene.json: materials.walls.q0: expected a number from 0.01 to 0.3, found 0.5");
  EXPECT_EQ(error_of(R"({"type": "road", "q0": 0.07})"), "scene.json: materials.walls: missing required key 'r_table'");
}

}  // namespace
}  // namespace skylit
