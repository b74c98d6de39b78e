// A scene as the renderer sees it: everything in SI units in the world frame
// (x east, y north, z up, metres), already validated by the loader (io/scene_loader.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "skylit/atmosphere/atmosphere_settings.h"
#include "skylit/clouds/cloud_layer.h"
#include "skylit/core/vec3.h"
#include "skylit/geometry/triangle_mesh.h"
#include "skylit/geometry/vertex_normals.h"
#include "skylit/lights/luminaire.h"
#include "skylit/material/material.h"
#include "skylit/media/fog_settings.h"
#include "skylit/scene/output_settings.h"
#include "skylit/scene/road_lighting_settings.h"
#include "skylit/scene/weather_summary.h"
#include "skylit/sun/solar_position.h"

namespace skylit {

// How far from the site (metres, on every axis) anything placed in a scene may be:
// 10,000 km, past any city or horizon. Embree holds coordinates in single precision, and
// lengths and products of far larger numbers overflow; scene readers check each placed
// point where it is read (issue 19, items 7 and 17).
inline constexpr double kSceneExtentM = 1e7;

// The most pixels a frame may have: 8K UHD, 7680 × 4320. The renderer holds about 300
// bytes per pixel (measured at 1280 × 720 with fog and lamps: the primary hits, the
// film, the caches), so this is about 10 GB; 16384 × 16384 would need 80 GB and was
// accepted (issue 19, item 10). Either side may still be up to 16384 (panoramas).
inline constexpr long long kMaxRenderPixels = 7680LL * 4320LL;

// How directions around the camera map onto the image (docs/scene-format.md, "camera";
// render/camera.h has the formulas). θ is the angle from the viewing direction.
enum class Projection {
  perspective,            // a pinhole: planar, straight lines stay straight
  fisheye_equidistant,    // angular fisheye: the distance from the centre ∝ θ (Radiance -vta)
  fisheye_equisolid,      // equal-area fisheye: ∝ sin(θ/2)
  fisheye_hemispherical,  // orthographic fisheye: ∝ sin θ (Radiance -vth)
  cylindrical,            // panorama: azimuth linear across, perspective up and down (Radiance -vtc)
  equirectangular,        // azimuth and elevation both linear: a full sphere in a 2:1 image
};

struct Camera {
  Vec3 position;
  Vec3 look_at;
  Vec3 up{0, 0, 1};
  // The angle the image's height spans (perspective, cylindrical: tan-spaced; fisheyes:
  // the image circle across the height; equirectangular: elevation).
  double vertical_fov_deg = 50.0;
  Projection projection = Projection::perspective;
  // cylindrical and equirectangular: the azimuth the image's width spans.
  double horizontal_fov_deg = 360.0;
  // perspective: lens shift, the image moved right and up by these fractions of its
  // width and height (Radiance -vs, -vl), for verticals that stay vertical.
  double shift_x = 0, shift_y = 0;
};

// Where the sun stands, seen from the site: given directly, or computed from the
// site and the time (io/scene_loader.cpp, NREL SPA).
struct Sun {
  double altitude_deg = 45.0;  // apparent, above the horizon
  double azimuth_deg = 180.0;  // clockwise from north
};

// How each pixel's light is found: the paper's fast, noise-free method, or the
// spectral Monte Carlo reference that every fast path is checked against.
enum class Integrator { bands, path };

struct RenderSettings {
  int width = 1280;
  int height = 720;
  std::optional<double> exposure_ev;  // empty: automatic (io/image/exposure_meter.h)
  int samples_per_axis = 2;           // bands: a regular grid of n × n samples per pixel
  Integrator integrator = Integrator::bands;
  int samples_per_pixel = 64;  // path: paths per pixel, at random places in it
  uint64_t seed = 1;           // path: which random numbers (the same seed, the same bytes)
  // bands: the clouds' multiple scattering by the two-stream slab, or the paper's Eq. 16
  // as printed (clouds/cloud_scattering.h)
  CloudLightModel cloud_light = CloudLightModel::two_stream;
  FalseColourSettings false_colour{};  // for *.falsecolor.png outputs
  bool exr_layers = false;             // .exr: add object, distance and normal layers
  bool human_display = false;          // .png: as a person would see it (io/image/human_display.h)
  // bands: obstacles in the sky light lit by the sky they see themselves, with the
  // bounces between them (render/obstacle_sky_light.h; within 3 % of the path tracer in
  // street canyons), or by the open sky ("open_sky", the paper's one bounce: shaded
  // walls across narrow streets 1.2–12 times too bright, for about 1/1.4 of the frame).
  bool obstacles_own_sky = true;
};

// Where a mesh object came from and what loading did to it (`skylit info`).
struct ModelSource {
  std::string file;
  char up_axis = 'z';  // the file's up axis as read: 'y' or 'z'
  std::string units = "m";
  Vec3 offset_m{0, 0, 0};  // the shift added by `center` and `place_on_ground`
  struct MaterialUse {
    std::string file_name;  // as the file names it
    std::string became;     // the scene material's name and kind
    bool overridden = false;
  };
  std::vector<MaterialUse> materials;
  std::vector<std::string> missing_libraries, missing_images;
  int skipped_primitives = 0;              // glTF points and lines, not drawn
  std::vector<std::string> read_warnings;  // LoadedModel::read_warnings
};

// Where a city model came from and how it was placed (`skylit info`).
struct CitySource {
  std::string file;
  std::string crs;
  // The local frame's origin, WGS 84 (the site; or the model's centre, which then
  // became the site), and the height that became z = 0 (the model's ground level).
  double latitude_deg = 0, longitude_deg = 0, ground_height_m = 0;
  bool site_from_model = false;
  bool curvature_applied = false;
  bool axes_swapped = false;                                    // PlacedCity::axes_swapped
  bool axes_swapped_by_format = false;                          // PlacedCity::axes_swapped_by_format
  std::vector<std::pair<std::string, size_t>> objects_by_type;  // city objects placed
  struct ClassUse {
    std::string name;  // "Building.RoofSurface"
    size_t triangles = 0;
    std::string material;  // the scene material's name
  };
  std::vector<ClassUse> classes;
  size_t objects_outside_region = 0;
  size_t degenerate_surfaces = 0;
  // Triangles that took the file's appearance (a material or texture of its theme), and
  // the texture images it names that were not found (their surfaces keep the palette).
  std::string appearance_theme;
  size_t appearance_triangles = 0;
  std::vector<std::string> missing_texture_images;
  // The terrain DEM, if any, said for skylit info (its file, cells, resampling, height
  // unit), and what looks wrong about it (placed far from the model, a unit not known).
  std::string terrain;
  std::vector<std::string> terrain_warnings;
};

struct SceneObject {
  std::string name;
  TriangleMesh mesh;        // in world coordinates
  uint32_t material_index;  // into Scene::materials, for every triangle unless...
  // ...a material per triangle is given (a model file's own materials), into
  // Scene::materials; empty otherwise.
  std::vector<uint32_t> triangle_materials{};
  // Smooth shading normals at each triangle's corners (geometry/vertex_normals.h);
  // empty: shaded flat with the geometric normal.
  std::vector<CornerNormals> corner_normals{};
  // Texture coordinates at each triangle's corners, for materials with textures; empty
  // when the file gives none.
  std::vector<CornerUvs> corner_uvs{};
  std::optional<ModelSource> source{};  // for mesh files
  std::optional<CitySource> city{};     // for city models

  uint32_t material_of(uint32_t triangle) const {
    return triangle_materials.empty() ? material_index : triangle_materials[triangle];
  }
};

// A luminaire (§7, Fig. 9): where it is, its intensity distribution in absolute
// candela, and its lamp's spectrum per candela (lights/lamp_spectrum.h), so that
// luminaire.intensity(direction) × spectrum_per_candela is the spectral radiant
// intensity toward that direction in W sr⁻¹ nm⁻¹.
struct SceneLight {
  std::string name;
  Luminaire luminaire;
  Spectrum spectrum_per_candela;
  // Where its photometry came from, for skylit info: the file and its format and rated
  // lumens, or the shape ("'road.ies' (LM-63-2002, lamps rated 12000 lm)", "spot shape").
  std::string source{};
};

struct Scene {
  Camera camera;
  Sun sun;
  // Where and when, when the scene gives them or a city model or weather file does (for
  // reports, docs/report.md; sun studies place the sun from the site).
  std::optional<SiteLocation> site;
  std::string time;  // as the scene wrote it (ISO 8601 with its offset); empty: none
  // The air; its site_elevation_m and earth_sun_distance_au come from `site` and `time`.
  AtmosphereSettings atmosphere;
  // A fog layer near the ground (§3.2, §5), if any.
  std::optional<FogSettings> fog;
  // Clouds (§6): given one by one, and/or a generated layer.
  std::vector<CloudShape> clouds;
  std::optional<CloudLayerSettings> cloud_layer;
  std::vector<NamedMaterial> materials;
  std::vector<SceneObject> objects;
  std::vector<SceneLight> lights;
  RenderSettings render;
  // How many `material_overrides` patterns the scene gives, and those that matched no
  // material of any file (a typo?).
  size_t material_override_count = 0;
  std::vector<std::string> unused_material_overrides;
  std::vector<Probe> probes;  // pixels whose luminance the statistics report
  // A road for `skylit road` (EN 13201-3 figures), if any.
  std::optional<RoadLightingSettings> road_lighting;
  // Set when the conditions came from a weather file (`weather`, docs/weather.md).
  std::optional<WeatherSummary> weather;
};

}  // namespace skylit
