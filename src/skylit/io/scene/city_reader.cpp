// A scene object of type "city": a city model file (CityJSON; CityGML) placed around
// the scene's site by its coordinate reference system, its surfaces given materials:
// the object's `city_materials` for their class, else the file's appearance (materials
// and textures of one theme), else the default palette for their class
// (io/city/city_palette.h). docs/city-models.md describes it.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "skylit/core/file_names.h"
#include "skylit/core/formatted.h"
#include "skylit/core/text_file.h"
#include "skylit/geometry/terrain_surface.h"
#include "skylit/io/city/city_appearance.h"
#include "skylit/io/city/city_palette.h"
#include "skylit/io/city/city_placement.h"
#include "skylit/io/city/citygml_reader.h"
#include "skylit/io/city/cityjson_reader.h"
#include "skylit/io/city/dem_reader.h"
#include "skylit/io/scene/scene_parts.h"

namespace skylit {

namespace {

// The model in the file, by its kind.
CityModel read_city_file(const JsonReader& file_value, const std::filesystem::path& file,
                         const CityJsonOptions& options) {
  const std::string extension = lower_case_extension(file);
  if (extension == ".json" || extension == ".jsonl") return read_cityjson_file(file, options);
  // ".citygml": Berlin's and some other cities' downloads.
  if (extension == ".gml" || extension == ".xml" || extension == ".citygml")
    return read_citygml_file(file, CityGmlOptions{options.lod, options.appearance});
  file_value.fail("unknown city model file '" + file.filename().string() +
                  "': expected CityJSON (.json, .city.json, .city.jsonl) or CityGML (.gml, .citygml, .xml)");
}

// The x–y box of the placed objects' vertices (metres, the local frame).
BoundingBox plan_box(const std::vector<PlacedCityObject>& objects) {
  BoundingBox box;
  for (const PlacedCityObject& o : objects)
    for (const Vec3& v : o.mesh.vertices) box.add({v.x, v.y, 0});
  return box;
}

// The object's `terrain`: a DEM (GeoTIFF or any raster GDAL reads) placed in the city
// model's frame, at its ground level, as one more TIN relief of the model.
void add_dem_terrain(const JsonReader& terrain, const std::filesystem::path& base_dir, CityPlacementOptions options,
                     PlacedCity& placed, CitySource& source) {
  terrain.allow_only({"file", "crs"});
  const std::filesystem::path file = base_dir / terrain.required("file").string();
  const DemTerrain dem = read_dem_terrain(file, terrain.has("crs"));
  options.crs = terrain.optional("crs") ? terrain.required("crs").string() : "";
  options.origin = GeoPoint{placed.origin.latitude_deg, placed.origin.longitude_deg, 0};
  options.ground_height_m = placed.origin.height_m;
  options.region.reset();  // the DEM is one object: a region would take all or none of it
  // The curvature drop where the model has it, and where the DEM alone reaches far
  // enough for it (a DEM of 100 km under a small model had stood 800 m too high at its
  // edge); the buildings are set down on the terrain either way.
  if (placed.curvature_applied) options.curvature = EarthCurvature::on;
  PlacedCity relief = place_city_model(dem.model, options, file.string());
  if (relief.objects.empty()) terrain.required("file").fail("the DEM gives no terrain");

  // A CRS without an EPSG code is WKT: its name says it in a line.
  const size_t quote = relief.crs.find('"');
  const std::string crs = relief.crs.starts_with("EPSG:") || quote == std::string::npos
                              ? relief.crs
                              : relief.crs.substr(quote + 1, relief.crs.find('"', quote + 1) - quote - 1);
  source.terrain = file.string() + ", CRS " + crs + ", " + std::to_string(dem.file_width) + " × " +
                   std::to_string(dem.file_height) + " cells";
  if (dem.read_width != dem.file_width || dem.read_height != dem.file_height)
    source.terrain += " read averaged down to " + std::to_string(dem.read_width) + " × " +
                      std::to_string(dem.read_height) + " (at most " + std::to_string(kMaxDemCells) + " cells)";
  source.terrain += formatted(" of %.4g × %.4g", dem.cell_size_x, dem.cell_size_y) + " CRS units";
  if (!dem.height_unit.empty())
    source.terrain += "; heights in '" + dem.height_unit + "'" +
                      (dem.metres_per_height_unit != 1 ? formatted(" × %.10g m", dem.metres_per_height_unit) : "");
  if (!dem.height_unit_known)
    source.terrain_warnings.push_back("terrain DEM " + quote_name(file.string()) + ": its heights' unit '" +
                                      dem.height_unit + "' is not one skylit knows; they are read as metres");
  if (dem.undeclared_no_data_cells > 0)
    source.terrain_warnings.push_back(
        "terrain DEM " + quote_name(file.string()) + ": " + std::to_string(dem.undeclared_no_data_cells) +
        formatted(" cells hold %g, a value often written for no data, but the file declares none: ",
                  dem.undeclared_no_data_value) +
        "they are read as heights (pits); declare it as the no-data value if it is one");
  // A DEM in another place than the model (a wrong CRS, of the DEM or of the model)
  // would otherwise only show as an empty or odd picture.
  // Where the terrain lies, in the scene's frame (a planner checks it covers the site);
  // its x and y are the plan's, compared with the model's below.
  const BoundingBox city = plan_box(placed.objects);
  BoundingBox ground;
  for (const PlacedCityObject& o : relief.objects) ground.add(o.mesh.bounds());
  if (!ground.empty())
    source.terrain += formatted("; covers x %.0f to %.0f m, ", ground.lo.x, ground.hi.x) +
                      formatted("y %.0f to %.0f m, ", ground.lo.y, ground.hi.y) +
                      formatted("heights %.1f to %.1f m (z)", ground.lo.z, ground.hi.z);
  size_t beyond_edge = 0;
  for (const PlacedCityObject& o : placed.objects) {
    const BoundingBox own = o.mesh.bounds();
    if (o.type == "TINRelief" || own.empty()) continue;
    const Vec3 c = own.center();
    if (c.x < ground.lo.x || c.x > ground.hi.x || c.y < ground.lo.y || c.y > ground.hi.y) ++beyond_edge;
  }
  if (!city.empty() && !ground.empty()) {
    const double gap_x = std::max({0.0, city.lo.x - ground.hi.x, ground.lo.x - city.hi.x});
    const double gap_y = std::max({0.0, city.lo.y - ground.hi.y, ground.lo.y - city.hi.y});
    if (const double gap = std::hypot(gap_x, gap_y); gap > 0)
      source.terrain_warnings.push_back(
          "terrain DEM " + quote_name(file.string()) +
          formatted(" lies %.1f km from the city model and does not reach under it: ", gap / 1000) +
          "is the CRS of either right?");
    else if (beyond_edge > 0)
      source.terrain_warnings.push_back("terrain DEM " + quote_name(file.string()) + ": " +
                                        std::to_string(beyond_edge) + " of the city model's " +
                                        std::to_string(placed.objects.size()) +
                                        " objects stand beyond its edge, where there is no ground under them");
  }
  for (PlacedCityObject& o : relief.objects) {
    for (uint32_t& c : o.triangle_class) {
      const std::string& key = relief.classes[c];
      const auto found = std::find(placed.classes.begin(), placed.classes.end(), key);
      c = static_cast<uint32_t>(found - placed.classes.begin());
      if (found == placed.classes.end()) placed.classes.push_back(key);
    }
    placed.objects.push_back(std::move(o));
  }
}

// A TIN relief in the file is the terrain: each building (and building part) is set
// down on it by its ground surfaces (geometry/terrain_surface.h, docs/citygml.md).
void seat_buildings_on_relief(PlacedCity& placed) {
  TriangleMesh relief;
  for (const PlacedCityObject& o : placed.objects)
    if (o.type == "TINRelief") relief.append(o.mesh);
  if (relief.triangles.empty()) return;
  const TerrainSurface terrain(relief);
  for (PlacedCityObject& o : placed.objects) {
    if (o.type != "Building" && o.type != "BuildingPart") continue;
    std::vector<bool> ground(o.triangle_class.size());
    for (size_t k = 0; k < ground.size(); ++k)
      ground[k] = placed.classes[o.triangle_class[k]].ends_with(".GroundSurface");
    seat_on_terrain(terrain, o.mesh, ground);
  }
}

std::optional<int> read_lod(const JsonReader& j) {
  std::optional<int> lod;
  if (j.is_string()) lod = parse_lod(j.string());
  if (j.is_number()) lod = parse_lod(std::to_string(j.number()));
  if (!lod) j.fail_expected("a level of detail from 0 to 4.3 (\"2.2\", 2, 1.3)");
  return lod;
}

CityRegion read_region(const JsonReader& j) {
  j.allow_only({"center_lonlat", "radius_m", "bbox_lonlat"});
  CityRegion region;
  if (j.has("center_lonlat") == j.has("bbox_lonlat")) j.fail("give either center_lonlat and radius_m, or bbox_lonlat");
  if (auto c = j.optional("center_lonlat")) {
    const auto lonlat = c->elements();
    if (lonlat.size() != 2) c->fail_expected("[longitude, latitude] in degrees");
    region.center_lonlat_deg = {lonlat[0].number_in(-180, 180), lonlat[1].number_in(-90, 90)};
    region.radius_m = j.required("radius_m").number_in(0, 1e7);
  } else {
    if (j.has("radius_m")) j.required("radius_m").fail("radius_m goes with center_lonlat");
    const JsonReader b = j.required("bbox_lonlat");
    const auto values = b.elements();
    if (values.size() != 4) b.fail_expected("[west, south, east, north] in degrees");
    region.bbox_lonlat_deg = {values[0].number_in(-180, 180), values[1].number_in(-90, 90),
                              values[2].number_in(-180, 180), values[3].number_in(-90, 90)};
    const auto& box = *region.bbox_lonlat_deg;
    if (!(box[2] > box[0] && box[3] > box[1])) b.fail("east must exceed west and north exceed south");
  }
  return region;
}

EarthCurvature read_curvature(const JsonReader& j) {
  if (j.is_string()) {
    j.one_of({"auto"});
    return EarthCurvature::automatic;
  }
  return j.boolean() ? EarthCurvature::on : EarthCurvature::off;
}

std::optional<uint32_t> material_index(const std::string& name, const std::vector<NamedMaterial>& materials) {
  for (size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == name) return static_cast<uint32_t>(i);
  return std::nullopt;
}

// The scene materials of a model's appearances, one per (material, texture) pair used,
// named "<object>/<material name>" or "<object>/<image>". A texture whose image is
// missing is left out (its surfaces keep their material, else their class's).
class CityAppearanceMaterials {
 public:
  CityAppearanceMaterials(const CityModel& model, const std::filesystem::path& folder, const std::string& object_name,
                          std::vector<NamedMaterial>& materials)
      : model_(model), images_(folder), object_name_(object_name), materials_(materials) {}

  // The scene material, or none when the surface has no appearance that can be shown.
  std::optional<uint32_t> material_for(int32_t material, int32_t texture) {
    std::shared_ptr<const Texture> image;
    if (texture != CitySurface::kNone) image = images_.image(model_.textures[static_cast<size_t>(texture)]);
    if (!image) texture = CitySurface::kNone;
    if (material == CitySurface::kNone && texture == CitySurface::kNone) return std::nullopt;
    const auto [it, added] = made_.try_emplace({material, texture}, 0);
    if (!added) return it->second;
    ModelMaterial m;
    if (material != CitySurface::kNone) m = model_material_from_x3d(model_.materials[static_cast<size_t>(material)]);
    if (image) {
      m.color_linear = {1, 1, 1};  // the texture replaces the colour, as in X3D
      m.color_texture = image;
      m.name =
          (material != CitySurface::kNone ? m.name + " + " : "") + model_.textures[static_cast<size_t>(texture)].image;
    }
    it->second = static_cast<uint32_t>(materials_.size());
    materials_.push_back({object_name_ + "/" + m.name, material_from_model(m), appearance_from_model(m)});
    return it->second;
  }
  const std::vector<std::string>& missing_images() const { return images_.missing(); }

 private:
  const CityModel& model_;
  CityTextureImages images_;
  std::string object_name_;
  std::vector<NamedMaterial>& materials_;
  std::map<std::pair<int32_t, int32_t>, uint32_t> made_;
};

// The scene material for each class: the object's city_materials (the class, its type
// or its semantic), else the palette's (added once per scene as "city/<entry>").
class CityMaterials {
 public:
  CityMaterials(const std::optional<JsonReader>& given, const std::string& object_name,
                std::vector<NamedMaterial>& materials)
      : given_(given), object_name_(object_name), materials_(materials) {}

  // The scene's city_materials entry for the class, if any: its key.
  std::optional<std::string> given_key(const std::string& class_key) const {
    if (!given_) return std::nullopt;
    const size_t dot = class_key.find('.');
    const std::string type = class_key.substr(0, dot);
    const std::string semantic = dot == std::string::npos ? "" : class_key.substr(dot + 1);
    for (const std::string& key : {class_key, type, semantic})
      if (!key.empty() && given_->has(key)) return key;
    return std::nullopt;
  }

  uint32_t material_for(const std::string& class_key) {
    if (const auto key = given_key(class_key)) return scene_material(given_->required(*key), *key);
    const CityPaletteEntry& entry = city_palette_entry(class_key);
    const std::string name = "city/" + std::string(entry.key);
    if (auto index = material_index(name, materials_)) return *index;
    // A preset's name is a JSON string once quoted.
    std::string text(entry.material_json);
    if (text.front() != '{') text = std::string(1, '"').append(text).append(1, '"');
    const nlohmann::json definition = parse_json_text(text, "the city palette");
    materials_.push_back({name, read_material(JsonReader(definition, "the city palette", name))});
    return static_cast<uint32_t>(materials_.size() - 1);
  }

 private:
  // A scene material's name, a preset, or a material defined inline.
  uint32_t scene_material(const JsonReader& value, const std::string& key) {
    if (value.is_string())
      if (auto index = material_index(value.string(), materials_)) return *index;
    const std::string name = object_name_ + "/" + key;
    if (auto index = material_index(name, materials_)) return *index;
    materials_.push_back({name, read_material(value)});
    return static_cast<uint32_t>(materials_.size() - 1);
  }

  std::optional<JsonReader> given_;
  std::string object_name_;
  std::vector<NamedMaterial>& materials_;
};

}  // namespace

SceneObject read_city(const JsonReader& j, const std::filesystem::path& base_dir, std::vector<NamedMaterial>& materials,
                      std::optional<SiteLocation>& site) {
  j.allow_only({"type", "name", "file", "crs", "lod", "region", "city_materials", "appearance", "appearance_theme",
                "earth_curvature", "refraction_k", "terrain"});
  SceneObject object;
  object.name = j.optional("name") ? j.required("name").string() : j.path();
  const JsonReader file_value = j.required("file");
  const std::filesystem::path file = base_dir / file_value.string();

  CityJsonOptions read_options;
  if (auto lod = j.optional("lod")) read_options.lod = read_lod(*lod);
  if (auto a = j.optional("appearance")) read_options.appearance.read = a->boolean();
  const auto theme = j.optional("appearance_theme");
  if (theme) read_options.appearance.theme = theme->string();
  const CityModel model = read_city_file(file_value, file, read_options);
  if (theme && read_options.appearance.read &&
      std::find(model.appearance_themes.begin(), model.appearance_themes.end(), read_options.appearance.theme) ==
          model.appearance_themes.end()) {
    std::string themes;
    for (const std::string& t : model.appearance_themes) themes += (themes.empty() ? "" : ", ") + quote_excerpt(t);
    theme->fail("the file has no appearance theme " + quote_excerpt(read_options.appearance.theme) +
                (themes.empty() ? " (it has no appearances)" : " (its themes: " + themes + ")"));
  }

  CityPlacementOptions options;
  if (auto crs = j.optional("crs")) options.crs = crs->string();
  if (site) options.origin = GeoPoint{site->latitude_deg, site->longitude_deg, 0};
  if (auto region = j.optional("region")) options.region = read_region(*region);
  if (auto c = j.optional("earth_curvature")) options.curvature = read_curvature(*c);
  if (auto k = j.optional("refraction_k")) options.refraction_k = k->number_in(0, 1);
  PlacedCity placed = place_city_model(model, options, file.string());
  if (placed.objects.empty())
    file_value.fail(placed.degenerate_surfaces > 0
                        ? "all " + std::to_string(placed.degenerate_surfaces) +
                              " surfaces of the city model have zero area once placed: are its coordinates (or a "
                              "CityJSON transform's scale and translate) right?"
                        : "the city model has no surfaces to show (in the region, at the LoD)");
  CitySource source;
  if (auto terrain = j.optional("terrain")) add_dem_terrain(*terrain, base_dir, options, placed, source);
  if (!site)  // the model's centre becomes the site, for the sun
    site = SiteLocation{placed.origin.latitude_deg, placed.origin.longitude_deg,
                        std::clamp(placed.origin.height_m, -500.0, 9000.0)};

  source.file = file.string();
  source.crs = placed.crs;
  source.latitude_deg = placed.origin.latitude_deg;
  source.longitude_deg = placed.origin.longitude_deg;
  source.ground_height_m = placed.origin.height_m;
  source.site_from_model = placed.origin_from_model;
  source.curvature_applied = placed.curvature_applied;
  source.axes_swapped = placed.axes_swapped;
  source.axes_swapped_by_format = placed.axes_swapped_by_format;
  source.objects_outside_region = placed.objects_outside_region;
  source.degenerate_surfaces = placed.degenerate_surfaces;

  CityMaterials city_materials(j.optional("city_materials"), object.name, materials);
  std::vector<uint32_t> class_material;
  for (const std::string& key : placed.classes) {
    class_material.push_back(city_materials.material_for(key));
    source.classes.push_back({key, 0, materials[class_material.back()].name});
  }
  seat_buildings_on_relief(placed);
  CityAppearanceMaterials appearance(model, file.parent_path(), object.name, materials);
  std::vector<bool> class_given(placed.classes.size());
  for (size_t c = 0; c < placed.classes.size(); ++c)
    class_given[c] = city_materials.given_key(placed.classes[c]).has_value();
  const bool textured = std::any_of(placed.objects.begin(), placed.objects.end(),
                                    [](const PlacedCityObject& o) { return !o.corner_uvs.empty(); });
  std::map<std::string, size_t> by_type;
  for (const PlacedCityObject& city_object : placed.objects) {
    ++by_type[city_object.type];
    for (const Vec3& v : city_object.mesh.vertices)
      if (!(std::abs(v.x) <= kSceneExtentM && std::abs(v.y) <= kSceneExtentM && std::abs(v.z) <= kSceneExtentM))
        file_value.fail("object '" + city_object.id + "' lies beyond ±1e7 m of the site once placed");
    object.mesh.append(city_object.mesh);
    const bool has_appearance = !city_object.triangle_material.empty();
    for (size_t t = 0; t < city_object.triangle_class.size(); ++t) {
      const uint32_t c = city_object.triangle_class[t];
      std::optional<uint32_t> m;  // city_materials > appearance > palette
      if (has_appearance && !class_given[c])
        m = appearance.material_for(city_object.triangle_material[t], city_object.triangle_texture[t]);
      object.triangle_materials.push_back(m ? *m : class_material[c]);
      ++source.classes[c].triangles;
      source.appearance_triangles += m.has_value();
    }
    if (textured)
      object.corner_uvs.insert(object.corner_uvs.end(), city_object.corner_uvs.begin(), city_object.corner_uvs.end());
    if (textured && city_object.corner_uvs.empty()) object.corner_uvs.resize(object.mesh.triangles.size(), CornerUvs{});
  }
  source.appearance_theme = model.texture_theme.empty() ? model.material_theme : model.texture_theme;
  source.missing_texture_images = appearance.missing_images();
  source.objects_by_type.assign(by_type.begin(), by_type.end());
  object.material_index = object.triangle_materials.front();
  object.city = std::move(source);
  return object;
}

}  // namespace skylit
