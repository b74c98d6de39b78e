// The `fog` part of a scene file: a fog layer near the ground (docs/fog.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "skylit/core/error.h"
#include "skylit/io/scene/scene_parts.h"
#include "skylit/media/fog_layer.h"

namespace skylit {

namespace {

// The densest fog a scene may hold, as extinction at its densest point: 10 m⁻¹ is a
// visibility of 0.4 m (Koschmieder), a hundred times the thickest natural fog (about
// 0.1 m⁻¹, 40 m). Past it the density law ρ0·exp(−z/h0) overflows inside the layer (a
// scale height of −0.001 m, a layer far below the ground) and the light it scatters
// becomes Inf or NaN (issue 19, item 4).
constexpr double kMaxFogExtinctionPerM = 10.0;
// And the density itself, whatever the extinction per unit density (0 included): the
// most density_at_ground may be. A density of 1e51 with τ0 = 0 still made NaN pixels
// (found by tests/render/extreme_scenes_test.cpp).
constexpr double kMaxFogDensity = 1e6;

void check_densest_point(const FogLayer& layer, const JsonReader& j) {
  const double densest = std::max(layer.density(layer.bottom_m()), layer.density(layer.top_m()));
  double sigma = 0;
  for (const double s : layer.unit_density_extinction_bins()) sigma = std::max(sigma, s);
  const bool too_dense = !(densest <= kMaxFogDensity);
  if (!too_dense && densest * sigma <= kMaxFogExtinctionPerM) return;
  char shown[48];
  std::snprintf(shown, sizeof shown, "%.3g", too_dense ? densest : densest * sigma);
  j.fail(std::string("the fog's ") + (too_dense ? "density" : "extinction") + " at its densest point (the layer's " +
         (layer.density(layer.bottom_m()) >= layer.density(layer.top_m()) ? "bottom" : "top") + ") would be " + shown +
         (too_dense ? ", over the limit of 1e6" : " per metre, over the limit of 10 (a visibility of 0.4 m)") +
         ": lower density_at_ground or unit_density_extinction_per_m, or move the layer or its scale_height_m");
}

}  // namespace

FogSettings read_fog(const JsonReader& j) {
  j.allow_only({"density_at_ground", "visibility_m", "scale_height_m", "bottom_m", "top_m",
                "unit_density_extinction_per_m", "reference_wavelength_nm", "wavelength_exponent",
                "single_scattering_albedo", "phase", "droplet_diameter_um", "asymmetry", "multiple_scattering"});
  FogSettings fog;
  if (j.has("density_at_ground") && j.has("visibility_m")) j.fail("give density_at_ground or visibility_m, not both");
  if (auto d = j.optional("density_at_ground")) fog.density_at_ground = d->number_in(0, 1e6);
  if (auto v = j.optional("visibility_m")) fog.ground_visibility_m = v->number_in(1, 1e6);
  if (auto h = j.optional("scale_height_m")) {
    fog.scale_height_m = h->number_in(-1e6, 1e6);
    if (fog.scale_height_m == 0) h->fail_expected("a scale height other than 0 (negative: denser upward)");
  }
  if (auto b = j.optional("bottom_m")) fog.bottom_altitude_m = b->number_in(-1e4, 1e5);
  if (auto t = j.optional("top_m")) fog.top_altitude_m = t->number_in(-1e4, 1e5);
  if (!(fog.top_altitude_m > fog.bottom_altitude_m)) j.fail("top_m must be above bottom_m");
  if (auto t = j.optional("unit_density_extinction_per_m")) fog.unit_density_extinction_per_m = t->number_in(0, 1e3);
  if (auto l = j.optional("reference_wavelength_nm")) fog.reference_wavelength_nm = l->number_in(300, 1000);
  if (auto b = j.optional("wavelength_exponent")) fog.wavelength_exponent = b->number_in(-4, 4);
  if (auto a = j.optional("single_scattering_albedo")) fog.single_scattering_albedo = a->number_in(0, 1);
  if (auto p = j.optional("phase"))
    fog.phase = p->one_of({"droplet_fit", "henyey_greenstein"}) == "droplet_fit" ? FogPhase::droplet_fit
                                                                                 : FogPhase::henyey_greenstein;
  if (auto d = j.optional("droplet_diameter_um")) fog.droplet_diameter_um = d->number_in(5, 50);
  if (auto g = j.optional("asymmetry")) fog.asymmetry = g->number_in(-0.99, 0.99);
  if (auto m = j.optional("multiple_scattering")) fog.multiple_scattering = m->boolean();
  // The layer checks the rest (and names the field) when it is built.
  std::optional<FogLayer> layer;
  try {
    layer.emplace(fog);
  } catch (const InputError& e) {
    j.fail(e.what());
  }
  check_densest_point(*layer, j);
  return fog;
}

}  // namespace skylit
