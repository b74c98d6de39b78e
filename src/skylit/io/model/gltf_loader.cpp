// glTF 2.0 geometry (.gltf with external or data-URI buffers, and .glb) through
// tinygltf: triangle-list primitives of every mesh instance in the scene, placed by
// the node hierarchy, each triangle with its primitive's material (metallic-roughness
// factors and the transmission, ior and volume extensions; docs/model-materials.md).
// Base-colour, emissive and normal textures (PNG, JPEG, BMP, TGA: io/model/texture_file.h) with
// the primitives' texture coordinates, emission, alphaMode and doubleSided, and the
// vertex normals (NORMAL). Positions and normals are morphed by their targets' default
// weights. Any of these accessors may be sparse. Everything else in the file is
// ignored. The file's own axes are kept (+Y up); load_model_file turns them into
// skylit's frame.
//
// This is the one translation unit that compiles tinygltf's implementation. tinygltf
// hands over the image bytes it finds inside the file (buffer views, data URIs); images
// in files beside it are read here; both are decoded by texture_file.h, only when a
// material uses them.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "skylit/core/error.h"
#include "skylit/core/formatted.h"
#include "skylit/core/text_file.h"
#include "skylit/geometry/transform.h"
#include "skylit/io/model/mesh_io.h"
#include "skylit/io/model/texture_file.h"

namespace skylit {
namespace {

// Required extensions that change only appearance, which skylit ignores anyway.
// Any other required extension (Draco, meshopt compression, ...) changes how the
// geometry is stored, so reading on would give wrong shapes.
bool harmless_extension(const std::string& name) {
  for (const char* prefix : {"KHR_materials_", "KHR_texture_", "EXT_texture_", "KHR_lights_punctual",
                             "KHR_mesh_quantization"})  // quantized positions are read below
    if (name.rfind(prefix, 0) == 0) return true;
  return false;
}

constexpr const char* kSpecularGlossiness = "KHR_materials_pbrSpecularGlossiness";
constexpr const char* kUnlit = "KHR_materials_unlit";

// A material extension's object, or null.
const tinygltf::Value* material_extension(const tinygltf::Material& m, const char* extension) {
  const auto e = m.extensions.find(extension);
  return e != m.extensions.end() && e->second.IsObject() ? &e->second : nullptr;
}

// A number in an extension's object, or `fallback`; `k`-th element of an array for k ≥ 0.
double value_number(const tinygltf::Value& object, const char* key, double fallback, int k = -1) {
  if (!object.Has(key)) return fallback;
  const tinygltf::Value* v = &object.Get(key);
  if (k >= 0) {
    if (!v->IsArray() || v->ArrayLen() <= static_cast<size_t>(k)) return fallback;
    v = &v->Get(k);
  }
  return v->IsNumber() && std::isfinite(v->GetNumberAsDouble()) ? v->GetNumberAsDouble() : fallback;
}

// A number in a material extension's object, or `fallback`.
double extension_number(const tinygltf::Material& m, const char* extension, const char* key, double fallback) {
  const tinygltf::Value* e = material_extension(m, extension);
  return e ? value_number(*e, key, fallback) : fallback;
}

// The older specular-glossiness model (KHR_materials_pbrSpecularGlossiness, archived by
// Khronos but still in many exports, often as a required extension with no
// metallic-roughness values at all, which then read as the spec's white metal). A
// specular colour above 0.2 at normal incidence no dielectric has (water 0.02, glass
// 0.04, diamond 0.17), so it is a metal of that colour, as MTL's black Kd with a bright
// Ks is; otherwise a coat whose index gives the specular's mean reflectance,
// n = (1 + √F0) / (1 − √F0), over a body of the diffuse colour. Roughness 1 − glossiness.
void read_specular_glossiness(const tinygltf::Value& sg, ModelMaterial& out) {
  for (int i = 0; i < 3; ++i) out.color_linear[static_cast<size_t>(i)] = value_number(sg, "diffuseFactor", 1.0, i);
  std::array<double, 3> specular{};
  for (int i = 0; i < 3; ++i)
    specular[static_cast<size_t>(i)] = std::clamp(value_number(sg, "specularFactor", 1.0, i), 0.0, 1.0);
  out.roughness = beckmann_from_gltf_roughness(1.0 - value_number(sg, "glossinessFactor", 1.0));
  if (out.kind == ModelMaterial::Kind::glass) return;
  if (std::max({specular[0], specular[1], specular[2]}) > 0.2) {
    out.kind = ModelMaterial::Kind::metal;
    out.color_linear = {specular[0], specular[1], specular[2]};
    return;
  }
  out.kind = ModelMaterial::Kind::coated;
  const double root_f0 = std::sqrt((specular[0] + specular[1] + specular[2]) / 3.0);
  out.ior = (1.0 + root_f0) / (1.0 - root_f0);
}

// The metallic-roughness model mapped onto skylit's kinds: mostly transmitting →
// glass; mostly metallic → a metal whose normal reflectance is the base colour;
// otherwise the spec's dielectric, a coat of index `ior` over a body of the base
// colour. Factors in between are rounded to the nearer kind (skylit does not blend).
// `metallic_roughness_mean` is the mean of the metallicRoughnessTexture (B metalness,
// G roughness), which multiplies the factors: with one kind per material, the mean
// decides it as the factor alone does without a texture. (Blender and most exporters
// leave metallicFactor out, 1 by the spec, when the texture carries the metalness:
// read by the factor alone, every such material was a metal.)
ModelMaterial model_material(const tinygltf::Material& m, size_t index,
                             const std::optional<Rgba>& metallic_roughness_mean) {
  ModelMaterial out;
  out.name = m.name.empty() ? "material " + std::to_string(index) : m.name;
  const auto& pbr = m.pbrMetallicRoughness;
  if (pbr.baseColorFactor.size() >= 3)  // linear by the spec
    out.color_linear = {pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]};
  const Rgba texture_scale = metallic_roughness_mean.value_or(Rgba{1, 1, 1, 1});
  const double metallic = pbr.metallicFactor * texture_scale[2];
  out.roughness = beckmann_from_gltf_roughness(pbr.roughnessFactor * texture_scale[1]);
  out.ior = extension_number(m, "KHR_materials_ior", "ior", 1.5);
  const double transmission = extension_number(m, "KHR_materials_transmission", "transmissionFactor", 0.0);
  const double thickness = extension_number(m, "KHR_materials_volume", "thicknessFactor", 0.0);
  if (transmission >= 0.5) {
    out.kind = ModelMaterial::Kind::glass;
    if (thickness > 0) out.thickness_m = thickness;
  } else if (metallic >= 0.5) {
    out.kind = ModelMaterial::Kind::metal;
  } else {
    out.kind = ModelMaterial::Kind::coated;
  }
  if (const tinygltf::Value* sg = material_extension(m, kSpecularGlossiness)) read_specular_glossiness(*sg, out);
  // An unlit material (KHR_materials_unlit: baked light, photogrammetry, signs) has no
  // reflection model to keep; its base colour is read as a matte body's, lit by the
  // scene (its metallic factors, often left at the default 1, ignored).
  if (material_extension(m, kUnlit)) out.kind = ModelMaterial::Kind::diffuse;
  // emissiveFactor × KHR_materials_emissive_strength, taken as cd/m²
  // (docs/model-materials.md).
  const double strength = extension_number(m, "KHR_materials_emissive_strength", "emissiveStrength", 1.0);
  if (m.emissiveFactor.size() >= 3)
    for (size_t i = 0; i < 3; ++i) out.emission_cd_m2[i] = m.emissiveFactor[i] * strength;
  return out;
}

// The encoded bytes of the images inside the file, by image index, as tinygltf finds
// them; decoded later, only if a material uses them.
using ImageBytes = std::map<int, std::vector<unsigned char>>;

bool keep_image_bytes(tinygltf::Image*, const int index, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void* user) {
  if (bytes != nullptr && size > 0) (*static_cast<ImageBytes*>(user))[index].assign(bytes, bytes + size);
  return true;
}

// tinygltf's file reading, with what every file input of ours refuses (issue 19, items
// 8 and 9): a buffer `uri` naming a folder ("." made tinygltf allocate the folder's
// nonsense size), a device such as /dev/zero, or a FIFO, which would block forever.
bool read_regular_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  const char* why = !std::filesystem::exists(status)                           ? "not found"
                    : !std::filesystem::is_regular_file(status)                ? "not a regular file"
                    : std::filesystem::file_size(path, ec) > kMaxMeshFileBytes ? "larger than the limit of 1 GiB"
                                                                               : nullptr;
  if (why != nullptr) {
    if (err) *err += "file " + quote_name(std::filesystem::path(path).filename().string()) + ": " + why + "\n";
    return false;
  }
  return tinygltf::ReadWholeFile(out, err, path, nullptr);
}

// tinygltf's own test opens the file, which for a FIFO waits for a writer forever.
bool file_exists(const std::string& path, void*) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

// tinygltf's message, on one line; a size mismatch names only what is wrong, not the
// size of whatever file the uri points at (item 16: "../../etc/passwd" showed its size).
std::string one_line(std::string s) {
  if (s.find("File size mismatch") != std::string::npos)
    return "a buffer's file does not have the byteLength the glTF gives it";
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  // tinygltf quotes a broken data URI whole (a truncated buffer gave a 135 KB line).
  constexpr size_t kLongest = 240;
  if (s.size() > kLongest) s = s.substr(0, kLongest) + "…";
  return s;
}

// %XX escapes in a URI (RFC 3986): glTF writes a file "Box With Spaces.png" as
// "Box%20With%20Spaces.png". Anything else, '+' included, is kept as it is.
std::string percent_decoded(const std::string& uri) {
  auto hex = [](char c) {
    return c >= '0' && c <= '9'   ? c - '0'
           : c >= 'a' && c <= 'f' ? c - 'a' + 10
           : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                  : -1;
  };
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
      out += static_cast<char>(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// The first extension the file requires that skylit does not read, read from its JSON
// directly (for .glb, the first chunk): tinygltf stops at what such an extension leaves
// out (Draco's buffer views) with a message that does not name it.
std::string unread_required_extension(const std::filesystem::path& path, bool binary) {
  std::ifstream in(path, std::ios::binary);
  std::string text;
  if (binary) {
    unsigned char header[20] = {};
    if (!in.read(reinterpret_cast<char*>(header), sizeof header)) return {};
    const uint32_t length = header[12] | header[13] << 8 | header[14] << 16 | static_cast<uint32_t>(header[15]) << 24;
    // A chunk longer than the file is not allocated (a 100-byte file claimed 578 MB).
    std::error_code ec;
    const std::uintmax_t file_bytes = std::filesystem::file_size(path, ec);
    if (ec || length > kMaxMeshFileBytes || length > file_bytes - sizeof header) return {};
    text.resize(length);
    if (!in.read(text.data(), length)) return {};
  } else {
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
  if (!document.is_object() || !document.contains("extensionsRequired") || !document["extensionsRequired"].is_array())
    return {};
  for (const nlohmann::json& e : document["extensionsRequired"])
    if (e.is_string() && !harmless_extension(e.get<std::string>())) return e.get<std::string>();
  return {};
}

// One accessor's elements, bounds-checked against its buffers once so reads need
// no further checks. Without a buffer view (`data` null) every element is zero (glTF
// 2.0 §3.6.2.1); a sparse accessor's elements at `replaced` are instead those of
// `replacements`, packed one after another in the same order (§3.6.2.3).
struct AccessorView {
  const unsigned char* data = nullptr;
  size_t count = 0;
  size_t stride = 0;
  int component_type = 0;
  int components = 0;
  bool normalized = false;
  std::vector<uint32_t> replaced;  // strictly increasing, each below count
  const unsigned char* replacements = nullptr;
  size_t replacement_stride = 0;

  // Component c of element i as a double, per the glTF rules for normalized ints.
  double get(size_t i, int c) const {
    const unsigned char* p = element(i);
    if (p == nullptr) return 0.0;
    switch (component_type) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return read<float>(p, c, 1.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return read<uint8_t>(p, c, 255.0);
      case TINYGLTF_COMPONENT_TYPE_BYTE:
        return read<int8_t>(p, c, 127.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return read<uint16_t>(p, c, 65535.0);
      case TINYGLTF_COMPONENT_TYPE_SHORT:
        return read<int16_t>(p, c, 32767.0);
      default:
        return read<uint32_t>(p, c, 4294967295.0);
    }
  }

 private:
  // Element i's bytes; null for a zero.
  const unsigned char* element(size_t i) const {
    const auto r = std::lower_bound(replaced.begin(), replaced.end(), i);
    if (r != replaced.end() && *r == i)
      return replacements + static_cast<size_t>(r - replaced.begin()) * replacement_stride;
    return data == nullptr ? nullptr : data + i * stride;
  }

  template <typename T>
  double read(const unsigned char* p, int c, double norm) const {
    T value;
    std::memcpy(&value, p + c * sizeof(T), sizeof(T));
    const double x = static_cast<double>(value);
    return normalized ? std::max(x / norm, -1.0) : x;
  }
};

class GltfReader {
 public:
  GltfReader(const tinygltf::Model& model, std::string name, const ImageBytes& images, std::filesystem::path folder)
      : model_(model), name_(std::move(name)), images_(images), folder_(std::move(folder)) {
    for (const tinygltf::Buffer& buffer : model_.buffers) buffer_bytes_ += buffer.data.size();
    std::vector<std::string> default_metals, unlit;
    for (size_t i = 0; i < model_.materials.size(); ++i) {
      const tinygltf::Material& m = model_.materials[i];
      const auto& pbr = m.pbrMetallicRoughness;
      std::optional<Rgba> metallic_roughness_mean;
      if (const auto t = texture(pbr.metallicRoughnessTexture.index, TextureEncoding::linear))
        metallic_roughness_mean = t->mean();
      ModelMaterial material = model_material(m, i, metallic_roughness_mean);
      const tinygltf::Value* sg = material_extension(m, kSpecularGlossiness);
      const int color_index = sg ? texture_index(*sg, "diffuseTexture") : pbr.baseColorTexture.index;
      material.color_texture = texture(color_index, TextureEncoding::srgb);
      material.emission_texture = texture(m.emissiveTexture.index, TextureEncoding::srgb);
      material.normal_texture = texture(m.normalTexture.index, TextureEncoding::linear);  // data, not colour
      material.normal_scale = m.normalTexture.scale;
      // One texture coordinate set per material, with its KHR_texture_transform: the base
      // colour's, else the emission's, else the normal map's (exporters give them all
      // TEXCOORD_0 and one transform: a material's tiling).
      if (material.normal_texture) use_uvs_of(i, m.normalTexture.texCoord, m.normalTexture.extensions);
      if (material.emission_texture) use_uvs_of(i, m.emissiveTexture.texCoord, m.emissiveTexture.extensions);
      if (material.color_texture) {
        if (sg)
          use_uvs_of(i, texture_set(*sg, "diffuseTexture"), {});
        else
          use_uvs_of(i, pbr.baseColorTexture.texCoord, pbr.baseColorTexture.extensions);
      }
      set_alpha(m, material, sg);
      if (material.alpha_cutoff > 0 && !material.alpha_texture && material.alpha_factor < material.alpha_cutoff)
        out_.read_warnings.push_back(
            "material " + quote_name(material.name) +
            formatted(" is cut away whole: alphaMode MASK with alpha %.3g below its alphaCutoff "
                      "%.3g and no texture",
                      material.alpha_factor, material.alpha_cutoff));
      if (!sg && is_metal_by_default(m, material, metallic_roughness_mean.has_value()))
        default_metals.push_back(quote_name(material.name));
      if (material_extension(m, kUnlit)) unlit.push_back(quote_name(material.name));
      out_.materials.push_back(std::move(material));
    }
    warn_of_default_metals(default_metals);
    if (!unlit.empty())
      out_.read_warnings.push_back(
          (unlit.size() == 1 ? "material " : "materials ") + first_few(unlit, 4) +
          " (KHR_materials_unlit) read as matte surfaces of their base colour, lit by the scene's sun and sky: an "
          "unlit look (light baked into the texture) is not kept");
  }

  // A textureInfo inside an extension's object: its texture index (−1 for none) and
  // texture coordinate set.
  static int texture_index(const tinygltf::Value& object, const char* key) {
    if (!object.Has(key) || !object.Get(key).Has("index") || !object.Get(key).Get("index").IsInt()) return -1;
    return object.Get(key).Get("index").GetNumberAsInt();
  }
  static int texture_set(const tinygltf::Value& object, const char* key) {
    const tinygltf::Value& info = object.Get(key);
    return info.Has("texCoord") && info.Get("texCoord").IsInt() ? info.Get("texCoord").GetNumberAsInt() : 0;
  }

  // glTF's default metallicFactor is 1, so a material that gives none is a metal, and
  // skylit's metals take their texture's mean colour: COLLADA2GLTF and other old
  // exporters wrote textured dielectrics so, and the texture vanished without a word.
  // (A specular-glossiness material has its own model; the caller does not ask.)
  static bool is_metal_by_default(const tinygltf::Material& m, const ModelMaterial& material, bool metalness_texture) {
    return material.kind == ModelMaterial::Kind::metal && material.color_texture && !metalness_texture &&
           m.values.count("metallicFactor") == 0;
  }

  // One line for all of them (a model may have hundreds), naming the first few.
  void warn_of_default_metals(const std::vector<std::string>& names) {
    if (names.empty()) return;
    const bool one = names.size() == 1;
    out_.read_warnings.push_back(
        (one ? "material " : "materials ") + first_few(names, 4) + (one ? " gives" : " give") +
        " no metallicFactor: by glTF's default a metal, shown by its texture's mean colour "
        "only; if not metal, give \"metallicFactor\": 0 in the file or override (\"material_overrides\")");
  }

  // alphaMode (docs/model-materials.md): MASK cuts holes where the base colour's alpha
  // (factor × texel) is below alphaCutoff; BLEND, which skylit cannot blend, makes a
  // material whose factor is translucent a glass pane (as MTL's d does) and cuts holes
  // where its texture's alpha is below one half; OPAQUE ignores alpha.
  static void set_alpha(const tinygltf::Material& m, ModelMaterial& material, const tinygltf::Value* sg) {
    material.double_sided = m.doubleSided;
    const auto& factor = m.pbrMetallicRoughness.baseColorFactor;
    const double alpha = sg                                               ? value_number(*sg, "diffuseFactor", 1.0, 3)
                         : factor.size() >= 4 && std::isfinite(factor[3]) ? factor[3]
                                                                          : 1.0;
    if (m.alphaMode == "MASK") {
      material.alpha_cutoff = m.alphaCutoff;
      material.alpha_factor = alpha;
      material.alpha_texture = material.color_texture;
    } else if (m.alphaMode == "BLEND") {
      if (alpha < 0.99 && material.kind != ModelMaterial::Kind::glass) {
        material.kind = ModelMaterial::Kind::glass;
        material.roughness = 0;  // as MTL's d: window glass is flat
      }
      if (material.color_texture) {
        material.alpha_cutoff = 0.5;
        material.alpha_texture = material.color_texture;
      }
    }
  }

  LoadedModel read_scene() {
    std::vector<int> roots;
    if (model_.defaultScene >= 0 && static_cast<size_t>(model_.defaultScene) >= model_.scenes.size())
      fail("the default scene is scene " + std::to_string(model_.defaultScene) + ", but the file has " +
           std::to_string(model_.scenes.size()));
    if (model_.defaultScene >= 0)
      roots = model_.scenes[model_.defaultScene].nodes;
    else if (!model_.scenes.empty())
      roots = model_.scenes[0].nodes;
    else
      roots = root_nodes();
    for (int node : roots) visit(node, Transform::identity(), 0);
    if (!any_uv_) out_.corner_uvs.clear();
    if (!any_normal_) out_.corner_normals.clear();
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(name_ + ": " + what); }

  std::vector<int> root_nodes() const {
    std::vector<bool> is_child(model_.nodes.size(), false);
    for (const auto& node : model_.nodes)
      for (int c : node.children)
        if (c >= 0 && static_cast<size_t>(c) < is_child.size()) is_child[c] = true;
    std::vector<int> roots;
    for (size_t i = 0; i < is_child.size(); ++i)
      if (!is_child[i]) roots.push_back(static_cast<int>(i));
    return roots;
  }

  Transform local_transform(const tinygltf::Node& node, int index) const {
    if (node.matrix.size() == 16) {
      std::array<double, 16> c;
      std::copy(node.matrix.begin(), node.matrix.end(), c.begin());
      return Transform::from_column_major_4x4(c);
    }
    Transform t;
    if (node.translation.size() == 3)
      t = Transform::translation({node.translation[0], node.translation[1], node.translation[2]});
    if (node.rotation.size() == 4) {
      const auto& q = node.rotation;
      if (!(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] > 0))
        fail("node " + std::to_string(index) + (node.name.empty() ? "" : " ('" + node.name + "')") +
             " has a zero rotation");
      t = t * Transform::rotation_quaternion(q[0], q[1], q[2], q[3]);
    }
    if (node.scale.size() == 3) t = t * Transform::scale({node.scale[0], node.scale[1], node.scale[2]});
    return t;
  }

  void visit(int index, const Transform& parent, size_t depth) {
    if (index < 0 || static_cast<size_t>(index) >= model_.nodes.size())
      fail("scene refers to node " + std::to_string(index) + " which does not exist");
    // A tree cannot be deeper than its node count, so deeper means a cycle; the
    // fixed cap keeps a hostile file from exhausting the stack.
    if (depth > model_.nodes.size() || depth > kMaxDepth)
      fail("the node hierarchy has a cycle or is deeper than " + std::to_string(kMaxDepth) + " levels");
    const tinygltf::Node& node = model_.nodes[index];
    const Transform world = parent * local_transform(node, index);
    if (node.mesh >= 0) {
      const Part& part = mesh(node.mesh, node.weights);
      out_.mesh.append(transformed(part.mesh, world));
      out_.triangle_material.insert(out_.triangle_material.end(), part.material.begin(), part.material.end());
      std::vector<CornerUvs> uvs = part.uvs;
      if (world.determinant() < 0) reverse_corner_order(uvs);  // as transformed() turned the triangles
      out_.corner_uvs.insert(out_.corner_uvs.end(), uvs.begin(), uvs.end());
      std::vector<CornerNormals> normals = part.normals;
      transform_corner_normals(normals, world);
      out_.corner_normals.insert(out_.corner_normals.end(), normals.begin(), normals.end());
    }
    for (int child : node.children) visit(child, world, depth + 1);
  }

  // A mesh in its own space with its triangles' materials.
  struct Part {
    TriangleMesh mesh;
    std::vector<int32_t> material;
    std::vector<CornerUvs> uvs;          // per triangle, zero without TEXCOORD
    std::vector<CornerNormals> normals;  // per triangle, zero without NORMAL
  };

  // A mesh at the morph target weights in force, the node's, else the mesh's own
  // (glTF 2.0 §3.7.2.2: the mesh's are the defaults), built once however many nodes use
  // it so.
  const Part& mesh(int index, const std::vector<double>& node_weights) {
    if (static_cast<size_t>(index) >= model_.meshes.size())
      fail("a node refers to mesh " + std::to_string(index) + " which does not exist");
    const tinygltf::Mesh& mesh = model_.meshes[static_cast<size_t>(index)];
    const std::vector<double>& weights = node_weights.empty() ? mesh.weights : node_weights;
    auto [it, inserted] = meshes_.try_emplace({index, weights});
    if (inserted)
      for (const auto& primitive : mesh.primitives) {
        const TriangleMesh triangles = read_primitive(primitive, weights);
        it->second.mesh.append(triangles);
        const int32_t material = material_of(primitive);
        it->second.material.insert(it->second.material.end(), triangles.triangles.size(), material);
        read_uvs(primitive, material, triangles, it->second.uvs);
        read_normals(primitive, weights, triangles, it->second.normals);
      }
    return it->second;
  }

  // Adds the primitive's morph targets of `attribute` (POSITION, NORMAL), each times its
  // weight, to `values`, one per vertex: the spec's base + Σ wᵢ targetᵢ. A target without
  // a weight has weight 0 (the spec's default), and a target of weight 0 is not read.
  void add_morph_targets(const tinygltf::Primitive& primitive, const std::vector<double>& weights,
                         const std::string& attribute, std::vector<Vec3>& values) const {
    for (size_t t = 0; t < primitive.targets.size() && t < weights.size(); ++t) {
      const auto found = primitive.targets[t].find(attribute);
      if (weights[t] == 0 || found == primitive.targets[t].end()) continue;
      const AccessorView d = view(found->second, (attribute + " morph target").c_str());
      if (d.components != 3) fail("a " + attribute + " morph target accessor is not VEC3");
      if (d.count < values.size()) fail("a " + attribute + " morph target has fewer elements than POSITION");
      for (size_t i = 0; i < values.size(); ++i) values[i] += weights[t] * Vec3{d.get(i, 0), d.get(i, 1), d.get(i, 2)};
    }
  }

  int32_t material_of(const tinygltf::Primitive& primitive) const {
    if (primitive.material < 0) return LoadedModel::kNoMaterial;
    if (static_cast<size_t>(primitive.material) >= model_.materials.size())
      fail("a primitive refers to material " + std::to_string(primitive.material) + " which does not exist");
    return primitive.material;
  }

  TriangleMesh read_primitive(const tinygltf::Primitive& primitive, const std::vector<double>& weights) {
    TriangleMesh mesh;
    // tinygltf fills in the spec's default mode (4, triangles) when absent. Points and
    // lines are no surfaces: counted for `skylit info`, not drawn.
    const int mode = primitive.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      ++out_.skipped_primitives;
      return mesh;
    }
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) return mesh;

    const AccessorView p = view(position->second, "POSITION");
    if (p.components != 3) fail("POSITION accessor is not VEC3");
    mesh.vertices.reserve(p.count);
    for (size_t i = 0; i < p.count; ++i) mesh.vertices.emplace_back(p.get(i, 0), p.get(i, 1), p.get(i, 2));
    add_morph_targets(primitive, weights, "POSITION", mesh.vertices);

    std::vector<uint32_t> indices;
    if (primitive.indices >= 0) {
      const AccessorView ix = view(primitive.indices, "indices");
      if (ix.components != 1 || ix.normalized || ix.component_type == TINYGLTF_COMPONENT_TYPE_FLOAT ||
          ix.component_type == TINYGLTF_COMPONENT_TYPE_BYTE || ix.component_type == TINYGLTF_COMPONENT_TYPE_SHORT)
        fail("indices accessor must hold unsigned integer scalars");
      indices.reserve(ix.count);
      for (size_t i = 0; i < ix.count; ++i) {
        const double v = ix.get(i, 0);
        if (v >= static_cast<double>(p.count))
          fail("an index (" + std::to_string(static_cast<uint64_t>(v)) + ") is beyond the " + std::to_string(p.count) +
               " vertices");
        indices.push_back(static_cast<uint32_t>(v));
      }
    } else {
      // Not indexed: consecutive vertices form triangles.
      for (size_t i = 0; i < p.count; ++i) indices.push_back(static_cast<uint32_t>(i));
    }
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      if (indices.size() % 3 != 0)
        fail("a triangle primitive has " + std::to_string(indices.size()) + " indices, not a multiple of 3");
      for (size_t i = 0; i < indices.size(); i += 3)
        mesh.triangles.push_back({indices[i], indices[i + 1], indices[i + 2]});
      return mesh;
    }
    // Strips and fans by the glTF 2.0 specification (§3.7.2.1): a strip's triangle i is
    // (v_i, v_{i+1+i%2}, v_{i+2−i%2}), which keeps every triangle's winding; a fan's is
    // (v_{i+1}, v_{i+2}, v_0). Triangles with a repeated vertex (a strip's joins) are
    // left out.
    for (size_t i = 0; i + 2 < indices.size(); ++i) {
      const std::array<uint32_t, 3> t = mode == TINYGLTF_MODE_TRIANGLE_STRIP
                                            ? std::array{indices[i], indices[i + 1 + i % 2], indices[i + 2 - i % 2]}
                                            : std::array{indices[i + 1], indices[i + 2], indices[0]};
      if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) mesh.triangles.push_back(t);
    }
    return mesh;
  }

  // The texture coordinates of the set the primitive's material's texture uses, at each
  // corner of the primitive's triangles (read again by index: read_primitive keeps
  // only positions).
  void read_uvs(const tinygltf::Primitive& primitive, int32_t material, const TriangleMesh& triangles,
                std::vector<CornerUvs>& uvs) {
    const auto set = uv_set_.find(material);
    const auto attribute =
        primitive.attributes.find("TEXCOORD_" + std::to_string(set == uv_set_.end() ? 0 : set->second));
    if (triangles.empty() || set == uv_set_.end() || attribute == primitive.attributes.end()) {
      if (!triangles.empty() && set != uv_set_.end() && uvless_materials_.insert(material).second)
        out_.read_warnings.push_back("material " + quote_name(out_.materials[static_cast<size_t>(material)].name) +
                                     ": its texture reads TEXCOORD_" + std::to_string(set->second) +
                                     ", which a primitive using it does not have (shown untextured)");
      uvs.insert(uvs.end(), triangles.triangles.size(), CornerUvs{});
      return;
    }
    const AccessorView t = view(attribute->second, "TEXCOORD");
    if (t.components != 2) fail("a TEXCOORD accessor is not VEC2");
    if (t.count < triangles.vertices.size()) fail("a TEXCOORD accessor has fewer elements than POSITION");
    const auto transform = uv_transform_.find(material);
    for (const auto& tri : triangles.triangles) {
      CornerUvs corner{};
      for (size_t k = 0; k < 3; ++k) {
        double u = t.get(tri[k], 0), v = t.get(tri[k], 1);
        if (transform != uv_transform_.end()) {
          const std::array<double, 6>& m = transform->second;
          const double tu = m[0] * u + m[1] * v + m[2], tv = m[3] * u + m[4] * v + m[5];
          u = tu, v = tv;
        }
        corner[k] = {std::isfinite(u) ? static_cast<float>(u) : 0.0f, std::isfinite(v) ? static_cast<float>(v) : 0.0f};
      }
      uvs.push_back(corner);
    }
    any_uv_ = true;
  }

  // The NORMAL attribute, morphed as the positions are, at each corner of the
  // primitive's triangles; zero (flat, by sanitize_file_normals) without one. Values are
  // checked and normalised later, not here.
  void read_normals(const tinygltf::Primitive& primitive, const std::vector<double>& weights,
                    const TriangleMesh& triangles, std::vector<CornerNormals>& normals) {
    const auto attribute = primitive.attributes.find("NORMAL");
    if (triangles.empty() || attribute == primitive.attributes.end()) {
      normals.insert(normals.end(), triangles.triangles.size(), CornerNormals{});
      return;
    }
    const AccessorView n = view(attribute->second, "NORMAL");
    if (n.components != 3) fail("a NORMAL accessor is not VEC3");
    if (n.count < triangles.vertices.size()) fail("a NORMAL accessor has fewer elements than POSITION");
    std::vector<Vec3> vertex_normals;
    vertex_normals.reserve(triangles.vertices.size());
    for (size_t i = 0; i < triangles.vertices.size(); ++i)
      vertex_normals.emplace_back(n.get(i, 0), n.get(i, 1), n.get(i, 2));
    add_morph_targets(primitive, weights, "NORMAL", vertex_normals);
    const auto at = [&](uint32_t v) {
      const Vec3& m = vertex_normals[v];
      return std::array{static_cast<float>(m.x), static_cast<float>(m.y), static_cast<float>(m.z)};
    };
    for (const auto& tri : triangles.triangles) normals.push_back({at(tri[0]), at(tri[1]), at(tri[2])});
    any_normal_ = true;
  }

  // Material `index` reads TEXCOORD_`set`, or the set and transform its textureInfo's
  // KHR_texture_transform gives: uv' = T(offset) R(rotation) S(scale) (u, v, 1), with
  // R = [cos r, sin r; −sin r, cos r] (row by row), the rotation of the extension's
  // sample model, Khronos' and Blender's importers, three.js and Babylon. The GLSL
  // listing in the extension's text, read column by column as GLSL reads it, turns the
  // other way: a known error of the listing (KhronosGroup/glTF issue 1563).
  void use_uvs_of(int32_t index, int set, const tinygltf::ExtensionMap& extensions) {
    uv_set_[index] = set;
    uv_transform_.erase(index);
    const auto found = extensions.find("KHR_texture_transform");
    if (found == extensions.end() || !found->second.IsObject()) return;
    const tinygltf::Value& t = found->second;
    auto number = [&](const tinygltf::Value& v, double fallback) {
      return v.IsNumber() && std::isfinite(v.GetNumberAsDouble()) ? v.GetNumberAsDouble() : fallback;
    };
    auto pair = [&](const char* key, double fallback) {
      std::array<double, 2> out{fallback, fallback};
      if (t.Has(key) && t.Get(key).IsArray() && t.Get(key).ArrayLen() == 2)
        for (int k = 0; k < 2; ++k) out[k] = number(t.Get(key).Get(k), fallback);
      return out;
    };
    const auto offset = pair("offset", 0.0), scale = pair("scale", 1.0);
    const double r = t.Has("rotation") ? number(t.Get("rotation"), 0.0) : 0.0;
    if (t.Has("texCoord") && t.Get("texCoord").IsInt()) uv_set_[index] = t.Get("texCoord").GetNumberAsInt();
    const double c = std::cos(r), sn = std::sin(r);
    uv_transform_[index] = {c * scale[0], sn * scale[1], offset[0], -sn * scale[0], c * scale[1], offset[1]};
  }

  // The texture a material's textureInfo names, decoded once per image; null for none,
  // and for an image file that cannot be found (listed as missing).
  // Read through the texture's sampler's wrapS and wrapT (glTF 2.0 §5.26; repeat by
  // default); the filters are the renderer's own (texture.h).
  std::shared_ptr<const Texture> texture(int index, TextureEncoding encoding) {
    if (index < 0) return nullptr;
    if (static_cast<size_t>(index) >= model_.textures.size())
      fail("a material refers to texture " + std::to_string(index) + " which does not exist");
    const tinygltf::Texture& texture = model_.textures[static_cast<size_t>(index)];
    if (texture.source < 0) {
      warn_of_unread_image_extensions(texture);
      return nullptr;
    }
    std::shared_ptr<const Texture> image = image_texture(texture.source, encoding);
    if (!image || texture.sampler < 0 || static_cast<size_t>(texture.sampler) >= model_.samplers.size()) return image;
    const tinygltf::Sampler& sampler = model_.samplers[static_cast<size_t>(texture.sampler)];
    const TextureWrap u = wrap_of(sampler.wrapS), v = wrap_of(sampler.wrapT);
    if (u == TextureWrap::repeat && v == TextureWrap::repeat) return image;
    auto [it, added] = wrapped_textures_.try_emplace({texture.source, encoding, u, v});
    if (added) it->second = std::make_shared<const Texture>(image->with_wrap(u, v));
    return it->second;
  }

  static TextureWrap wrap_of(int gl_wrap) {
    if (gl_wrap == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return TextureWrap::clamp_to_edge;
    if (gl_wrap == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return TextureWrap::mirrored_repeat;
    return TextureWrap::repeat;
  }

  // A texture whose image only an extension gives (WebP, KTX2 with Basis Universal,
  // AVIF; with a PNG or JPEG fallback `source` is that and is read): said once per
  // extension, as its materials then show their colour factors alone.
  void warn_of_unread_image_extensions(const tinygltf::Texture& texture) {
    for (const auto& [extension, value] : texture.extensions)
      if (value.IsObject() && value.Has("source") && unread_image_extensions_.insert(extension).second)
        out_.read_warnings.push_back("textures given only by " + extension +
                                     " are not read (skylit reads PNG, JPEG, BMP and TGA): their materials "
                                     "show their colour factors alone; export the images as PNG or JPEG");
  }

  // The texture of image `source`, decoded once per encoding.
  std::shared_ptr<const Texture> image_texture(int source, TextureEncoding encoding) {
    if (static_cast<size_t>(source) >= model_.images.size())
      fail("a texture refers to image " + std::to_string(source) + " which does not exist");
    auto [it, added] = textures_.try_emplace({source, encoding});
    if (!added) return it->second;
    const tinygltf::Image& image = model_.images[static_cast<size_t>(source)];
    const std::string where = name_ + ": image " + std::to_string(source);
    if (const auto bytes = images_.find(source); bytes != images_.end()) {
      it->second = decode_texture(bytes->second.data(), bytes->second.size(), encoding, where);
    } else if (image.uri.rfind("data:", 0) == 0) {
      // A data URI whose media type tinygltf does not list ("image/jpg", "image/webp",
      // none): its bytes, which decode_texture takes if they are a PNG, JPEG, BMP or TGA.
      const size_t comma = image.uri.find(',');
      if (comma == std::string::npos || !std::string_view(image.uri).substr(0, comma).ends_with(";base64"))
        fail("image " + std::to_string(source) + ": a data URI that is not base64");
      const std::string bytes = tinygltf::base64_decode(image.uri.substr(comma + 1));
      it->second = decode_texture(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), encoding, where);
    } else if (!image.uri.empty()) {
      const std::string uri = percent_decoded(image.uri);
      const std::filesystem::path file = folder_ / uri;
      std::error_code ec;
      if (std::filesystem::is_regular_file(file, ec))
        it->second = read_texture_file(file, encoding, where);
      else if (std::find(out_.missing_images.begin(), out_.missing_images.end(), uri) ==
               out_.missing_images.end())  // listed once, though read as colour and as data
        out_.missing_images.push_back(uri);
    }
    return it->second;
  }

  AccessorView view(int accessor_index, const char* what) const {
    const std::string label = std::string(what) + " accessor " + std::to_string(accessor_index);
    if (accessor_index < 0 || static_cast<size_t>(accessor_index) >= model_.accessors.size())
      fail(label + " does not exist");
    const tinygltf::Accessor& a = model_.accessors[accessor_index];
    // Zeros cost no bytes of the file, so a small file could claim billions of them.
    if (a.bufferView < 0 && a.count > buffer_bytes_)
      fail(label + " has no buffer view and " + std::to_string(a.count) +
           " elements, more than the file's buffers have bytes");
    AccessorView v = elements(label, a.bufferView, a.byteOffset, a.count, a.componentType, a.type, true);
    v.normalized = a.normalized;
    if (a.sparse.isSparse) replace_sparse(label, a, v);
    return v;
  }

  // `count` elements of `component_type` and `type` from byte `offset` of buffer view
  // `buffer_view`, checked to lie in the view and the view in its buffer; all zeros for
  // buffer view −1. The view may give a byteStride only if `strided`.
  AccessorView elements(const std::string& label, int buffer_view, size_t offset, size_t count, int component_type,
                        int type, bool strided) const {
    AccessorView v;
    v.count = count;
    v.component_type = component_type;
    const int component_size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(component_type));
    v.components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(type));
    if (component_size <= 0 || v.components <= 0 || v.components > 4) fail(label + " has an unknown type");
    const size_t element = static_cast<size_t>(component_size) * static_cast<size_t>(v.components);
    v.stride = element;
    if (buffer_view < 0) return v;
    if (static_cast<size_t>(buffer_view) >= model_.bufferViews.size())
      fail(label + " refers to buffer view " + std::to_string(buffer_view) + ", which does not exist");
    const tinygltf::BufferView& bv = model_.bufferViews[buffer_view];
    if (bv.buffer < 0 || static_cast<size_t>(bv.buffer) >= model_.buffers.size())
      fail(label + ": its buffer view has no buffer");
    const std::vector<unsigned char>& buffer = model_.buffers[bv.buffer].data;
    if (bv.byteStride != 0 && !strided) fail(label + ": its buffer view has a byteStride, which glTF forbids here");
    if (bv.byteStride != 0) v.stride = bv.byteStride;
    if (v.stride < element) fail(label + ": byteStride is smaller than one element");

    // Everything read must lie in the view, and the view in the buffer; written
    // so that no sum or product can overflow.
    if (bv.byteOffset > buffer.size() || bv.byteLength > buffer.size() - bv.byteOffset)
      fail(label + ": buffer view runs past the end of its buffer");
    if (count > 0) {
      const size_t room = bv.byteLength;
      if (offset > room || element > room - offset || (count - 1) > (room - offset - element) / v.stride)
        fail(label + " runs past the end of its buffer view");
    }
    v.data = buffer.data() + bv.byteOffset + offset;
    return v;
  }

  // A sparse accessor's replaced elements (glTF 2.0 §3.6.2.3): `sparse.count` indices
  // (unsigned bytes, shorts or ints), strictly increasing and each below the accessor's
  // count, and as many values of the accessor's own type, each packed in a buffer view.
  void replace_sparse(const std::string& label, const tinygltf::Accessor& a, AccessorView& v) const {
    const auto& sparse = a.sparse;
    if (sparse.count < 1 || static_cast<size_t>(sparse.count) > a.count)
      fail(label + ": its sparse count " + std::to_string(sparse.count) + " is not between 1 and its count " +
           std::to_string(a.count));
    const int type = sparse.indices.componentType;
    if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
      fail(label + ": its sparse indices are not unsigned bytes, shorts or ints");
    if (sparse.indices.bufferView < 0 || sparse.values.bufferView < 0)
      fail(label + ": its sparse indices or values have no buffer view");
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
      fail(label + ": its sparse indices or values have a negative byteOffset");
    const auto n = static_cast<size_t>(sparse.count);
    const AccessorView indices =
        elements(label + " (sparse indices)", sparse.indices.bufferView, static_cast<size_t>(sparse.indices.byteOffset),
                 n, type, TINYGLTF_TYPE_SCALAR, false);
    const AccessorView values =
        elements(label + " (sparse values)", sparse.values.bufferView, static_cast<size_t>(sparse.values.byteOffset), n,
                 a.componentType, a.type, false);
    v.replaced.reserve(n);
    for (size_t k = 0; k < n; ++k) {
      const auto i = static_cast<uint32_t>(indices.get(k, 0));
      if (i >= a.count)
        fail(label + ": its sparse index " + std::to_string(i) + " is beyond its " + std::to_string(a.count) +
             " elements");
      if (k > 0 && i <= v.replaced.back())
        fail(label + ": its sparse indices are not strictly increasing (" + std::to_string(v.replaced.back()) +
             " then " + std::to_string(i) + ")");
      v.replaced.push_back(i);
    }
    v.replacements = values.data;
    v.replacement_stride = values.stride;
  }

  static constexpr size_t kMaxDepth = 1000;
  const tinygltf::Model& model_;
  std::string name_;
  const ImageBytes& images_;
  std::filesystem::path folder_;
  std::map<std::pair<int, TextureEncoding>, std::shared_ptr<const Texture>> textures_;  // by image
  std::map<std::tuple<int, TextureEncoding, TextureWrap, TextureWrap>, std::shared_ptr<const Texture>>
      wrapped_textures_;  // by image and sampler wraps other than repeat
  std::set<std::string> unread_image_extensions_;
  std::map<int32_t, int> uv_set_;       // by material: its texture's TEXCOORD set
  std::set<int32_t> uvless_materials_;  // warned of: a primitive lacks their TEXCOORD set
  // By material: its texture's KHR_texture_transform, uv' = M (u, v, 1), row-major 2 × 3.
  std::map<int32_t, std::array<double, 6>> uv_transform_;
  bool any_uv_ = false;
  bool any_normal_ = false;
  std::map<std::pair<int, std::vector<double>>, Part> meshes_;  // by mesh and morph weights
  LoadedModel out_;
  size_t buffer_bytes_ = 0;  // in all the file's buffers together
};

}  // namespace

LoadedModel load_gltf_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  tinygltf::TinyGLTF loader;
  ImageBytes images;
  loader.SetImageLoader(&keep_image_bytes, &images);
  tinygltf::FsCallbacks files{};
  files.FileExists = &file_exists;
  files.ExpandFilePath = &tinygltf::ExpandFilePath;
  files.ReadWholeFile = &read_regular_file;
  files.WriteWholeFile = &tinygltf::WriteWholeFile;
  loader.SetFsCallbacks(files);
  tinygltf::Model model;
  std::string err, warn;
  // Binary or JSON by the GLB magic rather than the extension, so a .glb saved
  // as .gltf (or the reverse) still loads.
  char magic[4] = {};
  std::ifstream(path, std::ios::binary).read(magic, 4);
  const bool binary = std::memcmp(magic, "glTF", 4) == 0;
  const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, name)
                         : loader.LoadASCIIFromFile(&model, &err, &warn, name);
  if (!ok) {
    if (const std::string ext = unread_required_extension(path, binary); !ext.empty())
      throw InputError(name + ": requires glTF extension " + ext + ", which skylit does not read" +
                       (ext == "KHR_draco_mesh_compression" ? " (Draco compression: export without it)" : ""));
    throw InputError(name + ": cannot read glTF: " + one_line(err.empty() ? warn : err));
  }
  // glTF 1.0 is another format (techniques, shaders, no PBR materials) that tinygltf
  // half reads.
  if (model.asset.version.rfind("2.", 0) != 0)
    throw InputError(name + ": glTF version " + quote_excerpt(model.asset.version) + "; skylit reads glTF 2.0");
  for (const std::string& ext : model.extensionsRequired)
    if (!harmless_extension(ext))
      throw InputError(name + ": requires glTF extension " + ext + ", which skylit does not read");
  return GltfReader(model, name, images, path.parent_path()).read_scene();
}

}  // namespace skylit
