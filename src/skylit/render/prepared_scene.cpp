#include "skylit/render/prepared_scene.h"

#include <cmath>

#include "skylit/atmosphere/seen_sun.h"
#include "skylit/core/angles.h"
#include "skylit/render/obstacle_materials.h"
#include "skylit/spectrum/rgb_spectrum_table.h"

namespace skylit {

PointMaterial::PointMaterial(const Material& material, const SurfacePoint& point) : material_(material) {
  if (point.has_color) textured_ = with_body_reflectance(material, rgb_spectrum_table().reflectance(point.color));
}

PreparedScene::PreparedScene(const Scene& scene)
    : scene_(scene),
      pixel_angle_rad_(radians(scene.camera.vertical_fov_deg) / std::max(scene.render.height, 1)),
      atmosphere_(scene.atmosphere),
      sky_(atmosphere_,
           SunRefraction(atmosphere_)
               .true_direction(direction_from_altitude_azimuth(scene.sun.altitude_deg, scene.sun.azimuth_deg)),
           scene.camera.position.z) {
  for (const SceneObject& object : scene.objects) {
    cutouts_.push_back(surface_cutouts_for(object, scene.materials));
    tracer_.add_mesh(object.mesh, cutouts_.back().get());
  }
  tracer_.commit();
  if (!scene.clouds.empty() || scene.cloud_layer) {
    const Vec3 below_camera{scene.camera.position.x, scene.camera.position.y, 0.0};
    clouds_ =
        std::make_unique<CloudsInSky>(scene.clouds, scene.cloud_layer, sky_, below_camera, scene.render.cloud_light);
  }
  // The scene's meshes, for the fog's and the lamps' shadow volumes.
  std::vector<const TriangleMesh*> meshes;
  for (const SceneObject& object : scene.objects) meshes.push_back(&object.mesh);
  if (scene.fog) fog_ = std::make_unique<FogMedium>(*scene.fog, meshes, tracer_, sky_, scene.camera.position);
  // Transmittance is largest in the red: a dark last bin means no sunbeam at all (the
  // sun below the horizon, or an overcast CIE sky's).
  if (!scene.fog && sky_.direct_sun(0.0)[kSpectralBins - 1] > 0.0f &&
      tracer_.triangle_count() <= kMaxShadowedAirTriangles)
    shadowed_air_ = std::make_unique<ShadowedAir>(meshes, sky_);
  if (!scene.lights.empty())
    lamps_ = std::make_unique<SceneLamps>(scene.lights, tracer_, meshes, fog_ ? &fog_->layer() : nullptr);
}

void PreparedScene::shade_smooth(const SceneObject& object, const Hit& hit, const Ray& ray, bool front,
                                 SurfacePoint& point) {
  const CornerNormals& normals = object.corner_normals[hit.triangle];
  const double b[3] = {1.0 - hit.u - hit.v, hit.u, hit.v};
  Vec3 shading{0, 0, 0};
  for (int i = 0; i < 3; ++i) shading += b[i] * Vec3{normals[i][0], normals[i][1], normals[i][2]};
  const double len = length(shading);
  if (!(len > 0)) return;
  shading = (front ? 1.0 : -1.0) * shading / len;
  // A shading normal turned away from the viewer would shade the visible side as its
  // back: keep the flat normal there (at silhouettes of coarse meshes).
  if (dot(shading, ray.direction) >= 0) return;
  point.normal = shading;
  if (!front) return;  // the lift is toward the outside the normals describe
  const auto& tri = object.mesh.triangles[hit.triangle];
  point.position =
      shading_point({object.mesh.vertices[tri[0]], object.mesh.vertices[tri[1]], object.mesh.vertices[tri[2]]}, normals,
                    hit.u, hit.v);
}

}  // namespace skylit

namespace skylit {
namespace {

// The change of texture coordinates along a step `d` within a triangle's plane: d
// written as a e1 + b e2 in the triangle's edges, then a Δuv1 + b Δuv2. Zero for a
// degenerate triangle.
std::array<double, 2> uv_change(const Vec3& e1, const Vec3& e2, const std::array<double, 4>& duv, const Vec3& d) {
  const double g11 = dot(e1, e1), g12 = dot(e1, e2), g22 = dot(e2, e2);
  const double det = g11 * g22 - g12 * g12;
  if (!(std::abs(det) > 1e-30)) return {0.0, 0.0};
  const double p1 = dot(d, e1), p2 = dot(d, e2);
  const double a = (g22 * p1 - g12 * p2) / det, b = (g11 * p2 - g12 * p1) / det;
  return {a * duv[0] + b * duv[2], a * duv[1] + b * duv[3]};
}

}  // namespace

void PreparedScene::appearance_at(const SurfaceAppearance& appearance, const SceneObject& object, const Hit& hit,
                                  const Ray& ray, SurfacePoint& point) const {
  const std::array<float, 3> mean_color = mean_base_color(appearance);
  Rgba color{mean_color[0], mean_color[1], mean_color[2], 1}, emission{1, 1, 1, 1};
  if (!object.corner_uvs.empty()) {
    const CornerUvs& uv = object.corner_uvs[hit.triangle];
    const auto& tri = object.mesh.triangles[hit.triangle];
    const Vec3& p0 = object.mesh.vertices[tri[0]];
    const Vec3 e1 = object.mesh.vertices[tri[1]] - p0, e2 = object.mesh.vertices[tri[2]] - p0;
    const std::array<double, 4> duv{uv[1][0] - uv[0][0], uv[1][1] - uv[0][1], uv[2][0] - uv[0][0], uv[2][1] - uv[0][1]};
    const double b1 = hit.u, b2 = hit.v, b0 = 1.0 - b1 - b2;
    const double u = b0 * uv[0][0] + b1 * uv[1][0] + b2 * uv[2][0];
    const double v = b0 * uv[0][1] + b1 * uv[1][1] + b2 * uv[2][1];
    // The pixel's footprint on the triangle's plane: its width r across the view, and
    // r / cos θ along it, where the plane is seen at an angle θ from its normal.
    const double length_dir = length(ray.direction);
    const Vec3 view = ray.direction / length_dir;
    const Vec3& n = hit.geometric_normal;
    const double r = hit.t * length_dir * pixel_angle_rad_;
    const double cos_view = std::max(std::abs(dot(n, view)), 1e-4);
    Vec3 across = cross(n, view);
    if (!(length(across) > 1e-9)) across = std::abs(n.x) < 0.9 ? cross(n, Vec3{1, 0, 0}) : cross(n, Vec3{0, 1, 0});
    across = normalize(across);
    const Vec3 along = normalize(cross(across, n));
    const auto a = uv_change(e1, e2, duv, r * across), b = uv_change(e1, e2, duv, (r / cos_view) * along);
    if (appearance.base_color) {
      const Rgba t = appearance.base_color->filtered(u, v, a[0], a[1], b[0], b[1]);
      for (size_t i = 0; i < 3; ++i) color[i] = static_cast<float>(appearance.base_color_factor[i]) * t[i];
    }
    if (appearance.emission) emission = appearance.emission->filtered(u, v, a[0], a[1], b[0], b[1]);
    if (appearance.normal_map) normal_mapped(appearance, object, hit, ray, {u, v, a[0], a[1], b[0], b[1]}, point);
  } else if (appearance.emission) {
    emission = appearance.emission->mean();
  }
  if (appearance.textured()) {
    point.has_color = true;
    point.color = {color[0], color[1], color[2]};
  }
  if (appearance.emissive()) {
    for (size_t i = 0; i < 3; ++i)
      point.emission_cd_m2[i] = static_cast<float>(appearance.emission_cd_m2[i]) * emission[i];
    point.emissive = point.emission_cd_m2[0] > 0 || point.emission_cd_m2[1] > 0 || point.emission_cd_m2[2] > 0;
  }
}

// The normal a tangent-space normal map gives (glTF 2.0 §3.9.3; MikkTSpace's frame):
// tangent T along increasing u and bitangent B toward the image's top row (decreasing v
// in our coordinates, increasing v in OpenGL's), both from the triangle's own texture
// coordinates (per triangle, not interpolated per corner as MikkTSpace does; the same on
// a flat or gently curved surface), made orthogonal to the interpolated normal N. The
// texel (r, g, b) gives n = normalize(s (2r − 1) T + s (2g − 1) B + (2b − 1) N).
// A mapped normal can lean so far that the viewer is below its horizon, or it below
// the surface; it is then bent toward the viewer, and toward the surface's side, just
// far enough to see the point at a grazing 0.01 (cosine), so that no point is shaded as
// its own back side and shadow rays leave on the lit side.
void PreparedScene::normal_mapped(const SurfaceAppearance& appearance, const SceneObject& object, const Hit& hit,
                                  const Ray& ray, const std::array<double, 6>& footprint, SurfacePoint& point) {
  const CornerUvs& uv = object.corner_uvs[hit.triangle];
  const auto& tri = object.mesh.triangles[hit.triangle];
  const Vec3& p0 = object.mesh.vertices[tri[0]];
  const Vec3 e1 = object.mesh.vertices[tri[1]] - p0, e2 = object.mesh.vertices[tri[2]] - p0;
  const double du1 = uv[1][0] - uv[0][0], dv1 = uv[1][1] - uv[0][1];
  const double du2 = uv[2][0] - uv[0][0], dv2 = uv[2][1] - uv[0][1];
  const double det = du1 * dv2 - dv1 * du2;
  if (!(std::abs(det) > 1e-20)) return;  // no texture mapping to take a frame from
  const Vec3 dp_du = (dv2 * e1 - dv1 * e2) / det, dp_dv = (du1 * e2 - du2 * e1) / det;
  // The normal on the outward (counter-clockwise) side, where the map's +z points.
  const bool front = dot(hit.geometric_normal, ray.direction) <= 0;
  const Vec3 n = front ? point.normal : -point.normal;
  Vec3 t = dp_du - dot(dp_du, n) * n;
  if (!(length(t) > 0)) return;
  t = normalize(t);
  Vec3 b = cross(n, t);
  if (dot(b, dp_dv) > 0) b = -b;  // toward decreasing v: the image's top
  const Rgba texel = appearance.normal_map->filtered(footprint[0], footprint[1], footprint[2], footprint[3],
                                                     footprint[4], footprint[5]);
  const double s = appearance.normal_scale;
  Vec3 mapped = s * (2.0 * texel[0] - 1.0) * t + s * (2.0 * texel[1] - 1.0) * b + (2.0 * texel[2] - 1.0) * n;
  if (!(length(mapped) > 0)) return;
  mapped = (front ? 1.0 : -1.0) * normalize(mapped);
  const Vec3 to_viewer = -normalize(ray.direction);
  const Vec3 surface_side = front ? hit.geometric_normal : -hit.geometric_normal;
  constexpr double kGrazing = 0.01;
  for (const Vec3& keep_above : {surface_side, to_viewer})
    if (const double c = dot(mapped, keep_above); c < kGrazing)
      mapped = normalize(mapped + (kGrazing - c) * keep_above);
  if (std::isfinite(mapped.x) && std::isfinite(mapped.y) && std::isfinite(mapped.z)) point.normal = mapped;
}

}  // namespace skylit
