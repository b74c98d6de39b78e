// The `clouds` part of a scene file (docs/clouds.md): an array of clouds given one by
// one, or an object describing a generated layer.
#include <tuple>

#include "skylit/io/scene/scene_parts.h"

namespace skylit {

namespace {

// Two numbers [x, y] in metres.
std::pair<double, double> read_xy(const JsonReader& j) {
  const auto xy = j.elements();
  if (xy.size() != 2) j.fail_expected("[x, y] in metres");
  return {xy[0].number_in(-kSceneExtentM, kSceneExtentM), xy[1].number_in(-kSceneExtentM, kSceneExtentM)};
}

CloudShape read_cloud(const JsonReader& j) {
  j.allow_only({"center_m", "altitude_m", "semi_axes_m", "rotation_deg", "max_thickness_m", "falloff",
                "extinction_per_m", "seed"});
  CloudShape c;
  std::tie(c.center_x, c.center_y) = read_xy(j.required("center_m"));
  c.altitude = j.required("altitude_m").number_in(0, 20000);
  const auto axes = j.required("semi_axes_m").elements();
  if (axes.size() != 2) j.required("semi_axes_m").fail_expected("[a, b] in metres");
  c.semi_axis_a = axes[0].number_in(1, 1e5);
  c.semi_axis_b = axes[1].number_in(1, 1e5);
  if (auto r = j.optional("rotation_deg")) c.rotation = radians(r->number_in(-360, 360));
  if (auto t = j.optional("max_thickness_m")) c.max_thickness = t->number_in(0, 10000);
  if (auto p = j.optional("falloff")) c.falloff_exponent = p->number_in(0.05, 10);
  if (auto e = j.optional("extinction_per_m")) c.extinction = e->number_in(0, 10);
  const int seed = j.optional("seed") ? j.required("seed").integer_in(0, 1 << 30) : 1;
  add_gardner_waves(c, static_cast<std::uint64_t>(seed));
  return c;
}

CloudLayerSettings read_layer(const JsonReader& j) {
  j.allow_only({"altitude_m", "coverage", "seed", "center_m", "half_extent_m", "min_semi_axis_m", "max_semi_axis_m",
                "min_thickness_m", "max_thickness_m", "extinction_per_m"});
  CloudLayerSettings s;
  s.altitude = j.required("altitude_m").number_in(0, 20000);
  s.coverage = j.required("coverage").number_in(0, 1);
  if (auto seed = j.optional("seed")) s.seed = static_cast<std::uint64_t>(seed->integer_in(0, 1 << 30));
  if (auto c = j.optional("center_m")) std::tie(s.center_x, s.center_y) = read_xy(*c);
  if (auto h = j.optional("half_extent_m")) s.half_extent = h->number_in(10, 1e5);
  if (auto v = j.optional("min_semi_axis_m")) s.min_semi_axis = v->number_in(1, 1e5);
  if (auto v = j.optional("max_semi_axis_m")) s.max_semi_axis = v->number_in(1, 1e5);
  if (s.max_semi_axis < s.min_semi_axis) j.fail("max_semi_axis_m must not be below min_semi_axis_m");
  if (auto v = j.optional("min_thickness_m")) s.min_thickness = v->number_in(0, 10000);
  if (auto v = j.optional("max_thickness_m")) s.max_thickness = v->number_in(0, 10000);
  if (s.max_thickness < s.min_thickness) j.fail("max_thickness_m must not be below min_thickness_m");
  if (auto e = j.optional("extinction_per_m")) s.extinction = e->number_in(0, 10);
  if (const double n = expected_generated_cloud_count(s); n > static_cast<double>(kMaxGeneratedClouds))
    j.fail("this layer would hold about " + std::to_string(static_cast<long long>(n)) + " clouds, over the limit of " +
           std::to_string(kMaxGeneratedClouds) +
           " (each cloud seen needs its own table of sunlight, 0.4 MB and about a tenth of a second): "
           "raise min_semi_axis_m or max_semi_axis_m, or lower half_extent_m or coverage");
  return s;
}

}  // namespace

void read_clouds(const JsonReader& j, Scene& scene) {
  if (j.is_array()) {
    for (const JsonReader& c : j.elements()) scene.clouds.push_back(read_cloud(c));
  } else if (j.is_object()) {
    scene.cloud_layer = read_layer(j);
  } else {
    j.fail_expected("an array of clouds or an object describing a cloud layer");
  }
}

}  // namespace skylit
