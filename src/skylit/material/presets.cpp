// The material presets as scene-file JSON; docs/materials.md gives each value's source.
#include "skylit/material/presets.h"

namespace skylit {

namespace {

// ColorChecker patch 4 "foliage", which McCamy, Marcus & Davidson (1976) made to
// match the reflectance of green leaves: N. Ohta's (1997) measurement at 5 nm, as
// tabulated in the colour-science library (colour/characterisation/datasets/
// colour_checkers/sds.py, DATA_COLORCHECKER_N_OHTA). Luminous reflectance Y ≈ 0.13.
constexpr std::string_view kGrass = R"({"type": "diffuse", "reflectance": {"spectrum": {
  "wavelength_nm": [
    380, 385, 390, 395, 400, 405, 410, 415, 420, 425, 430, 435, 440, 445, 450, 455, 460,
    465, 470, 475, 480, 485, 490, 495, 500, 505, 510, 515, 520, 525, 530, 535, 540, 545,
    550, 555, 560, 565, 570, 575, 580, 585, 590, 595, 600, 605, 610, 615, 620, 625, 630,
    635, 640, 645, 650, 655, 660, 665, 670, 675, 680, 685, 690, 695, 700, 705, 710, 715,
    720, 725, 730, 735, 740, 745, 750, 755, 760, 765, 770, 775, 780
  ],
  "value": [
    0.048, 0.049, 0.049, 0.049, 0.050, 0.049, 0.049, 0.050, 0.050, 0.051, 0.052, 0.053, 0.054, 0.056,
    0.058, 0.060, 0.061, 0.063, 0.064, 0.065, 0.067, 0.068, 0.070, 0.072, 0.078, 0.088, 0.106, 0.130,
    0.155, 0.173, 0.181, 0.182, 0.177, 0.168, 0.157, 0.147, 0.137, 0.129, 0.126, 0.125, 0.122, 0.119,
    0.115, 0.109, 0.104, 0.100, 0.098, 0.097, 0.098, 0.100, 0.100, 0.099, 0.097, 0.096, 0.095, 0.095,
    0.095, 0.097, 0.101, 0.110, 0.125, 0.147, 0.174, 0.210, 0.247, 0.283, 0.311, 0.329, 0.343, 0.353,
    0.358, 0.362, 0.364, 0.360, 0.362, 0.364, 0.368, 0.368, 0.355, 0.346, 0.341
  ]}}})";

}  // namespace

const std::vector<MaterialPreset>& material_presets() {
  static const std::vector<MaterialPreset> presets = {
      // A beige glazed ceramic tile (the paper's Fig. 7 a–c): a Lambertian body
      // under a glaze of n = 1.5 with a semi-matt finish.
      {"tile", R"({"type": "layered", "reflectance": {"srgb": [0.72, 0.58, 0.45]}, "ior": 1.5, "roughness": 0.2})"},
      // Sheet aluminium cladding (Fig. 7 d–f): Rakić's (1995) optical constants, the
      // satin finish of rolled or brushed sheet.
      {"aluminium", R"({"type": "cook_torrance", "metal": "aluminium", "roughness": 0.15})"},
      // A 6 mm single pane of float glass (Vogt et al. 2016), a dark room behind.
      {"glass",
       R"({"type": "glass", "dielectric": "glass", "thickness_mm": 6, "roughness": 0, "interior_reflectance": 0.05})"},
      // New grey Portland-cement concrete, solar reflectance 0.35–0.40 (US EPA 2008).
      {"concrete", R"({"type": "diffuse", "reflectance": 0.35})"},
      // Asphalt road: 0.05 new, 0.10–0.15 aged (US EPA 2008).
      {"asphalt", R"({"type": "diffuse", "reflectance": 0.08})"},
      {"grass", kGrass},
  };
  return presets;
}

const MaterialPreset* find_material_preset(std::string_view name) {
  for (const MaterialPreset& p : material_presets())
    if (p.name == name) return &p;
  return nullptr;
}

std::string material_preset_names() {
  std::string out;
  for (const MaterialPreset& p : material_presets()) out += (out.empty() ? "" : ", ") + std::string(p.name);
  return out;
}

}  // namespace skylit
