// Shading and visibility from model files (issue 21): the file's own vertex normals,
// normal maps, one-sided faces, alpha-masked cut-outs and emission textures, on small
// glTF files written here (geometry and PNGs embedded as base64 data URIs) and OBJ + MTL.
#include <gtest/gtest.h>

#include <png.h>

#include <cmath>
#include <cstring>
#include <span>

#include "../test_support.h"
#include "skylit/core/base64.h"
#include "skylit/io/scene/scene_loader.h"
#include "skylit/render/prepared_scene.h"
#include "skylit/spectrum/cie.h"
#include "skylit/spectrum/color_space.h"

namespace skylit {
namespace {

using testing::TempDir;

// A PNG of 8-bit RGBA texels, row by row from the top.
std::string png_rgba(int width, int height, const std::vector<uint8_t>& rgba) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(width);
  png.height = static_cast<png_uint_32>(height);
  png.format = PNG_FORMAT_RGBA;
  png_alloc_size_t size = 0;
  EXPECT_TRUE(png_image_write_to_memory(&png, nullptr, &size, 0, rgba.data(), 0, nullptr));
  std::string out(size, '\0');
  EXPECT_TRUE(png_image_write_to_memory(&png, out.data(), &size, 0, rgba.data(), 0, nullptr));
  out.resize(size);
  return out;
}

std::string data_uri(const std::string& mime, const std::string& bytes) {
  return "data:" + mime + ";base64," +
         base64_encode(std::span(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()));
}

// One glTF primitive of float positions, normals (optional) and texture coordinates
// (optional), with 16-bit indices, its material given as JSON and its images (PNG bytes)
// as textures 0, 1, ... in that order, all inside the .gltf.
struct GltfPrimitive {
  std::vector<float> positions, normals, uvs;
  std::vector<uint16_t> indices;
  std::string material = "{}";
  std::vector<std::string> images;

  std::string json() const {
    std::string bin, views, accessors, attributes;
    int index = 0;
    const auto add = [&](const void* data, size_t bytes, size_t count, const char* type, int component,
                         const char* attribute) {
      views += std::string(index ? ", " : "") + R"({"buffer": 0, "byteOffset": )" + std::to_string(bin.size()) +
               R"(, "byteLength": )" + std::to_string(bytes) + "}";
      accessors += std::string(index ? ", " : "") + R"({"bufferView": )" + std::to_string(index) +
                   R"(, "componentType": )" + std::to_string(component) + R"(, "count": )" + std::to_string(count) +
                   R"(, "type": ")" + type + "\"}";
      if (attribute != nullptr)
        attributes += std::string(attributes.empty() ? "" : ", ") + "\"" + attribute + "\": " + std::to_string(index);
      bin.append(static_cast<const char*>(data), bytes);
      while (bin.size() % 4 != 0) bin.push_back('\0');
      ++index;
    };
    add(positions.data(), positions.size() * 4, positions.size() / 3, "VEC3", 5126, "POSITION");
    if (!normals.empty()) add(normals.data(), normals.size() * 4, normals.size() / 3, "VEC3", 5126, "NORMAL");
    if (!uvs.empty()) add(uvs.data(), uvs.size() * 4, uvs.size() / 2, "VEC2", 5126, "TEXCOORD_0");
    const int indices_accessor = index;
    add(indices.data(), indices.size() * 2, indices.size(), "SCALAR", 5123, nullptr);
    std::string textures, image_list;
    for (size_t i = 0; i < images.size(); ++i) {
      textures += std::string(i ? ", " : "") + R"({"source": )" + std::to_string(i) + "}";
      image_list += std::string(i ? ", " : "") + R"({"uri": ")" + data_uri("image/png", images[i]) + "\"}";
    }
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {)" +
           attributes + R"(}, "indices": )" + std::to_string(indices_accessor) + R"(, "material": 0}]}],
      "materials": [)" +
           material + R"(], "textures": [)" + textures + R"(], "images": [)" + image_list + R"(],
      "buffers": [{"uri": ")" +
           data_uri("application/octet-stream", bin) + R"(", "byteLength": )" + std::to_string(bin.size()) + R"(}],
      "bufferViews": [)" +
           views + R"(], "accessors": [)" + accessors + "]}";
  }
};

// A 2 m square in the plane z = height (the file's z up), facing +z, with the image
// across it: u to +x, v down from the image's top row at +y.
GltfPrimitive square(float height) {
  GltfPrimitive p;
  p.positions = {-1, -1, height, 1, -1, height, 1, 1, height, -1, 1, height};
  p.uvs = {0, 1, 1, 1, 1, 0, 0, 0};
  p.indices = {0, 1, 2, 0, 2, 3};
  return p;
}

// A scene with the file as object "model" (more keys in `more`) and what `objects`
// adds, lit by a sun `sun`.
std::string scene_json(const std::string& file, const std::string& more = "", const std::string& objects = "",
                       const std::string& sun = R"("altitude_deg": 90, "azimuth_deg": 180)") {
  return R"({"camera": {"position": [0, 0, 10], "look_at": [0, 0.001, 0]}, "sun": {)" + sun + R"(},
    "materials": {"white": {"type": "diffuse", "reflectance": 0.8}},
    "objects": [{"type": "mesh", "name": "model", "file": ")" +
         file + R"(", "up_axis": "z", "material": "white")" + more + "}" + objects + R"(],
    "render": {"width": 64, "height": 48}})";
}

Scene load(const TempDir& dir, const std::string& gltf, const std::string& more = "", const std::string& objects = "",
           const std::string& sun = R"("altitude_deg": 90, "azimuth_deg": 180)") {
  dir.write("model.gltf", gltf);
  return load_scene(dir.write("scene.json", scene_json("model.gltf", more, objects, sun)));
}

// The scene's meshes in a ray tracer with their cut-outs, as PreparedScene puts them
// there, without the atmosphere's tables (which take most of a second to build).
struct Traced {
  std::vector<std::unique_ptr<SurfaceCutouts>> cutouts;
  RayTracer tracer;
  explicit Traced(const Scene& scene) {
    for (const SceneObject& object : scene.objects) {
      cutouts.push_back(surface_cutouts_for(object, scene.materials));
      tracer.add_mesh(object.mesh, cutouts.back().get());
    }
    tracer.commit();
  }
};

// An OBJ file `name`.obj with its library `name`.mtl holding `mtl`: a 2 m square at
// height `z` facing +z, textured across (OBJ's v runs up the image), in its material.
void write_obj_square(const TempDir& dir, const std::string& name, const std::string& mtl, const std::string& z) {
  dir.write(name + ".mtl", mtl);
  const std::string material = mtl.substr(7, mtl.find('\n') - 7);  // after "newmtl "
  dir.write(name + ".obj", "mtllib " + name + ".mtl\nv -1 -1 " + z + "\nv 1 -1 " + z + "\nv 1 1 " + z + "\nv -1 1 " +
                               z + "\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl " + material + "\nf 1/1 2/2 3/3 4/4\n");
}

// What a ray straight down onto (x, y) from 10 m up meets first: the object's index, or
// -1 for nothing.
int object_below(const Traced& traced, double x, double y) {
  const std::optional<Hit> hit = traced.tracer.intersect(Ray{{x, y, 10}, {0, 0, -1}});
  return hit ? static_cast<int>(hit->mesh_id) : -1;
}

// 2 × 2 texels, all white, with alpha 0 at the top left and bottom right (a checker).
std::string checker_mask() {
  return png_rgba(2, 2, {255, 255, 255, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0});
}

std::string masked_material(const std::string& mode, const std::string& more = "") {
  return R"({"name": "Leaves", "alphaMode": ")" + mode + R"(", )" + more +
         R"("pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0}})";
}

// The texel centres of the 2 × 2 image on the square: top left (-0.5, 0.5), ...
constexpr double kTexel = 0.5;

TEST(ModelShading, MaskedTexelsAreHolesForCameraRays) {
  TempDir dir;
  GltfPrimitive card = square(1);
  card.images = {checker_mask()};
  card.material = masked_material("MASK");
  const Scene scene = load(dir, card.json(), "", R"(, {"type": "plane", "material": "white", "size_m": 20})");
  const Traced prepared(scene);
  EXPECT_EQ(object_below(prepared, -kTexel, kTexel), 1);  // alpha 0: through to the ground
  EXPECT_EQ(object_below(prepared, kTexel, kTexel), 0);   // alpha 1: the card
  EXPECT_EQ(object_below(prepared, -kTexel, -kTexel), 0);
  EXPECT_EQ(object_below(prepared, kTexel, -kTexel), 1);
  // OPAQUE ignores alpha: the card everywhere.
  card.material = masked_material("OPAQUE");
  const Scene opaque = load(dir, card.json(), "", R"(, {"type": "plane", "material": "white", "size_m": 20})");
  const Traced prepared_opaque(opaque);
  EXPECT_EQ(object_below(prepared_opaque, -kTexel, kTexel), 0);
  EXPECT_EQ(object_below(prepared_opaque, kTexel, -kTexel), 0);
  // The cutoff compares factor × texel alpha: 0.6 × 1 passes 0.5 but not 0.7.
  card.material = R"({"alphaMode": "MASK", "alphaCutoff": 0.7, "pbrMetallicRoughness": {"baseColorFactor":
    [1, 1, 1, 0.6], "baseColorTexture": {"index": 0}}})";
  const Scene high_cutoff = load(dir, card.json());
  EXPECT_EQ(object_below(Traced(high_cutoff), kTexel, kTexel), -1);
  card.material = R"({"alphaMode": "MASK", "pbrMetallicRoughness": {"baseColorFactor":
    [1, 1, 1, 0.6], "baseColorTexture": {"index": 0}}})";
  const Scene default_cutoff = load(dir, card.json());
  EXPECT_EQ(object_below(Traced(default_cutoff), kTexel, kTexel), 0);
}

TEST(ModelShading, AMaskedCardCastsItsPatternAsShadow) {
  // The card 1 m above the ground, the sun 45° up in the south: each texel's shadow falls
  // 1 m north of it. From ground points there, the shadow ray meets the card where its
  // texel is opaque and passes where it is masked out, as the bands integrator asks.
  TempDir dir;
  GltfPrimitive card = square(1);
  card.images = {checker_mask()};
  card.material = masked_material("MASK");
  const Scene scene = load(dir, card.json(), "", R"(, {"type": "plane", "material": "white", "size_m": 20})",
                           R"("altitude_deg": 45, "azimuth_deg": 180)");
  const Traced prepared(scene);
  const Vec3 to_sun = direction_from_altitude_azimuth(scene.sun.altitude_deg, scene.sun.azimuth_deg);
  EXPECT_NEAR(to_sun.y, -std::sqrt(0.5), 1e-9);  // toward the south
  const auto shadowed = [&](double x, double y) {
    const Ray ray{offset_from_surface({x, y + 1, 0}, {0, 0, 1}), to_sun};
    return prepared.tracer.occluded(ray);
  };
  EXPECT_FALSE(shadowed(-kTexel, kTexel));
  EXPECT_TRUE(shadowed(kTexel, kTexel));
  EXPECT_TRUE(shadowed(-kTexel, -kTexel));
  EXPECT_FALSE(shadowed(kTexel, -kTexel));
}

TEST(ModelShading, BlendTurnsATranslucentFactorIntoGlassAndMasksTheTextureAtOneHalf) {
  TempDir dir;
  GltfPrimitive card = square(1);
  card.images = {checker_mask()};
  card.material = R"({"alphaMode": "BLEND", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 0.3],
    "baseColorTexture": {"index": 0}}})";
  const Scene scene = load(dir, card.json());
  ASSERT_TRUE(scene.objects[0].source.has_value());
  EXPECT_NE(scene.objects[0].source->materials.at(0).became.find("glass"), std::string::npos);
  const Traced prepared(scene);
  EXPECT_EQ(object_below(prepared, -kTexel, kTexel), -1);
  EXPECT_EQ(object_below(prepared, kTexel, kTexel), 0);
}

TEST(ModelShading, ObjMapDCutsHolesFromAGreyMask) {
  TempDir dir;
  // Black (0) at the top left texel: a hole; the rest white.
  dir.write("mask.png", png_rgba(2, 2, {0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255}));
  write_obj_square(dir, "card", "newmtl Leaves\nKd 0.3 0.6 0.2\nmap_d mask.png\n", "1");
  const Scene scene = load_scene(dir.write("scene.json", scene_json("card.obj")));
  const Traced prepared(scene);
  EXPECT_EQ(object_below(prepared, -kTexel, kTexel), -1);
  EXPECT_EQ(object_below(prepared, kTexel, kTexel), 0);
  EXPECT_EQ(object_below(prepared, -kTexel, -kTexel), 0);
  // Exporters write "d 0" (or illum 4) beside the mask: still cut-outs, not glass (an
  // outside trial's barn had turned to glass).
  write_obj_square(dir, "card", "newmtl Leaves\nKd 0.3 0.6 0.2\nd 0\nillum 4\nmap_d mask.png\n", "1");
  const Scene exported = load_scene(dir.write("exported.json", scene_json("card.obj")));
  EXPECT_EQ(exported.objects[0].source->materials.at(0).became.find("glass"), std::string::npos);
  const Traced cut(exported);
  EXPECT_EQ(object_below(cut, -kTexel, kTexel), -1);
  EXPECT_EQ(object_below(cut, kTexel, kTexel), 0);
}

TEST(ModelShading, ASingleSidedBackFaceIsInvisibleButCastsShadow) {
  TempDir dir;
  GltfPrimitive sheet = square(1);  // faces +z
  sheet.material = R"({"doubleSided": false})";
  const Scene scene = load(dir, sheet.json());
  const Traced prepared(scene);
  const Ray down{{0.2, 0.3, 10}, {0, 0, -1}}, up{{0.2, 0.3, -10}, {0, 0, 1}};
  EXPECT_TRUE(prepared.tracer.intersect(down).has_value());  // the front
  EXPECT_FALSE(prepared.tracer.intersect(up).has_value());   // the back: not seen
  EXPECT_TRUE(prepared.tracer.occluded(up));                 // but it still shades
  sheet.material = R"({"doubleSided": true})";
  const Scene two_sided = load(dir, sheet.json());
  const PreparedScene prepared_two(two_sided);
  const std::optional<Hit> hit = prepared_two.tracer().intersect(up);
  ASSERT_TRUE(hit.has_value());
  // Seen from below, the normal faces the viewer.
  EXPECT_NEAR(prepared_two.surface_point(up, *hit).normal.z, -1.0, 1e-9);
}

Vec3 unit(double x, double y, double z) { return normalize(Vec3{x, y, z}); }

TEST(ModelShading, FileNormalsInterpolateBarycentrically) {
  // One triangle in the file's x–z plane (glTF's y up, turned to skylit's z up as
  // (x, y, z) → (x, −z, y)), with a different normal at each corner.
  TempDir dir;
  GltfPrimitive tri;
  tri.positions = {0, 0, 0, 2, 0, 0, 0, 0, -2};  // skylit: (0,0,0), (2,0,0), (0,2,0)
  const Vec3 file_n[3] = {unit(0.2, 1, 0.1), unit(-0.3, 1, 0), unit(0, 1, 0.4)};
  for (const Vec3& n : file_n)
    for (double c : {n.x, n.y, n.z}) tri.normals.push_back(static_cast<float>(c));
  tri.indices = {0, 1, 2};
  dir.write("model.gltf", tri.json());
  const Scene scene =
      load_scene(dir.write("scene.json", R"({"camera": {"position": [0, 0, 10], "look_at": [0, 0.001, 0]},
    "sun": {"altitude_deg": 60, "azimuth_deg": 180}, "materials": {"white": {"type": "diffuse", "reflectance": 0.8}},
    "objects": [{"type": "mesh", "file": "model.gltf", "material": "white"}], "render": {"width": 8, "height": 8}})"));
  const PreparedScene prepared(scene);
  const Ray ray{{0.5, 0.7, 10}, {0, 0, -1}};
  const std::optional<Hit> hit = prepared.tracer().intersect(ray);
  ASSERT_TRUE(hit.has_value());
  // The corners in skylit's frame, and the point's barycentrics b1 = x / 2, b2 = y / 2.
  const double b1 = 0.25, b2 = 0.35, b0 = 1 - b1 - b2;
  Vec3 expected{0, 0, 0};
  const double b[3] = {b0, b1, b2};
  for (int i = 0; i < 3; ++i) expected += b[i] * Vec3{file_n[i].x, -file_n[i].z, file_n[i].y};
  expected = normalize(expected);
  const Vec3 n = prepared.surface_point(ray, *hit).normal;
  // Normals are stored in float: 1e-6.
  EXPECT_NEAR(n.x, expected.x, 1e-6);
  EXPECT_NEAR(n.y, expected.y, 1e-6);
  EXPECT_NEAR(n.z, expected.z, 1e-6);
}

TEST(ModelShading, ObjVertexNormalsAndTheirDegenerateCasesAndTheCreaseOption) {
  TempDir dir;
  // Corner normals: one tilted, one zero, one NaN: the last two become the flat +z.
  dir.write("tri.obj",
            "v 0 0 0\nv 2 0 0\nv 0 2 0\nvn 0.6 0 0.8\nvn 0 0 0\nvn nan 0 1\n"
            "f 1//1 2//2 3//3\n");
  const Scene scene = load_scene(dir.write("scene.json", scene_json("tri.obj")));
  ASSERT_EQ(scene.objects[0].corner_normals.size(), 1u);
  const PreparedScene prepared(scene);
  const Ray ray{{0.5, 0.7, 10}, {0, 0, -1}};
  const std::optional<Hit> hit = prepared.tracer().intersect(ray);
  ASSERT_TRUE(hit.has_value());
  const double b0 = 1 - 0.25 - 0.35;
  const Vec3 expected = normalize(b0 * Vec3{0.6, 0, 0.8} + (1 - b0) * Vec3{0, 0, 1});
  const Vec3 n = prepared.surface_point(ray, *hit).normal;
  EXPECT_NEAR(n.x, expected.x, 1e-6);
  EXPECT_NEAR(n.z, expected.z, 1e-6);
  // Normals on the far side of the winding are turned over, not shaded as a back.
  dir.write("flipped.obj", "v 0 0 0\nv 2 0 0\nv 0 2 0\nvn -0.6 0 -0.8\nf 1//1 2//1 3//1\n");
  const Scene flipped = load_scene(dir.write("flipped.json", scene_json("flipped.obj")));
  EXPECT_NEAR(flipped.objects[0].corner_normals[0][0][2], 0.8f, 1e-6);
  // "normals": "crease" ignores them: one flat triangle needs no normals.
  const Scene crease = load_scene(dir.write("crease.json", scene_json("tri.obj", R"(, "normals": "crease")")));
  EXPECT_TRUE(crease.objects[0].corner_normals.empty());
}

// The tangent-space normal an 8-bit texel (r, g, b) encodes, scaled as glTF says.
Vec3 decoded(int r, int g, int b, double scale) {
  return normalize(Vec3{scale * (2 * r / 255.0 - 1), scale * (2 * g / 255.0 - 1), 2 * b / 255.0 - 1});
}

TEST(ModelShading, ANormalMappedPlaneShadesLikeThePlaneTiltedAsTheMapSays) {
  // A flat square whose normal map leans every normal toward +x (the texture's right,
  // along u), and a square actually turned about y by the angle the texel encodes.
  // Lambert's cosine toward the sun must agree within 0.5 %; the normal itself, within
  // the float storage (1e-5). An sRGB-decoded map would tilt 14° the other way.
  const int r = 171, g = 128, b = 239;  // 21.3° toward +x
  TempDir dir;
  GltfPrimitive flat = square(0);
  flat.images = {png_rgba(1, 1, {r, g, b, 255})};
  flat.material = R"({"normalTexture": {"index": 0, "scale": 1}})";
  const Scene mapped = load(dir, flat.json(), "", "", R"("altitude_deg": 50, "azimuth_deg": 250)");
  const PreparedScene prepared(mapped);
  const Ray ray{{0.1, 0.2, 10}, {0, 0, -1}};
  const Vec3 n = prepared.surface_point(ray, *prepared.tracer().intersect(ray)).normal;
  const Vec3 expected = decoded(r, g, b, 1);
  EXPECT_NEAR(n.x, expected.x, 1e-5);
  EXPECT_NEAR(n.y, expected.y, 1e-5);
  EXPECT_NEAR(n.z, expected.z, 1e-5);

  const double tilt_deg = std::atan2(expected.x, expected.z) * 180 / M_PI;
  GltfPrimitive plain = square(0);
  const Scene tilted =
      load(dir, plain.json(), R"(, "transform": {"rotate_deg": [0, )" + std::to_string(tilt_deg) + R"(, 0]})", "",
           R"("altitude_deg": 50, "azimuth_deg": 250)");
  const PreparedScene prepared_tilted(tilted);
  const Vec3 n_tilted = prepared_tilted.surface_point(ray, *prepared_tilted.tracer().intersect(ray)).normal;
  const double cos_mapped = dot(n, prepared.to_sun()), cos_tilted = dot(n_tilted, prepared.to_sun());
  EXPECT_NEAR(cos_mapped, cos_tilted, 0.005 * cos_tilted);

  // The scale multiplies x and y; toward the image's top (green above 128) is +y.
  flat.images = {png_rgba(1, 1, {128, 200, 230, 255})};
  flat.material = R"({"normalTexture": {"index": 0, "scale": 0.5}})";
  const Scene scaled = load(dir, flat.json());
  const PreparedScene prepared_scaled(scaled);
  const Vec3 s = prepared_scaled.surface_point(ray, *prepared_scaled.tracer().intersect(ray)).normal;
  const Vec3 s_expected = decoded(128, 200, 230, 0.5);
  EXPECT_NEAR(s.y, s_expected.y, 1e-5);
  EXPECT_GT(s.y, 0.1);
}

TEST(ModelShading, ObjNormTakesTheSameFrameAsGltf) {
  // OBJ's v runs up the image; read with the same convention, the map tilts the same way.
  TempDir dir;
  dir.write("n.png", png_rgba(1, 1, {128, 200, 230, 255}));
  write_obj_square(dir, "q", "newmtl Bumpy\nKd 0.5 0.5 0.5\nnorm n.png\n", "0");
  const Scene scene = load_scene(dir.write("scene.json", scene_json("q.obj")));
  const PreparedScene prepared(scene);
  const Ray ray{{0.1, 0.2, 10}, {0, 0, -1}};
  const Vec3 n = prepared.surface_point(ray, *prepared.tracer().intersect(ray)).normal;
  const Vec3 expected = decoded(128, 200, 230, 1);
  EXPECT_NEAR(n.y, expected.y, 1e-5);
  EXPECT_NEAR(n.z, expected.z, 1e-5);
}

TEST(ModelShading, AMappedNormalIsNeverTurnedAwayFromTheViewer) {
  // A map leaning 80° toward +x, scaled 10 times, seen from far off to −x at 20° above
  // the plane: taken as it is, the viewer would be below the normal's horizon.
  TempDir dir;
  GltfPrimitive flat = square(0);
  flat.images = {png_rgba(1, 1, {255, 128, 150, 255})};
  flat.material = R"({"normalTexture": {"index": 0, "scale": 10}})";
  const Scene scene = load(dir, flat.json());
  const PreparedScene prepared(scene);
  const Vec3 to_viewer = unit(-std::cos(20 * M_PI / 180), 0, std::sin(20 * M_PI / 180));
  const Ray ray{Vec3{0.1, 0.2, 0} + 10.0 * to_viewer, -to_viewer};
  const SurfacePoint p = prepared.surface_point(ray, *prepared.tracer().intersect(ray));
  EXPECT_TRUE(std::isfinite(p.normal.x) && std::isfinite(p.normal.y) && std::isfinite(p.normal.z));
  EXPECT_NEAR(length(p.normal), 1.0, 1e-9);
  // Bent just far enough: seen at a grazing cosine of about 0.01, so still leaning
  // toward +x nearly as far as a visible normal can (sin 20° = 0.342).
  EXPECT_GT(dot(p.normal, to_viewer), 0.0);
  EXPECT_LT(dot(p.normal, to_viewer), 0.05);
  EXPECT_GT(p.normal.z, 0.0);
  EXPECT_GT(p.normal.x, 0.3);
}

TEST(ModelShading, EmissiveTexelsGiveTheirLuminanceTimesTheFactor) {
  // emissiveFactor × strength × the texel decoded from sRGB, cd/m² per linear channel.
  TempDir dir;
  GltfPrimitive sign = square(0);
  sign.images = {png_rgba(2, 2, {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 128, 128, 128, 255})};
  sign.material = R"({"emissiveFactor": [1, 1, 1], "emissiveTexture": {"index": 0},
    "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 100}}})";
  const Scene scene = load(dir, sign.json());
  const PreparedScene prepared(scene);
  const Ray ray{{kTexel, -kTexel, 10}, {0, 0, -1}};  // bottom right: sRGB grey 128
  const SurfacePoint p = prepared.surface_point(ray, *prepared.tracer().intersect(ray));
  ASSERT_TRUE(p.emissive);
  const double grey = 100 * srgb_decode(128 / 255.0);  // 21.6 cd/m²
  for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(p.emission_cd_m2[i], grey, 1e-4 * grey);
  EXPECT_NEAR(luminance(emitted_radiance(p.emission_cd_m2)), grey, 1e-3 * grey);
  const Ray red{{-kTexel, kTexel, 10}, {0, 0, -1}};
  const SurfacePoint q = prepared.surface_point(red, *prepared.tracer().intersect(red));
  EXPECT_NEAR(q.emission_cd_m2[0], 100, 1e-3);
  EXPECT_NEAR(q.emission_cd_m2[1], 0, 1e-6);
}

TEST(ModelShading, ObjMapKeTexelsTimesKe) {
  TempDir dir;
  dir.write("e.png", png_rgba(2, 2, {255, 255, 255, 255, 0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255}));
  write_obj_square(dir, "q", "newmtl Screen\nKd 0 0 0\nKe 300 300 300\nmap_Ke e.png\n", "0");
  const Scene scene = load_scene(dir.write("scene.json", scene_json("q.obj")));
  const PreparedScene prepared(scene);
  const Ray lit{{-kTexel, kTexel, 10}, {0, 0, -1}}, dark{{kTexel, -kTexel, 10}, {0, 0, -1}};
  EXPECT_NEAR(prepared.surface_point(lit, *prepared.tracer().intersect(lit)).emission_cd_m2[1], 300, 1e-3);
  EXPECT_FALSE(prepared.surface_point(dark, *prepared.tracer().intersect(dark)).emissive);
}

}  // namespace
}  // namespace skylit
