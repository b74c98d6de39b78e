// A streaming CityGML reader on expat: the elements arrive one by one; the reader
// keeps a stack of what it is inside (a city object, a semantic surface, a geometry
// property of some level of detail, a polygon, a ring) and collects polygons. At the
// end of the document, references (xlink:href) and appearance targets, which may
// point forward, are resolved and each object keeps its most detailed LoD.
#include "skylit/io/city/citygml_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <exception>
#include <fstream>
#include <memory>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <expat.h>

#include "skylit/core/error.h"
#include "skylit/core/text_file.h"
#include "skylit/io/city/citygml_names.h"

namespace skylit {
namespace {

struct Name {
  std::string_view uri;
  std::string_view local;
};

// Namespace prefixes in scope. Expat's own namespace processing would refuse a whole
// file for one undeclared prefix, and real files have them (the PLATEAU sample uses
// "energy:" undeclared); here an element with an unknown prefix is merely not read.
class Namespaces {
 public:
  // Takes the declarations among an element's attributes (xmlns="...", xmlns:p="...").
  void declare(const XML_Char** attributes, int depth) {
    for (int i = 0; attributes[i] != nullptr; i += 2) {
      const std::string_view name(attributes[i]);
      if (name == "xmlns")
        bindings_.push_back({"", attributes[i + 1], depth});
      else if (name.substr(0, 6) == "xmlns:")
        bindings_.push_back({std::string(name.substr(6)), attributes[i + 1], depth});
    }
  }
  void end_scope(int depth) {
    while (!bindings_.empty() && bindings_.back().depth == depth) bindings_.pop_back();
  }
  // An element's or attribute's namespace and local name. Unprefixed attributes have
  // no namespace; unprefixed elements have the default one.
  Name resolve(std::string_view qualified, bool attribute) const {
    const auto colon = qualified.find(':');
    if (colon == std::string_view::npos) return {attribute ? std::string_view{} : uri_of(""), qualified};
    return {uri_of(qualified.substr(0, colon)), qualified.substr(colon + 1)};
  }

 private:
  std::string_view uri_of(std::string_view prefix) const {
    // The innermost declaration first.
    for (size_t k = bindings_.size(); k-- > 0;)
      if (bindings_[k].prefix == prefix) return bindings_[k].uri;
    return {};
  }
  struct Binding {
    std::string prefix, uri;
    int depth;
  };
  std::vector<Binding> bindings_;
};

// GML 3.1.1 ("http://www.opengis.net/gml", CityGML 1.0 and 2.0) or 3.2.
bool is_gml(std::string_view uri) { return uri.substr(0, 26) == "http://www.opengis.net/gml"; }
bool is_citygml(std::string_view uri) { return uri.find("opengis.net/citygml") != std::string_view::npos; }
bool is_appearance(std::string_view uri) { return uri.find("/citygml/appearance/") != std::string_view::npos; }
bool is_xlink(std::string_view uri) { return uri == "http://www.w3.org/1999/xlink"; }

// The attributes this reader uses, found in one pass.
struct Attributes {
  std::string_view gml_id, href, srs_name, srs_dimension, uri, ring;
};

Attributes read_attributes(const XML_Char** attributes, const Namespaces& namespaces) {
  Attributes a;
  for (int i = 0; attributes[i] != nullptr; i += 2) {
    const Name n = namespaces.resolve(attributes[i], true);
    const std::string_view value(attributes[i + 1]);
    if (n.local == "id" && is_gml(n.uri))
      a.gml_id = value;
    else if (n.local == "href" && is_xlink(n.uri))
      a.href = value;
    else if (n.local == "srsName" && n.uri.empty())
      a.srs_name = value;
    else if (n.local == "srsDimension" && n.uri.empty())
      a.srs_dimension = value;
    else if (n.local == "uri" && n.uri.empty())
      a.uri = value;
    else if (n.local == "ring" && n.uri.empty())
      a.ring = value;
  }
  return a;
}

// A polygon met inside a city object's geometry at some LoD, or a reference to one.
struct SurfaceUse {
  int lod = 0;
  std::string semantic;
  int polygon = -1;  // index into the polygons read, or -1 for a reference
  std::string href;  // the referenced gml:id (without '#')
  unsigned long line = 0;
};

struct ObjectInProgress {
  CityObject object;
  std::vector<SurfaceUse> uses;
  int depth = 0;
};

// What the text of the element being read is for.
enum class TextFor {
  nothing,
  pos_list,
  pos,
  coordinates,
  relief_lod,
  appearance_theme,
  material_target,
  material_value,
  texture_uri,
  wrap_mode,
  texture_coordinates,
  texture_ring,
  implicit_matrix,
  implicit_reference
};

// An id as an appearance writes it ("#id", perhaps with spaces around), without the '#'.
std::string without_hash(std::string_view id) {
  const auto b = id.find_first_not_of(" \t\r\n#");
  if (b == std::string_view::npos) return {};
  const auto e = id.find_last_not_of(" \t\r\n");
  return std::string(id.substr(b, e - b + 1));
}

// The texture coordinates of one ring (app:textureCoordinates ring="#id").
struct RingCoordinates {
  std::string ring;
  std::vector<double> st;  // s, t, s, t, ...
  unsigned long line = 0;
};

// One app:X3DMaterial or app:ParameterizedTexture with what it is given to.
struct SurfaceData {
  std::string theme;  // its app:Appearance's
  bool is_material = false;
  CityMaterial material;
  CityTexture texture;
  std::vector<std::string> targets;    // material: ids of polygons or surface aggregates
  std::vector<RingCoordinates> rings;  // texture
  unsigned long line = 0;
};

// An implicit geometry being read (core:ImplicitGeometry): its polygons, read in
// relative coordinates, are moved by its matrix to its reference point at its end.
struct Implicit {
  int depth = 0;
  unsigned long line = 0;
  size_t first_polygon = 0;
  int relative_depth = 0;         // of core:relativeGMLGeometry
  std::string prototype;          // the gml:id of the relative geometry it defines
  std::string href;               // or the one it refers to
  std::vector<double> matrix;     // 16, row by row
  std::optional<Vec3> reference;  // core:referencePoint
};
class CityGmlParser {
 public:
  CityGmlParser(std::string name, CityGmlOptions options) : name_(std::move(name)), options_(std::move(options)) {
    parser_ = XML_ParserCreate(nullptr);
    if (parser_ == nullptr) throw std::bad_alloc();
    XML_SetUserData(parser_, this);
    XML_SetElementHandler(parser_, &CityGmlParser::on_start, &CityGmlParser::on_end);
    XML_SetCharacterDataHandler(parser_, &CityGmlParser::on_text);
  }
  ~CityGmlParser() { XML_ParserFree(parser_); }
  CityGmlParser(const CityGmlParser&) = delete;
  CityGmlParser& operator=(const CityGmlParser&) = delete;

  void feed(const char* data, size_t size, bool last) {
    // Expat takes an int length: feed very large buffers in pieces.
    constexpr size_t kPiece = size_t{1} << 28;
    do {
      const size_t n = std::min(size, kPiece);
      const bool final_piece = last && n == size;
      if (XML_Parse(parser_, data, static_cast<int>(n), final_piece ? XML_TRUE : XML_FALSE) != XML_STATUS_OK) {
        if (failure_) std::rethrow_exception(failure_);
        fail(std::string("malformed XML: ") + XML_ErrorString(XML_GetErrorCode(parser_)));
      }
      data += n;
      size -= n;
    } while (size > 0);
  }

  CityModel finish();

 private:
  [[noreturn]] void fail(const std::string& what) const { fail_at(XML_GetCurrentLineNumber(parser_), what); }
  [[noreturn]] void fail_at(unsigned long line, const std::string& what) const {
    throw InputError(name_ + ":" + std::to_string(line) + ": " + what);
  }

  // Expat is C: an exception must not unwind through it. The first one is kept and
  // the parser stopped; feed() throws it.
  template <class F>
  static void guarded(void* self_ptr, F&& f) {
    auto* self = static_cast<CityGmlParser*>(self_ptr);
    if (self->failure_) return;
    try {
      f(*self);
    } catch (...) {
      self->failure_ = std::current_exception();
      XML_StopParser(self->parser_, XML_FALSE);
    }
  }
  static void XMLCALL on_start(void* self, const XML_Char* name, const XML_Char** attributes) {
    guarded(self, [&](CityGmlParser& p) { p.start(name, attributes); });
  }
  static void XMLCALL on_end(void* self, const XML_Char* name) {
    guarded(self, [&](CityGmlParser& p) { p.end(name); });
  }
  static void XMLCALL on_text(void* self, const XML_Char* text, int length) {
    auto* p = static_cast<CityGmlParser*>(self);
    if (p->text_for_ != TextFor::nothing) p->text_.append(text, static_cast<size_t>(length));
  }

  void start(const XML_Char* name, const XML_Char** attribute_list);
  void end(const XML_Char* name);
  void start_citygml(std::string_view local, const Attributes& a);
  void start_gml(std::string_view local, const Attributes& a);
  void start_appearance(std::string_view local, const Attributes& a);
  void capture_text(TextFor what) {
    text_for_ = what;
    text_depth_ = depth_;
    text_line_ = XML_GetCurrentLineNumber(parser_);
    text_.clear();
  }
  void use_text();
  void use_material_value();
  void finish_implicit_geometry();
  void resolve_appearances(CityModel& model);
  void note_crs(std::string_view srs_name);
  void finish_ring();
  void finish_polygon();
  bool in_geometry() const {
    return !objects_.empty() && !lods_.empty() && lods_.back().second > objects_.back().depth;
  }
  std::string current_semantic() const {
    // A semantic surface counts only inside the innermost object.
    if (semantics_.empty() || semantics_.back().second < objects_.back().depth) return {};
    return semantics_.back().first;
  }
  std::vector<double> numbers(std::string_view text) const;
  void add_points(const std::vector<double>& values, int dimension);
  std::vector<int> polygons_named(const std::string& id) const;

  std::string name_;
  CityGmlOptions options_;
  XML_Parser parser_ = nullptr;
  std::exception_ptr failure_;
  int depth_ = 0;
  int skip_depth_ = 0;  // > 0 while inside a subtree that is not read
  Namespaces namespaces_;

  std::string crs_;
  std::vector<ObjectInProgress> objects_;  // open, innermost last
  std::vector<ObjectInProgress> finished_;
  std::vector<std::pair<std::string, int>> semantics_;   // (class, depth)
  std::vector<std::pair<int, int>> lods_;                // (lod ×10, depth)
  std::vector<std::pair<int, int>> dimensions_;          // (srsDimension, depth)
  std::vector<std::pair<std::string, int>> aggregates_;  // (gml:id of a surface aggregate, depth)
  int relief_lod_ = 10;

  // The polygon and ring being read.
  bool in_polygon_ = false, polygon_used_ = false;
  int polygon_depth_ = 0;
  unsigned long polygon_line_ = 0;
  std::string polygon_id_;
  std::string ring_id_, exterior_id_;
  std::vector<std::string> interior_ids_;
  std::vector<Vec3> exterior_;
  std::vector<std::vector<Vec3>> interiors_;
  bool ring_is_interior_ = false;
  bool in_ring_ = false;
  int ring_depth_ = 0;
  unsigned long ring_line_ = 0;
  std::vector<Vec3> ring_;

  TextFor text_for_ = TextFor::nothing;
  int text_depth_ = 0;
  unsigned long text_line_ = 0;
  std::string text_;

  // Appearances: the theme of the app:Appearance being read, the surface data being
  // read (an X3DMaterial or ParameterizedTexture), and all of them.
  std::string appearance_theme_;
  int surface_data_depth_ = 0;  // > 0 inside one
  std::string material_field_;  // the X3DMaterial element whose text is read
  std::vector<SurfaceData> surface_data_;
  std::string coordinates_ring_;  // the ring of the app:textureCoordinates being read

  // The implicit geometry being read.
  std::optional<Implicit> implicit_;
  // Relative geometries by gml:id, as read (before any instance's transformation).
  std::unordered_map<std::string, std::vector<CitySurface>> prototypes_;

  std::vector<CitySurface> polygons_;
  std::unordered_map<std::string, int> polygon_ids_;
  std::unordered_map<std::string, std::vector<int>> aggregate_polygons_;
  std::unordered_map<std::string, std::pair<int, int>> ring_ids_;  // (polygon, ring) by gml:id
  std::unordered_set<std::string> dropped_ring_ids_;               // holes of fewer than three points (finish_ring)
  std::unordered_set<std::string> skipped_ids_;  // gml:ids inside subtrees not read (rooms, addresses)

  // Keeps the gml:id of an element inside a skipped subtree, whose namespaces are not
  // resolved: an attribute "id" with any prefix.
  void note_skipped_id(const XML_Char** attribute_list) {
    for (const XML_Char** at = attribute_list; at[0] != nullptr; at += 2) {
      const std::string_view attribute_name(at[0]);
      if (attribute_name == "id" || attribute_name.ends_with(":id")) skipped_ids_.insert(std::string(at[1]));
    }
  }
};

void CityGmlParser::start(const XML_Char* name, const XML_Char** attribute_list) {
  ++depth_;
  if (skip_depth_ > 0) {  // (a skipped subtree's own declarations are not needed)
    note_skipped_id(attribute_list);
    return;
  }
  namespaces_.declare(attribute_list, depth_);
  const Name n = namespaces_.resolve(name, false);
  const Attributes a = read_attributes(attribute_list, namespaces_);
  if (depth_ == 1 && !(n.local == "CityModel" && is_citygml(n.uri)))
    fail("the root element is <" + std::string(n.local) + ">, not a CityGML 1.0, 2.0 or 3.0 CityModel");
  if (!a.srs_name.empty()) note_crs(a.srs_name);
  if (!a.srs_dimension.empty()) {
    int d = 0;
    std::from_chars(a.srs_dimension.data(), a.srs_dimension.data() + a.srs_dimension.size(), d);
    if (d != 2 && d != 3) fail("srsDimension " + quote_excerpt(a.srs_dimension) + ": only 2 and 3 are read");
    dimensions_.emplace_back(d, depth_);
  }
  if (is_appearance(n.uri) || surface_data_depth_ > 0)
    start_appearance(n.local, a);
  else if (is_citygml(n.uri))
    start_citygml(n.local, a);
  else if (is_gml(n.uri))
    start_gml(n.local, a);
}

void CityGmlParser::start_citygml(std::string_view local, const Attributes& a) {
  if (!objects_.empty() && local.size() > 4 && local.starts_with("lod") && local[3] >= '0' && local[3] <= '4' &&
      local.ends_with("ImplicitRepresentation")) {
    lods_.emplace_back((local[3] - '0') * 10, depth_);
    return;
  }
  if (!objects_.empty() && local == "ImplicitGeometry" && !lods_.empty() && !implicit_) {
    implicit_.emplace();
    implicit_->depth = depth_;
    implicit_->line = XML_GetCurrentLineNumber(parser_);
    implicit_->first_polygon = polygons_.size();
    return;
  }
  if (implicit_) {
    if (local == "transformationMatrix") {
      capture_text(TextFor::implicit_matrix);
    } else if (local == "relativeGMLGeometry") {
      implicit_->relative_depth = depth_;
      if (!a.href.empty()) implicit_->href = without_hash(a.href);
    }
    if (local != "referencePoint") return;
  }
  // Addresses are not read either: their location points may be in another CRS (the
  // OGC's 3.0 samples give them in EPSG:4326), which is no reason to refuse the file.
  if (citygml::is_interior_feature(local) || local == "Address" || local.find("Implicit") != std::string_view::npos) {
    skip_depth_ = depth_;
    return;
  }
  if (auto type = citygml::city_object_type(local)) {
    ObjectInProgress o;
    o.object.type = *type;
    o.object.id =
        a.gml_id.empty() ? *type + "@line" + std::to_string(XML_GetCurrentLineNumber(parser_)) : std::string(a.gml_id);
    o.depth = depth_;
    objects_.push_back(std::move(o));
    if (*type == "TINRelief") relief_lod_ = 10;
    return;
  }
  if (objects_.empty()) return;
  if (citygml::is_semantic_surface(local)) {
    semantics_.emplace_back(citygml::semantic_surface_class(local), depth_);
  } else if (auto lod = citygml::lod_of_property(local)) {
    lods_.emplace_back(*lod, depth_);
    if (!a.href.empty() && a.href.front() == '#')  // a whole geometry given by reference
      objects_.back().uses.push_back(
          {*lod, current_semantic(), -1, std::string(a.href.substr(1)), XML_GetCurrentLineNumber(parser_)});
  } else if (local == "tin") {
    lods_.emplace_back(relief_lod_, depth_);
  } else if (local == "lod" && objects_.back().object.type == "TINRelief") {
    capture_text(TextFor::relief_lod);
  }
}

void CityGmlParser::start_gml(std::string_view local, const Attributes& a) {
  if (implicit_ && !in_polygon_) {
    if (implicit_->relative_depth > 0 && depth_ == implicit_->relative_depth + 1 && !a.gml_id.empty())
      implicit_->prototype = a.gml_id;
    if (local == "pos" && !in_ring_) {
      capture_text(TextFor::implicit_reference);
      return;
    }
  }
  // A gml:Surface's patches (gml:PolygonPatch, GML 3.1.1 §10.5.10) are polygons too; the
  // Surface's own gml:id makes it an aggregate of them, as a CompositeSurface's does.
  if (local == "Polygon" || local == "Triangle" || local == "PolygonPatch") {
    in_polygon_ = true;
    polygon_used_ = in_geometry();
    polygon_depth_ = depth_;
    polygon_line_ = XML_GetCurrentLineNumber(parser_);
    polygon_id_ = a.gml_id;
    exterior_.clear();
    interiors_.clear();
    exterior_id_.clear();
    interior_ids_.clear();
  } else if (!in_polygon_) {
    // A reference to a surface from a solid, shell or multi-surface.
    if (!a.href.empty() && a.href.front() == '#' && in_geometry())
      objects_.back().uses.push_back({lods_.back().first, current_semantic(), -1, std::string(a.href.substr(1)),
                                      XML_GetCurrentLineNumber(parser_)});
    else if (!a.gml_id.empty())
      aggregates_.emplace_back(std::string(a.gml_id), depth_);
  } else if (local == "exterior" || local == "outerBoundaryIs") {
    ring_is_interior_ = false;
  } else if (local == "interior" || local == "innerBoundaryIs") {
    ring_is_interior_ = true;
  } else if (local == "LinearRing") {
    in_ring_ = true;
    ring_id_ = a.gml_id;
    ring_depth_ = depth_;
    ring_line_ = XML_GetCurrentLineNumber(parser_);
    ring_.clear();
  } else if (in_ring_ && local == "posList") {
    capture_text(TextFor::pos_list);
  } else if (in_ring_ && local == "pos") {
    capture_text(TextFor::pos);
  } else if (in_ring_ && local == "coordinates") {
    capture_text(TextFor::coordinates);
  }
}

void CityGmlParser::start_appearance(std::string_view local, const Attributes& a) {
  if (!options_.appearance.read) return;
  if (local == "Appearance") {
    appearance_theme_.clear();
  } else if (local == "theme" && surface_data_depth_ == 0) {
    capture_text(TextFor::appearance_theme);
  } else if (local == "X3DMaterial" || local == "ParameterizedTexture") {
    surface_data_depth_ = depth_;
    SurfaceData data;
    data.theme = appearance_theme_;
    data.is_material = local == "X3DMaterial";
    data.line = XML_GetCurrentLineNumber(parser_);
    data.material.name = a.gml_id.empty() ? "X3DMaterial@line" + std::to_string(XML_GetCurrentLineNumber(parser_))
                                          : std::string(a.gml_id);
    surface_data_.push_back(std::move(data));
  } else if (surface_data_depth_ == 0) {
    return;  // (a GeoreferencedTexture is not read)
  } else if (local == "target") {
    // X3DMaterial: <app:target>#id</app:target>; textures: <app:target uri="#id">.
    if (a.uri.empty())
      capture_text(TextFor::material_target);
    else
      surface_data_.back().targets.push_back(without_hash(a.uri));
  } else if (local == "imageURI") {
    capture_text(TextFor::texture_uri);
  } else if (local == "wrapMode") {
    capture_text(TextFor::wrap_mode);
  } else if (local == "textureCoordinates") {
    coordinates_ring_ = without_hash(a.ring);
    capture_text(TextFor::texture_coordinates);
  } else if (local == "ring" && !surface_data_.empty() && !surface_data_.back().is_material) {
    // CityGML 3.0 names a TexCoordList's ring in an element after its coordinates
    // (<app:textureCoordinates>…</app:textureCoordinates><app:ring>#id</app:ring>), pairs
    // in order, where 2.0 gives it as the coordinates' attribute ring="#id".
    capture_text(TextFor::texture_ring);
  } else if (surface_data_.back().is_material &&
             (local == "diffuseColor" || local == "emissiveColor" || local == "specularColor" || local == "shininess" ||
              local == "transparency" || local == "isSmooth")) {
    material_field_ = local;
    capture_text(TextFor::material_value);
  }
}

void CityGmlParser::use_material_value() {
  CityMaterial& m = surface_data_.back().material;
  if (material_field_ == "isSmooth") {
    m.smooth = without_hash(text_) == "true" || without_hash(text_) == "1";
    return;
  }
  const std::vector<double> values = numbers(text_);
  const bool colour = material_field_.ends_with("Color");
  const bool in_range = std::all_of(values.begin(), values.end(), [](double v) { return v >= 0 && v <= 1; });
  if (values.size() != (colour ? 3U : 1U) || !in_range)
    fail_at(text_line_, "app:" + material_field_ + " must be " + (colour ? "three numbers" : "a number") +
                            " from 0 to 1, found " + quote_excerpt(text_));
  if (material_field_ == "diffuseColor") std::copy(values.begin(), values.end(), m.diffuse.begin());
  if (material_field_ == "emissiveColor") std::copy(values.begin(), values.end(), m.emissive.begin());
  if (material_field_ == "specularColor") std::copy(values.begin(), values.end(), m.specular.begin());
  if (material_field_ == "shininess") m.shininess = values[0];
  if (material_field_ == "transparency") m.transparency = values[0];
}

void CityGmlParser::note_crs(std::string_view srs_name) {
  auto epsg = citygml::epsg_from_srs_name(srs_name);
  if (!epsg)
    fail("srsName " + quote_excerpt(srs_name) +
         " is not a coordinate reference system this reader knows (EPSG:n, urn:ogc:def:crs:EPSG::n, "
         "http://www.opengis.net/def/crs/EPSG/0/n)");
  if (crs_.empty() || epsg->starts_with(crs_ + "+")) {
    crs_ = *epsg;  // the first, or the compound form of the first
  } else if (*epsg != crs_ && !crs_.starts_with(*epsg + "+")) {
    fail("srsName " + quote_excerpt(srs_name) + " differs from the file's first, " + crs_);
  }
}

std::vector<double> CityGmlParser::numbers(std::string_view text) const {
  std::vector<double> values;
  values.reserve(text.size() / 8);
  unsigned long line = text_line_;
  size_t i = 0;
  while (true) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\n' || text[i] == '\r')) {
      if (text[i] == '\n') ++line;
      ++i;
    }
    if (i == text.size()) break;
    size_t j = i;
    while (j < text.size() && text[j] != ' ' && text[j] != '\t' && text[j] != '\n' && text[j] != '\r') ++j;
    std::string_view token = text.substr(i, j - i);
    std::string_view digits = token.front() == '+' ? token.substr(1) : token;
    double v = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (ec != std::errc() || end != digits.data() + digits.size() || !std::isfinite(v))
      fail_at(line, "expected a coordinate (a finite number), found " + quote_excerpt(token));
    values.push_back(v);
    i = j;
  }
  return values;
}

void CityGmlParser::add_points(const std::vector<double>& values, int dimension) {
  if (values.size() % static_cast<size_t>(dimension) != 0)
    fail_at(text_line_,
            std::to_string(values.size()) + " coordinates are not points of dimension " + std::to_string(dimension));
  for (size_t k = 0; k < values.size(); k += static_cast<size_t>(dimension))
    ring_.emplace_back(values[k], values[k + 1], dimension == 3 ? values[k + 2] : 0.0);
}

void CityGmlParser::use_text() {
  const TextFor what = text_for_;
  text_for_ = TextFor::nothing;
  switch (what) {
    case TextFor::pos_list:
      add_points(numbers(text_), dimensions_.empty() ? 3 : dimensions_.back().first);
      break;
    case TextFor::pos: {
      const auto values = numbers(text_);
      if (values.size() != 2 && values.size() != 3)
        fail_at(text_line_, "a gml:pos has " + std::to_string(values.size()) + " coordinates, not 2 or 3");
      add_points(values, static_cast<int>(values.size()));
      break;
    }
    case TextFor::coordinates: {
      // GML 2's "x,y,z x,y,z ...": commas separate coordinates, spaces points.
      std::string spaced = text_;
      const auto first_tuple = spaced.substr(0, spaced.find_first_of(" \t\r\n", spaced.find_first_not_of(" \t\r\n")));
      const int dimension = 1 + static_cast<int>(std::count(first_tuple.begin(), first_tuple.end(), ','));
      std::replace(spaced.begin(), spaced.end(), ',', ' ');
      if (dimension != 2 && dimension != 3)
        fail_at(text_line_, "gml:coordinates with points of dimension " + std::to_string(dimension) + ", not 2 or 3");
      add_points(numbers(spaced), dimension);
      break;
    }
    case TextFor::relief_lod: {
      const auto values = numbers(text_);
      if (values.size() != 1 || values[0] < 0 || values[0] > 4)
        fail_at(text_line_, "dem:lod must be one of 0 to 4, found " + quote_excerpt(text_));
      relief_lod_ = static_cast<int>(std::lround(values[0] * 10));
      break;
    }
    case TextFor::appearance_theme:
      appearance_theme_ = without_hash(text_);
      break;
    case TextFor::material_target:
      surface_data_.back().targets.push_back(without_hash(text_));
      break;
    case TextFor::material_value:
      use_material_value();
      break;
    case TextFor::texture_uri:
      surface_data_.back().texture.image = without_hash(text_);
      break;
    case TextFor::wrap_mode:
      surface_data_.back().texture.wrap_mode = without_hash(text_);
      break;
    case TextFor::texture_coordinates:
      surface_data_.back().rings.push_back({coordinates_ring_, numbers(text_), text_line_});
      break;
    case TextFor::texture_ring: {
      // The last coordinates without a ring take this one (3.0's pairing).
      auto& rings = surface_data_.back().rings;
      if (rings.empty() || !rings.back().ring.empty())
        fail_at(text_line_, "an app:ring " + quote_excerpt(text_) + " follows no app:textureCoordinates of its own");
      rings.back().ring = without_hash(text_);
      break;
    }
    case TextFor::implicit_matrix:
      implicit_->matrix = numbers(text_);
      if (implicit_->matrix.size() != 16)
        fail_at(text_line_,
                "a core:transformationMatrix has " + std::to_string(implicit_->matrix.size()) + " numbers, not 16");
      break;
    case TextFor::implicit_reference: {
      const auto values = numbers(text_);
      if (values.size() != 3) fail_at(text_line_, "an implicit geometry's reference point needs three coordinates");
      implicit_->reference = Vec3{values[0], values[1], values[2]};
      break;
    }
    case TextFor::nothing:
      break;
  }
}

void CityGmlParser::finish_ring() {
  in_ring_ = false;
  if (ring_.size() > 1 && ring_.front().x == ring_.back().x && ring_.front().y == ring_.back().y &&
      ring_.front().z == ring_.back().z)
    ring_.pop_back();  // GML closes rings by repeating the first point
  // A ring of one or two distinct points encloses nothing. Real files hold such rings
  // (the OGC's own CityGML 3.0 sample of Lyon, in a posList of two points), and refusing
  // the file lost a whole district for one: an exterior of them is kept, its polygon
  // then counted among the surfaces of zero area (city_placement.h), and a hole of them
  // is dropped. An empty ring is no ring at all.
  if (ring_.empty()) fail_at(ring_line_, "a ring (gml:LinearRing) without points");
  if (ring_is_interior_ && ring_.size() < 3) {
    if (!ring_id_.empty()) dropped_ring_ids_.insert(std::move(ring_id_));  // its texture coordinates are skipped
    ring_.clear();
    ring_id_.clear();
    return;
  }
  if (ring_is_interior_) {
    interiors_.push_back(std::move(ring_));
    interior_ids_.push_back(std::move(ring_id_));
  } else {
    exterior_ = std::move(ring_);
    exterior_id_ = std::move(ring_id_);
  }
  ring_id_.clear();
  ring_.clear();
}

void CityGmlParser::finish_polygon() {
  in_polygon_ = false;
  if (exterior_.empty()) fail_at(polygon_line_, "a polygon without an exterior ring");
  CitySurface surface;
  surface.rings.reserve(1 + interiors_.size());
  surface.rings.push_back(std::move(exterior_));
  for (auto& ring : interiors_) surface.rings.push_back(std::move(ring));
  exterior_.clear();
  interiors_.clear();
  const int index = static_cast<int>(polygons_.size());
  polygons_.push_back(std::move(surface));
  if (!polygon_id_.empty()) polygon_ids_.emplace(polygon_id_, index);
  if (options_.appearance.read) {  // rings named for their texture coordinates
    if (!exterior_id_.empty()) ring_ids_.emplace(exterior_id_, std::pair{index, 0});
    for (size_t r = 0; r < interior_ids_.size(); ++r)
      if (!interior_ids_[r].empty()) ring_ids_.emplace(interior_ids_[r], std::pair{index, static_cast<int>(r + 1)});
  }
  exterior_id_.clear();
  interior_ids_.clear();
  // The aggregates around it, innermost first, at most kAggregateLevels (a real file has
  // a multi-surface in a composite in a shell in a solid; a crafted one could nest
  // thousands, and every polygon would be listed under each).
  constexpr size_t kAggregateLevels = 8;
  for (size_t k = aggregates_.size(); k-- > 0 && aggregates_.size() - k <= kAggregateLevels;)
    aggregate_polygons_[aggregates_[k].first].push_back(index);
  if (polygon_used_) objects_.back().uses.push_back({lods_.back().first, current_semantic(), index, {}, polygon_line_});
}

void CityGmlParser::end(const XML_Char* /*name*/) {
  if (skip_depth_ > 0 && depth_ > skip_depth_) {
    --depth_;
    return;
  }
  skip_depth_ = 0;  // the skipped element itself ends below, like any other
  if (text_for_ != TextFor::nothing && text_depth_ == depth_) use_text();
  if (in_ring_ && ring_depth_ == depth_) finish_ring();
  if (in_polygon_ && polygon_depth_ == depth_) finish_polygon();
  if (surface_data_depth_ == depth_) surface_data_depth_ = 0;
  if (implicit_ && implicit_->depth == depth_) finish_implicit_geometry();
  if (!aggregates_.empty() && aggregates_.back().second == depth_) aggregates_.pop_back();
  if (!lods_.empty() && lods_.back().second == depth_) lods_.pop_back();
  if (!semantics_.empty() && semantics_.back().second == depth_) semantics_.pop_back();
  if (!dimensions_.empty() && dimensions_.back().second == depth_) dimensions_.pop_back();
  if (!objects_.empty() && objects_.back().depth == depth_) {
    finished_.push_back(std::move(objects_.back()));
    objects_.pop_back();
  }
  namespaces_.end_scope(depth_);
  --depth_;
}

std::vector<int> CityGmlParser::polygons_named(const std::string& id) const {
  if (auto p = polygon_ids_.find(id); p != polygon_ids_.end()) return {p->second};
  if (auto a = aggregate_polygons_.find(id); a != aggregate_polygons_.end()) return a->second;
  return {};
}

// An implicit geometry's polygons (its own, or copies of the relative geometry it refers
// to) moved to where it stands: p' = M p + reference (CityGML 2.0 §10.2.2), as CityJSON
// instances are.
void CityGmlParser::finish_implicit_geometry() {
  Implicit implicit = std::move(*implicit_);
  implicit_.reset();
  if (!implicit.reference) fail_at(implicit.line, "an implicit geometry without a core:referencePoint");
  if (implicit.matrix.empty()) implicit.matrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  if (!implicit.prototype.empty())
    prototypes_[implicit.prototype].assign(polygons_.begin() + static_cast<std::ptrdiff_t>(implicit.first_polygon),
                                           polygons_.end());
  if (!implicit.href.empty()) {
    const auto found = prototypes_.find(implicit.href);
    if (found == prototypes_.end())
      fail_at(implicit.line, "core:relativeGMLGeometry xlink:href=" + quote_excerpt("#" + implicit.href) +
                                 " names no implicit geometry before it");
    for (const CitySurface& surface : found->second) {
      objects_.back().uses.push_back(
          {lods_.back().first, current_semantic(), static_cast<int>(polygons_.size()), {}, implicit.line});
      polygons_.push_back(surface);
    }
  }
  const auto& m = implicit.matrix;
  const Vec3 r = *implicit.reference;
  for (size_t p = implicit.first_polygon; p < polygons_.size(); ++p)
    for (auto& ring : polygons_[p].rings)
      for (Vec3& v : ring) {
        const Vec3 q{m[0] * v.x + m[1] * v.y + m[2] * v.z + m[3], m[4] * v.x + m[5] * v.y + m[6] * v.z + m[7],
                     m[8] * v.x + m[9] * v.y + m[10] * v.z + m[11]};
        v = q + r;
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
          fail_at(implicit.line, "an implicit geometry's transformation gives a coordinate that is not finite");
      }
}

// The appearances of the chosen theme (the scene's, else the first the file gives)
// given to the polygons they target: X3D materials to polygons or aggregates by id,
// textures to the rings their coordinates name. The first appearance of each kind a
// polygon meets is kept.
void CityGmlParser::resolve_appearances(CityModel& model) {
  for (const SurfaceData& d : surface_data_)
    if (std::find(model.appearance_themes.begin(), model.appearance_themes.end(), d.theme) ==
        model.appearance_themes.end())
      model.appearance_themes.push_back(d.theme);
  if (surface_data_.empty()) return;
  const std::string theme = options_.appearance.theme.empty() ? surface_data_.front().theme : options_.appearance.theme;
  for (SurfaceData& d : surface_data_) {
    if (d.theme != theme) continue;
    if (d.is_material) {
      const int index = static_cast<int>(model.materials.size());
      for (const std::string& id : d.targets)
        for (int p : polygons_named(id))
          if (polygons_[p].material == CitySurface::kNone) polygons_[p].material = index;
      model.materials.push_back(std::move(d.material));
      model.material_theme = theme;
      continue;
    }
    if (d.texture.image.empty()) fail_at(d.line, "an app:ParameterizedTexture without an app:imageURI");
    const int index = static_cast<int>(model.textures.size());
    for (const RingCoordinates& coordinates : d.rings) {
      if (dropped_ring_ids_.contains(coordinates.ring)) continue;
      const auto found = ring_ids_.find(coordinates.ring);
      if (found == ring_ids_.end())
        fail_at(coordinates.line,
                "app:textureCoordinates ring=" + quote_excerpt("#" + coordinates.ring) + " names no ring in the file");
      const auto [p, r] = found->second;
      CitySurface& surface = polygons_[p];
      const size_t points = surface.rings[r].size(), pairs = coordinates.st.size() / 2;
      // GML rings repeat their first point at the end; their coordinates may too.
      if (coordinates.st.size() % 2 != 0 || (pairs != points && pairs != points + 1))
        fail_at(coordinates.line, "app:textureCoordinates give " + std::to_string(coordinates.st.size()) +
                                      " numbers for ring " + quote_excerpt("#" + coordinates.ring) + " of " +
                                      std::to_string(points) + " points: expected two per point");
      if (surface.texture != CitySurface::kNone && surface.texture != index) continue;
      if (surface.texture_coordinates.empty())
        for (const auto& ring : surface.rings) surface.texture_coordinates.emplace_back(ring.size());
      surface.texture = index;
      for (size_t k = 0; k < points; ++k)
        surface.texture_coordinates[r][k] = {static_cast<float>(coordinates.st[2 * k]),
                                             static_cast<float>(coordinates.st[2 * k + 1])};
    }
    model.textures.push_back(std::move(d.texture));
    model.texture_theme = theme;
  }
}

CityModel CityGmlParser::finish() {
  const CityGmlOptions& options = options_;
  CityModel model;
  resolve_appearances(model);
  // Which polygons each object keeps: those of its most detailed LoD, each once.
  std::vector<std::vector<std::pair<int, std::string>>> kept(finished_.size());
  std::vector<int> uses_left(polygons_.size(), 0);
  std::vector<bool> leave_out(finished_.size(), false);
  for (size_t o = 0; o < finished_.size(); ++o) {
    int lod = -1;
    for (const auto& use : finished_[o].uses)
      if (!options.lod || use.lod <= *options.lod) lod = std::max(lod, use.lod);
    finished_[o].object.lod = std::max(lod, 0);
    if (lod < 0 && options.lod) leave_out[o] = true;  // nothing at or below the chosen LoD
    std::unordered_map<int, size_t> slot;
    for (const auto& use : finished_[o].uses) {
      if (use.lod != lod) continue;
      std::vector<int> named = use.polygon >= 0 ? std::vector<int>{use.polygon} : polygons_named(use.href);
      // A surface of a room or other part not read (a 3.0 storey's walls are its rooms')
      // is left out with it; one the file lacks is an error.
      if (named.empty() && skipped_ids_.contains(use.href)) continue;
      if (named.empty())
        fail_at(use.line, "xlink:href " + quote_excerpt("#" + use.href) + " names no surface in the file");
      for (int p : named) {
        auto [at, added] = slot.emplace(p, kept[o].size());
        if (added) {
          kept[o].emplace_back(p, use.semantic);
          ++uses_left[p];
        } else if (kept[o][at->second].second.empty()) {
          kept[o][at->second].second = use.semantic;
        }
      }
    }
  }
  model.crs = crs_;
  model.objects.reserve(finished_.size());
  for (size_t o = 0; o < finished_.size(); ++o) {
    if (leave_out[o]) continue;
    CityObject object = std::move(finished_[o].object);
    object.surfaces.reserve(kept[o].size());
    for (auto& [p, semantic] : kept[o]) {
      // The last object to use a polygon takes it; earlier ones copy it.
      CitySurface surface = --uses_left[p] == 0 ? std::move(polygons_[p]) : polygons_[p];
      surface.semantic = std::move(semantic);
      object.surfaces.push_back(std::move(surface));
    }
    model.objects.push_back(std::move(object));
  }
  return model;
}

}  // namespace

CityModel parse_citygml(std::string_view text, const std::string& name, const CityGmlOptions& options) {
  CityGmlParser parser(name, options);
  parser.feed(text.data(), text.size(), true);
  return parser.finish();
}

CityModel read_citygml_file(const std::filesystem::path& file, const CityGmlOptions& options) {
  require_regular_file(file, "CityGML file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ":1: cannot read the CityGML file");
  CityGmlParser parser(file.string(), options);
  std::vector<char> buffer(size_t{1} << 20);
  while (true) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const auto got = static_cast<size_t>(in.gcount());
    if (in.bad()) throw InputError(file.string() + ": cannot read the CityGML file");
    const bool last = in.eof();
    parser.feed(buffer.data(), got, last);
    if (last) break;
  }
  return parser.finish();
}

}  // namespace skylit
