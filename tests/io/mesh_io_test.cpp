// Mesh files: OBJ polygons and negative indices, glTF with embedded buffers, node
// transforms and the y-up → z-up turn, GLB, and user errors that name the file.
#include "skylit/io/model/mesh_io.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

#include "skylit/core/error.h"
#include "skylit/spectrum/rgb_to_spectrum.h"

namespace skylit {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test, removed afterwards.
class MeshIo : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("skylit_mesh_io_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& bytes) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }

  // Expects load_mesh_file to throw InputError whose message names the file.
  void expect_input_error(const fs::path& p, const std::string& also = "") {
    try {
      load_mesh_file(p, UpAxis::y);
      ADD_FAILURE() << "no InputError for " << p;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(also), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "message must be one line";
    }
  }

  fs::path dir_;
};

// Little-endian bytes of floats and integers, as glTF buffers hold them.
template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

std::string base64(const std::string& in) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    const uint32_t n = (uint8_t(in[i]) << 16) | (uint8_t(in[i + 1]) << 8) | uint8_t(in[i + 2]);
    for (int s : {18, 12, 6, 0}) out += table[(n >> s) & 63];
  }
  if (i + 1 == in.size()) {
    const uint32_t n = uint8_t(in[i]) << 16;
    out += table[(n >> 18) & 63], out += table[(n >> 12) & 63], out += "==";
  } else if (i + 2 == in.size()) {
    const uint32_t n = (uint8_t(in[i]) << 16) | (uint8_t(in[i + 1]) << 8);
    out += table[(n >> 18) & 63], out += table[(n >> 12) & 63], out += table[(n >> 6) & 63], out += '=';
  }
  return out;
}

// One triangle (0,0,0), (1,0,0), (0,1,0) as float32, then uint16 indices 0 1 2
// padded to 4 bytes: 36 + 8 = 44 bytes.
std::string triangle_buffer(float first_x = 0.0f) {
  std::string b;
  for (float f : {first_x, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) put(b, f);
  for (uint16_t i : {0, 1, 2, 0}) put(b, i);
  return b;
}

// glTF JSON around the triangle buffer; `nodes` and `scenes` are spliced in.
std::string triangle_gltf(const std::string& buffer_json, const std::string& nodes,
                          const std::string& extra_primitive = "", size_t position_count = 3) {
  return R"({"asset": {"version": "2.0"},
  "buffers": [)" +
         buffer_json + R"(],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
         std::to_string(position_count) + R"(, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1})" +
         extra_primitive + R"(]}],
  )" + nodes +
         "}";
}

std::string embedded(const std::string& bytes) {
  return R"({"byteLength": )" + std::to_string(bytes.size()) + R"(, "uri": "data:application/octet-stream;base64,)" +
         base64(bytes) + R"("})";
}

const std::string kTranslatedNode =
    R"("nodes": [{"mesh": 0, "translation": [10, 20, 30]}], "scenes": [{"nodes": [0]}], "scene": 0)";

TEST_F(MeshIo, ObjQuadsAndNegativeIndicesLoad) {
  // A unit quad (relative indices) and a triangle (absolute), plus things to ignore.
  const fs::path p = write("quad.obj",
                           "# test\nmtllib missing.mtl\no thing\n"
                           "v 0 0 0\nv 2 0 0\nv 2 3 0\nv 0 3 0.5\nvn 0 0 1\nvt 0 0\n"
                           "usemtl nothing\nf -4 -3 -2 -1\n"
                           "v 0 0 7\nf 1/1 2/1/1 5//1\nl 1 2\n");
  const TriangleMesh z = load_mesh_file(p, UpAxis::z);
  ASSERT_EQ(z.triangles.size(), 3u);
  ASSERT_EQ(z.vertices.size(), 5u);
  EXPECT_EQ(z.vertices[3], Vec3(0, 3, 0.5));
  EXPECT_EQ(z.vertices[4], Vec3(0, 0, 7));
  // The quad's two triangles cover exactly its four corners, and keep its winding (+z).
  std::vector<int> used(5, 0);
  for (int t = 0; t < 2; ++t) {
    for (uint32_t i : z.triangles[t]) ++used[i];
    const auto& tri = z.triangles[t];
    const Vec3 n = cross(z.vertices[tri[1]] - z.vertices[tri[0]], z.vertices[tri[2]] - z.vertices[tri[0]]);
    EXPECT_GT(n.z, 0.0);
  }
  EXPECT_EQ(used[4], 0);
  EXPECT_EQ(used[0] + used[1] + used[2] + used[3], 6);
  EXPECT_EQ(z.triangles[2], (std::array<uint32_t, 3>{0, 1, 4}));

  // The same file read as y-up: (x, y, z) → (x, -z, y).
  const TriangleMesh y = load_mesh_file(p, UpAxis::y);
  EXPECT_EQ(y.vertices[3], Vec3(0, -0.5, 3));
  EXPECT_EQ(y.vertices[4], Vec3(0, -7, 0));
}

// An L-shaped face listed from its reflex corner: a fan from that corner (what a
// naive split does) would cover the notch and count 4 m² too many. The triangles
// must add up to the L's 3 m² (exact in binary, so 1e-12) and face +z like the face.
TEST_F(MeshIo, ObjConcaveFaceIsSplitInsideItsOutline) {
  const fs::path p = write("l.obj", "v 1 1 0\nv 1 2 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nv 2 1 0\nf 1 2 3 4 5 6\n");
  const TriangleMesh mesh = load_mesh_file(p, UpAxis::z);
  ASSERT_EQ(mesh.triangles.size(), 4u);
  double area = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3 n = cross(mesh.vertices[t[1]] - mesh.vertices[t[0]], mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    EXPECT_GT(n.z, 0.0);
    area += 0.5 * length(n);
    const Vec3 c = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
    EXPECT_FALSE(c.x > 1 && c.y > 1) << "a triangle lies in the notch";
  }
  EXPECT_NEAR(area, 3.0, 1e-12);
}

TEST_F(MeshIo, ObjBadIndexOrHugeCoordinateIsInputError) {
  expect_input_error(write("bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"), "vertex");
  expect_input_error(write("bad_quad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 -9\n"), "vertex");
  // Beyond single precision: would be infinity in the ray tracer.
  expect_input_error(write("huge.obj", "v 1e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "finite");
  // tinyobjloader alone would read these as 0; the line number is reported.
  expect_input_error(write("nan.obj", "v 0 0 0\nv 1 0 0\n\nv nan 1 0\nf 1 2 3\n"), ":4:");
  expect_input_error(write("word.obj", "v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n"), ":2:");
  expect_input_error(write("short.obj", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n"), ":2:");
}

TEST_F(MeshIo, ObjKeepsDoublePrecisionSiteCoordinates) {
  // Survey coordinates far from the origin, to be moved back by the scene's
  // transform: float would round 4200000.125 to 4200000.0.
  const fs::path p = write("site.obj",
                           "v 500123.25 4200000.125 12.5\r\nv +500124.25 4200000.125 12.5 1.0\r\n"
                           "v 500123.25 4200001.125 1.25e1\r\nf 1 2 3\r\n");
  const TriangleMesh m = load_mesh_file(p, UpAxis::z);
  ASSERT_EQ(m.vertices.size(), 3u);
  EXPECT_EQ(m.vertices[0], Vec3(500123.25, 4200000.125, 12.5));
  EXPECT_EQ(m.vertices[1], Vec3(500124.25, 4200000.125, 12.5));
  EXPECT_EQ(m.vertices[2], Vec3(500123.25, 4200001.125, 12.5));
}

TEST_F(MeshIo, GltfEmbeddedBufferNodeTranslationAndYUp) {
  const fs::path p = write("tri.gltf", triangle_gltf(embedded(triangle_buffer()), kTranslatedNode));
  // File frame: the triangle moved by the node's translation.
  const TriangleMesh raw = load_mesh_file(p, UpAxis::z);
  ASSERT_EQ(raw.triangles.size(), 1u);
  ASSERT_EQ(raw.vertices.size(), 3u);
  EXPECT_EQ(raw.vertices[0], Vec3(10, 20, 30));
  EXPECT_EQ(raw.vertices[1], Vec3(11, 20, 30));
  EXPECT_EQ(raw.vertices[2], Vec3(10, 21, 30));
  // glTF's +Y up becomes +z; its +Z becomes -y (south).
  const TriangleMesh m = load_mesh_file(p, UpAxis::y);
  EXPECT_EQ(m.vertices[0], Vec3(10, -30, 20));
  EXPECT_EQ(m.vertices[1], Vec3(11, -30, 20));
  EXPECT_EQ(m.vertices[2], Vec3(10, -30, 21));
  EXPECT_EQ(m.triangles[0], (std::array<uint32_t, 3>{0, 1, 2}));
}

TEST_F(MeshIo, GltfExternalBufferAndDefaultScene) {
  write("tri.bin", triangle_buffer());
  // Scene 1 is the default; scene 0 (which would move the triangle) must be ignored.
  // Images, embedded or missing, are never read.
  const std::string nodes =
      R"("nodes": [{"mesh": 0, "translation": [5, 0, 0]}, {"mesh": 0}], "scenes": [{"nodes": [0]}, {"nodes": [1]}],
      "scene": 1, "images": [{"uri": "missing.png"}, {"uri": "data:image/png;base64,iVBORw0KGgo="}])";
  const fs::path p = write("ext.gltf", triangle_gltf(R"({"byteLength": 44, "uri": "tri.bin"})", nodes));
  const TriangleMesh m = load_mesh_file(p, UpAxis::z);
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.vertices[1], Vec3(1, 0, 0));
}

TEST_F(MeshIo, GltfHierarchyComposesParentThenChild) {
  // Parent scales by 2 and turns 90° about +Y (quaternion); child has a matrix
  // translating by +1 in x. Vertex (0,0,0) → child (1,0,0) → parent: scale (2,0,0),
  // then rotate about Y by 90°: x → -z, so (0,0,-2). The other order would give
  // (1,0,0).
  const double s = std::sqrt(0.5);
  const std::string nodes = R"("nodes": [{"children": [1], "scale": [2, 2, 2], "rotation": [0, )" + std::to_string(s) +
                            ", 0, " + std::to_string(s) + R"(]},
    {"mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 1,0,0,1]}], "scenes": [{"nodes": [0]}])";
  const fs::path p = write("tree.gltf", triangle_gltf(embedded(triangle_buffer()), nodes));
  const TriangleMesh m = load_mesh_file(p, UpAxis::z);
  ASSERT_EQ(m.vertices.size(), 3u);
  EXPECT_NEAR(m.vertices[0].x, 0, 1e-6);
  EXPECT_NEAR(m.vertices[0].y, 0, 1e-6);
  EXPECT_NEAR(m.vertices[0].z, -2, 1e-6);
  // (1,0,0) → (2,0,0) → scaled (4,0,0) → rotated (0,0,-4).
  EXPECT_NEAR(m.vertices[1].z, -4, 1e-6);
  // (0,1,0) → (1,1,0) → (2,2,0) → (0,2,-2).
  EXPECT_NEAR(m.vertices[2].y, 2, 1e-6);
  EXPECT_NEAR(m.vertices[2].z, -2, 1e-6);
}

TEST_F(MeshIo, GltfSkipsNonTrianglePrimitives) {
  // A second primitive drawing the same data as lines (mode 1) adds nothing.
  const std::string lines = R"(, {"attributes": {"POSITION": 0}, "mode": 1})";
  const fs::path p = write("lines.gltf", triangle_gltf(embedded(triangle_buffer()), kTranslatedNode, lines));
  EXPECT_EQ(load_mesh_file(p, UpAxis::y).triangles.size(), 1u);

  const std::string only_lines = R"({"asset": {"version": "2.0"},
    "buffers": [)" + embedded(triangle_buffer()) +
                                 R"(],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "mode": 0}]}],
    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})";
  expect_input_error(write("points.gltf", only_lines), "no triangles");
}

// Triangle strips and fans (glTF 2.0 §3.7.2.1): four vertices of the unit square in the
// file's x-y plane drawn as a strip (0 1 2 3) and as a fan (0 1 2 3 around 0) give two
// triangles each, facing +z (the strip's second one turned as the spec says), covering
// the square; points and lines are counted, not drawn.
TEST_F(MeshIo, GltfStripsAndFansByTheSpecificationAndLinesCounted) {
  std::string square;
  for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 1.f, 1.f, 0.f}) put(square, f);  // strip order
  for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 0.f, 0.f, 1.f, 0.f}) put(square, f);  // fan order
  const std::string gltf = R"({"asset": {"version": "2.0"}, "buffers": [)" + embedded(square) + R"(],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 48}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                  {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "mode": 5}, {"attributes": {"POSITION": 1}, "mode": 6},
                               {"attributes": {"POSITION": 0}, "mode": 1}, {"attributes": {"POSITION": 1}, "mode": 0}]}],
    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})";
  const LoadedModel model = load_model_file(write("modes.gltf", gltf), UpAxis::z);
  ASSERT_EQ(model.mesh.triangles.size(), 4u);
  EXPECT_EQ(model.skipped_primitives, 2);
  double area = 0;
  for (const auto& t : model.mesh.triangles) {
    const Vec3 n = cross(model.mesh.vertices[t[1]] - model.mesh.vertices[t[0]],
                         model.mesh.vertices[t[2]] - model.mesh.vertices[t[0]]);
    EXPECT_GT(n.z, 0) << "every triangle faces +z";
    area += 0.5 * length(n);
  }
  EXPECT_NEAR(area, 2.0, 1e-12);  // the square twice
}

// A file that requires Draco compression is refused by name, though tinygltf stops
// earlier at the buffer views Draco leaves out.
TEST_F(MeshIo, GltfRequiringDracoIsRefusedByName) {
  const std::string draco = R"({"asset": {"version": "2.0"},
    "extensionsUsed": ["KHR_draco_mesh_compression"], "extensionsRequired": ["KHR_draco_mesh_compression"],
    "buffers": [{"byteLength": 8, "uri": "missing.bin"}],
    "accessors": [{"componentType": 5126, "count": 3, "type": "VEC3"}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0},
      "extensions": {"KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": 0}}}}]}],
    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})";
  expect_input_error(write("draco.gltf", draco), "requires glTF extension KHR_draco_mesh_compression");
}

// A default scene the file does not hold, and a glTF 1.0 file (another format, which
// tinygltf half reads), are refused by name; they had fallen back to scene 0 and loaded.
TEST_F(MeshIo, GltfMissingDefaultSceneAndVersionOneAreRefused) {
  std::string no_scene = triangle_gltf(embedded(triangle_buffer()), kTranslatedNode);
  no_scene.replace(no_scene.find(R"("scene": 0)"), 10, R"("scene": 5)");
  expect_input_error(write("scene5.gltf", no_scene), "the default scene is scene 5, but the file has 1");
  std::string old = triangle_gltf(embedded(triangle_buffer()), kTranslatedNode);
  old.replace(old.find(R"("version": "2.0")"), 16, R"("version": "1.0")");
  expect_input_error(write("old.gltf", old), "glTF version '1.0'; skylit reads glTF 2.0");
}

TEST_F(MeshIo, GlbLoads) {
  const std::string bin = triangle_buffer();
  std::string json = triangle_gltf(R"({"byteLength": 44})", kTranslatedNode);
  while (json.size() % 4) json += ' ';
  std::string glb = "glTF";
  put<uint32_t>(glb, 2);
  put<uint32_t>(glb, static_cast<uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  put<uint32_t>(glb, static_cast<uint32_t>(json.size()));
  glb += "JSON" + json;
  put<uint32_t>(glb, static_cast<uint32_t>(bin.size()));
  glb += std::string("BIN\0", 4) + bin;
  const TriangleMesh m = load_mesh_file(write("tri.glb", glb), UpAxis::y);
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.vertices[1], Vec3(11, -30, 20));
}

TEST_F(MeshIo, GltfQuantizedPositionsAreScaledByTheNode) {
  // KHR_mesh_quantization: uint16 positions (stride 8), not indexed; the node's
  // scale brings them to metres.
  std::string b;
  for (uint16_t v : {0, 0, 0, 0, 4, 0, 0, 0, 0, 4, 0, 0}) put(b, v);
  const std::string json = R"({"asset": {"version": "2.0"},
    "extensionsUsed": ["KHR_mesh_quantization"], "extensionsRequired": ["KHR_mesh_quantization"],
    "buffers": [)" + embedded(b) +
                           R"(],
    "bufferViews": [{"buffer": 0, "byteLength": 24, "byteStride": 8}],
    "accessors": [{"bufferView": 0, "componentType": 5123, "count": 3, "type": "VEC3"}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "nodes": [{"mesh": 0, "scale": [0.25, 0.25, 0.25]}], "scenes": [{"nodes": [0]}]})";
  const TriangleMesh m = load_mesh_file(write("quantized.gltf", json), UpAxis::z);
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.vertices[1], Vec3(1, 0, 0));
  EXPECT_EQ(m.vertices[2], Vec3(0, 1, 0));
}

// The triangle with normals (0, 0, 1) and one morph target that moves vertex 1 by
// (0.4, 0.6, 0.8) and turns vertex 2's normal by (0, 2, 0); the mesh's default weight
// 0.5. Node 0 takes it, node 1 (10 m along x) gives its own weight 1.
std::string morphed_gltf() {
  std::string b = triangle_buffer();
  for (int i = 0; i < 3; ++i)
    for (float f : {0.f, 0.f, 1.f}) put(b, f);
  for (float f : {0.f, 0.f, 0.f, 0.4f, 0.6f, 0.8f, 0.f, 0.f, 0.f}) put(b, f);
  for (float f : {0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 2.f, 0.f}) put(b, f);
  return R"({"asset": {"version": "2.0"}, "buffers": [)" + embedded(b) + R"(],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6},
                  {"buffer": 0, "byteOffset": 44, "byteLength": 36}, {"buffer": 0, "byteOffset": 80, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 116, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
                {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 3, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 4, "componentType": 5126, "count": 3, "type": "VEC3"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 2}, "indices": 1,
                              "targets": [{"POSITION": 3, "NORMAL": 4}]}], "weights": [0.5]}],
  "nodes": [{"mesh": 0}, {"mesh": 0, "weights": [1], "translation": [10, 0, 0]}],
  "scenes": [{"nodes": [0, 1]}], "scene": 0})";
}

// glTF 2.0 §3.7.2.2: positions and normals are base + Σ wᵢ targetᵢ, the weights the
// node's, else the mesh's defaults.
TEST_F(MeshIo, GltfMorphTargetsTakeTheirDefaultWeights) {
  const LoadedModel model = load_model_file(write("morph.gltf", morphed_gltf()), UpAxis::z);
  ASSERT_EQ(model.mesh.vertices.size(), 6u);
  const auto expect_near = [](const Vec3& a, const Vec3& b) {
    EXPECT_NEAR(length(a - b), 0, 1e-6) << a.x << " " << a.y << " " << a.z;
  };
  expect_near(model.mesh.vertices[1], {1.2, 0.3, 0.4});   // the mesh's weight 0.5
  expect_near(model.mesh.vertices[4], {11.4, 0.6, 0.8});  // node 1's weight 1
  expect_near(model.mesh.vertices[3], {10, 0, 0});        // vertex 0 does not move
  ASSERT_EQ(model.corner_normals.size(), 2u);
  const auto normal = [&](size_t triangle, size_t corner) {
    const auto& n = model.corner_normals[triangle][corner];
    return Vec3{n[0], n[1], n[2]};
  };
  expect_near(normal(0, 2), normalize(Vec3{0, 1, 1}));  // (0, 0, 1) + 0.5 (0, 2, 0)
  expect_near(normal(1, 2), normalize(Vec3{0, 2, 1}));
  expect_near(normal(0, 0), {0, 0, 1});
}

// A unit quad (0,0,0), (1,0,0), (1,1,0), (0,1,0) of two triangles with one morph target
// of weight 0.5 as Blender writes a shape key: a sparse accessor without a buffer view,
// all zeros but at the vertices `moved` (uint16 indices), the k-th moved by (0, 0, 2k + 2).
// `values_length`, if given, is the byteLength of the values' buffer view.
std::string sparse_morph_gltf(const std::vector<uint16_t>& moved, size_t values_length = 0) {
  std::string b;
  for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 0.f, 0.f, 1.f, 0.f}) put(b, f);
  for (uint16_t i : {0, 1, 2, 0, 2, 3}) put(b, i);
  for (uint16_t i : moved) put(b, i);
  if (b.size() % 4 != 0) put(b, uint16_t{0});
  const size_t values_offset = b.size();
  for (size_t k = 0; k < moved.size(); ++k)
    for (float f : {0.f, 0.f, static_cast<float>(2 * k + 2)}) put(b, f);
  return R"({"asset": {"version": "2.0"}, "buffers": [)" + embedded(b) + R"(],
  "bufferViews": [{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12},
                  {"buffer": 0, "byteOffset": 60, "byteLength": )" +
         std::to_string(2 * moved.size()) + R"(},
                  {"buffer": 0, "byteOffset": )" +
         std::to_string(values_offset) + R"(, "byteLength": )" +
         std::to_string(values_length != 0 ? values_length : 12 * moved.size()) + R"(}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
                {"componentType": 5126, "count": 4, "type": "VEC3", "sparse": {"count": )" +
         std::to_string(moved.size()) + R"(,
                 "indices": {"bufferView": 2, "componentType": 5123}, "values": {"bufferView": 3}}}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "targets": [{"POSITION": 2}]}],
              "weights": [0.5]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})";
}

// glTF 2.0 §3.6.2.3: a sparse accessor without a buffer view is zeros but at its
// indices, so the target moves those vertices and no others.
TEST_F(MeshIo, GltfSparseMorphTargetMovesOnlyItsVertices) {
  const LoadedModel model = load_model_file(write("shape_key.gltf", sparse_morph_gltf({1, 3})), UpAxis::z);
  ASSERT_EQ(model.mesh.vertices.size(), 4u);
  EXPECT_EQ(model.mesh.vertices[0], Vec3(0, 0, 0));
  EXPECT_EQ(model.mesh.vertices[1], Vec3(1, 0, 1));  // + 0.5 (0, 0, 2)
  EXPECT_EQ(model.mesh.vertices[2], Vec3(1, 1, 0));
  EXPECT_EQ(model.mesh.vertices[3], Vec3(0, 1, 2));  // + 0.5 (0, 0, 4)
}

// A sparse accessor with a buffer view: its base, with the elements at its indices
// (here uint8) replaced.
TEST_F(MeshIo, GltfSparsePositionsReplaceTheirBase) {
  std::string b = triangle_buffer();
  for (uint8_t i : {0, 2, 0, 0}) put(b, i);
  for (float f : {-1.f, -2.f, -3.f, 4.f, 5.f, 6.f}) put(b, f);
  const std::string json = R"({"asset": {"version": "2.0"}, "buffers": [)" + embedded(b) + R"(],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6},
                  {"buffer": 0, "byteOffset": 44, "byteLength": 2}, {"buffer": 0, "byteOffset": 48, "byteLength": 24}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "sparse": {"count": 2,
                 "indices": {"bufferView": 2, "componentType": 5121}, "values": {"bufferView": 3}}},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})";
  const TriangleMesh m = load_mesh_file(write("sparse_positions.gltf", json), UpAxis::z);
  ASSERT_EQ(m.vertices.size(), 3u);
  EXPECT_EQ(m.vertices[0], Vec3(-1, -2, -3));
  EXPECT_EQ(m.vertices[1], Vec3(1, 0, 0));
  EXPECT_EQ(m.vertices[2], Vec3(4, 5, 6));
}

// Bad sparse data is refused in one line naming the file and the accessor; a target of
// weight 0 is not read, so its bad data does not count.
TEST_F(MeshIo, GltfBadSparseAccessorIsInputError) {
  expect_input_error(write("beyond.gltf", sparse_morph_gltf({1, 4})),
                     "POSITION morph target accessor 2: its sparse index 4 is beyond its 4 elements");
  expect_input_error(write("unordered.gltf", sparse_morph_gltf({3, 1})),
                     "POSITION morph target accessor 2: its sparse indices are not strictly increasing (3 then 1)");
  expect_input_error(write("repeated.gltf", sparse_morph_gltf({1, 1})), "not strictly increasing (1 then 1)");
  expect_input_error(write("short.gltf", sparse_morph_gltf({1, 3}, 12)),
                     "POSITION morph target accessor 2 (sparse values) runs past the end of its buffer view");
  // Zeros take no room in the file, so their number is bounded by the file's bytes.
  std::string zeros = sparse_morph_gltf({1, 3});
  zeros.replace(zeros.find(R"("count": 4, "type": "VEC3", "sparse")"), 10, R"("count": 1000000000)");
  expect_input_error(write("zeros.gltf", zeros), "has no buffer view and 1000000000 elements");
  std::string unweighted = sparse_morph_gltf({1, 4});
  unweighted.replace(unweighted.find(R"("weights": [0.5])"), 16, R"("weights": [0])");
  EXPECT_EQ(load_model_file(write("unweighted.gltf", unweighted), UpAxis::z).mesh.vertices[1], Vec3(1, 0, 0));
}

TEST_F(MeshIo, GltfNonFiniteCoordinateIsInputError) {
  const std::string bytes = triangle_buffer(std::numeric_limits<float>::quiet_NaN());
  expect_input_error(write("nan.gltf", triangle_gltf(embedded(bytes), kTranslatedNode)), "finite");
}

TEST_F(MeshIo, GltfAccessorPastItsBufferIsInputError) {
  // 4 positions claimed in a 36-byte view that holds 3.
  const fs::path p = write("short.gltf", triangle_gltf(embedded(triangle_buffer()), kTranslatedNode, "", 4));
  expect_input_error(p, "past the end");
}

TEST_F(MeshIo, GltfBrokenHierarchyIsInputError) {
  const std::string buffer = embedded(triangle_buffer());
  const std::string cycle = R"("nodes": [{"children": [1]}, {"mesh": 0, "children": [0]}], "scenes": [{"nodes": [0]}])";
  expect_input_error(write("cycle.gltf", triangle_gltf(buffer, cycle)), "cycle");
  const std::string dangling = R"("nodes": [{"mesh": 0, "children": [7]}], "scenes": [{"nodes": [0]}])";
  expect_input_error(write("dangling.gltf", triangle_gltf(buffer, dangling)), "node 7");
  const std::string draco = kTranslatedNode + R"(, "extensionsRequired": ["KHR_draco_mesh_compression"])";
  expect_input_error(write("draco.gltf", triangle_gltf(buffer, draco)), "KHR_draco_mesh_compression");
}

TEST_F(MeshIo, MissingFileIsInputErrorNamingIt) {
  expect_input_error(dir_ / "nowhere.gltf", "not found");
  expect_input_error(dir_ / "nowhere.obj", "not found");
}

TEST_F(MeshIo, GarbageFilesAreInputErrorsNamingThem) {
  expect_input_error(write("garbage.gltf", "{ this is not json"));
  expect_input_error(write("garbage.glb", std::string("glTF\x02\0\0\0\xff\xff", 10)));
  expect_input_error(write("garbage.obj", std::string("\x7f"
                                                      "ELF\x01\x02 binary junk\n")),
                     "no triangles");
  expect_input_error(write("model.stl", "solid x\nendsolid x\n"), "extension");
}

}  // namespace
}  // namespace skylit

namespace skylit {
namespace {

// Normal-incidence Fresnel reflectance of an interface from air, |(ñ − 1)/(ñ + 1)|²,
// written out here independently of material/fresnel.cpp.
double normal_reflectance(double n, double k) { return ((n - 1) * (n - 1) + k * k) / ((n + 1) * (n + 1) + k * k); }

void expect_same_spectrum(const Spectrum& a, const Spectrum& b, double tolerance) {
  for (int i = 0; i < Spectrum::size(); ++i) EXPECT_NEAR(a[i], b[i], tolerance) << "bin " << i;
}

TEST_F(MeshIo, ObjMaterialsFromMtlPerFace) {
  write("house.mtl",
        "newmtl Brick_red\nKd 0.5 0.2 0.1\nillum 1\n"
        "newmtl Window_Glass\nKd 0.1 0.1 0.1\nd 0.3\nNi 1.52\n"
        "newmtl Roof_Metal\nKd 0 0 0\nKs 0.9 0.6 0.3\nNs 200\nillum 3\n"
        "newmtl Painted\nKd 0.3 0.3 0.3\nKs 0.5 0.5 0.5\nNs 50\nillum 2\n"
        "newmtl Frosted\nKd 1 1 1\nTr 0.8\nNi 1.0\n");
  const fs::path p = write("house.obj",
                           "mtllib house.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                           "f 1 2 3\nusemtl Brick_red\nf 1 2 3 4\nusemtl Window_Glass\nf 1 3 4\n"
                           "usemtl Roof_Metal\nf 1 2 4\nusemtl Painted\nf 2 3 4\nusemtl Frosted\nf 1 2 3\n");
  const LoadedModel model = load_model_file(p, UpAxis::z);
  ASSERT_EQ(model.materials.size(), 5u);
  EXPECT_TRUE(model.missing_libraries.empty());
  ASSERT_EQ(model.triangle_material.size(), 7u);  // the quad gives two
  EXPECT_EQ(model.triangle_material, (std::vector<int32_t>{LoadedModel::kNoMaterial, 0, 0, 1, 2, 3, 4}));

  const ModelMaterial& brick = model.materials[0];
  EXPECT_EQ(brick.name, "Brick_red");
  EXPECT_EQ(brick.kind, ModelMaterial::Kind::diffuse);
  const Material brick_material = material_from_model(brick);
  ASSERT_TRUE(std::holds_alternative<DiffuseMaterial>(brick_material));
  expect_same_spectrum(std::get<DiffuseMaterial>(brick_material).reflectance,
                       reflectance_from_linear_srgb({0.5, 0.2, 0.1}), 1e-6);

  EXPECT_EQ(model.materials[1].kind, ModelMaterial::Kind::glass);  // d < 1
  EXPECT_NEAR(model.materials[1].ior, 1.52, 1e-6);
  const Material glass = material_from_model(model.materials[1]);
  ASSERT_TRUE(std::holds_alternative<GlassMaterial>(glass));
  EXPECT_NEAR(std::get<GlassMaterial>(glass).ior().n[10], 1.52, 1e-6);

  // A black body with a coloured Ks: a metal whose normal reflectance is Ks.
  const ModelMaterial& roof = model.materials[2];
  EXPECT_EQ(roof.kind, ModelMaterial::Kind::metal);
  const Material roof_material = material_from_model(roof);
  ASSERT_TRUE(std::holds_alternative<CookTorranceMaterial>(roof_material));
  const auto& metal = std::get<CookTorranceMaterial>(roof_material);
  EXPECT_TRUE(metal.ior().is_conductor());
  EXPECT_FALSE(metal.has_diffuse());
  EXPECT_NEAR(metal.roughness(), std::sqrt(2.0 / 202.0), 1e-12);  // Walter et al. Eq. 37
  const Spectrum ks = reflectance_from_linear_srgb({0.9, 0.6, 0.3});
  for (int i = 0; i < Spectrum::size(); ++i)  // n, k are floats: 1e-5
    EXPECT_NEAR(normal_reflectance(metal.ior().n[i], metal.ior().k[i]), ks[i], 1e-5) << "bin " << i;

  EXPECT_EQ(model.materials[3].kind, ModelMaterial::Kind::coated);
  EXPECT_NEAR(model.materials[3].ior, 1.5, 1e-12);  // Ni absent: the usual coat
  // Tr = 1 − d; Ni 1.0 means "not set": glass of index 1.5.
  EXPECT_EQ(model.materials[4].kind, ModelMaterial::Kind::glass);
  EXPECT_NEAR(model.materials[4].ior, 1.5, 1e-12);
}

// MeshLab writes `Tr` as an opacity: `Tr 1` alone is an opaque material, with a warning
// naming the library, the material and the rule. A transparent illum, a `d` (which wins)
// or a Tr below 0.99 keep Tr = 1 − d. The second library, with CRLF lines, checks that
// each material is matched to its own lines.
TEST_F(MeshIo, MtlTrOfOneAloneIsMeshLabsOpacity) {
  write("a.mtl",
        "newmtl material_0\nKa 0.2 0.2 0.2\nKd 0.6 0.5 0.4\nKs 0 0 0\nTr 1.000000\nillum 2\nNs 0\n"
        "newmtl Pane\nKd 0.1 0.1 0.1\nTr 1\nillum 4\n"
        "newmtl Dissolved\nKd 0.5 0.5 0.5\nd 0\nTr 1\n"
        "newmtl Half\nKd 0.5 0.5 0.5\nTr 0.5\n");
  write("b.mtl", "newmtl Painted\r\nKd 0.3 0.3 0.3\r\nKs 0.5 0.5 0.5\r\nillum 2\r\nTr 0.995\r\n");
  const fs::path p = write("m.obj", "mtllib a.mtl b.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl material_0\nf 1 2 3\n");
  const LoadedModel model = load_model_file(p, UpAxis::z);
  ASSERT_EQ(model.materials.size(), 5u);
  EXPECT_EQ(model.materials[0].kind, ModelMaterial::Kind::diffuse);
  expect_same_spectrum(std::get<DiffuseMaterial>(material_from_model(model.materials[0])).reflectance,
                       reflectance_from_linear_srgb({0.6, 0.5, 0.4}), 1e-6);
  EXPECT_EQ(model.materials[1].kind, ModelMaterial::Kind::glass);  // illum 4: meant clear
  EXPECT_EQ(model.materials[2].kind, ModelMaterial::Kind::glass);  // d 0 wins over Tr
  EXPECT_EQ(model.materials[3].kind, ModelMaterial::Kind::glass);  // Tr 0.5: d 0.5 either way
  EXPECT_EQ(model.materials[4].kind, ModelMaterial::Kind::coated);
  EXPECT_EQ(model.read_warnings,
            (std::vector<std::string>{
                "material library 'a.mtl', material 'material_0': Tr 1 without d read as MeshLab writes it, an "
                "opacity (opaque), not as 1 − d (clear glass)",
                "material library 'b.mtl', material 'Painted': Tr 0.995 without d read as MeshLab writes it, an "
                "opacity (opaque), not as 1 − d (clear glass)"}));
}

// usemtl names a material as newmtl does, spaces and all (Max2Mtl's "Hard Shiny
// Plastic White" fell back to the object's material without a word), else by its first
// word as tinyobjloader reads it; a name no library defines is warned of.
TEST_F(MeshIo, ObjMaterialNamesWithSpacesAndUndefinedNames) {
  write("spaces.mtl", "newmtl Hard Shiny Plastic White\nKd 0.9 0.9 0.9\nnewmtl Glass\nd 0.2\n");
  const fs::path p = write("spaces.obj",
                           "mtllib spaces.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\n"
                           "usemtl Hard Shiny Plastic White \nf 1 2 3\nusemtl Glass left over\nf 1 2 3\n"
                           "usemtl Nowhere\nf 1 2 3\n");
  const LoadedModel model = load_model_file(p, UpAxis::z);
  ASSERT_EQ(model.materials.size(), 2u);
  EXPECT_EQ(model.materials[0].name, "Hard Shiny Plastic White");
  EXPECT_EQ(model.triangle_material, (std::vector<int32_t>{0, 1, LoadedModel::kNoMaterial}));
  EXPECT_EQ(
      model.read_warnings,
      std::vector<std::string>{"usemtl 'Nowhere': in no mtllib of the file; those faces take the object's material"});

  const LoadedModel without_library =
      load_model_file(write("bare.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl Brick\nf 1 2 3\n"), UpAxis::z);
  EXPECT_EQ(
      without_library.read_warnings,
      std::vector<std::string>{"usemtl 'Brick', but no mtllib of the file; those faces take the object's material"});
}

// A vertex index outside the file is an error; a vt or vn index outside is read as
// none and warned of (three.js' verify.obj has them; viewers show such files).
TEST_F(MeshIo, ObjTextureAndNormalIndicesOutsideTheFileAreReadAsNoneAndSaid) {
  const LoadedModel model = load_model_file(
      write("past.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/5/1 3/1/7\nf 1/1/1 2/1/1 3/1/1\n"),
      UpAxis::z);
  EXPECT_EQ(model.skipped_primitives, 0);
  ASSERT_EQ(model.corner_uvs.size(), 2u);
  EXPECT_EQ(model.corner_uvs[0][1], (std::array<float, 2>{0.0f, 0.0f}));
  EXPECT_EQ(model.read_warnings,
            std::vector<std::string>{"2 face corner(s) name a texture coordinate (vt) or normal (vn) the file does not "
                                     "have; read as none"});
}

// Points and lines are not surfaces: skipped, and counted for `skylit info` as glTF's are.
TEST_F(MeshIo, ObjPointsAndLinesAreCounted) {
  const LoadedModel model =
      load_model_file(write("lines.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nl 1 2 3\np 1\nl 2 3\n"), UpAxis::z);
  EXPECT_EQ(model.mesh.triangles.size(), 1u);
  EXPECT_EQ(model.skipped_primitives, 3);
}

TEST_F(MeshIo, ObjMissingMaterialLibraryIsNotAnError) {
  const fs::path p = write("lost.obj", "mtllib nowhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl Brick\nf 1 2 3\n");
  const LoadedModel model = load_model_file(p, UpAxis::z);
  EXPECT_EQ(model.missing_libraries, std::vector<std::string>{"nowhere.mtl"});
  EXPECT_EQ(model.triangle_material, std::vector<int32_t>{LoadedModel::kNoMaterial});
}

std::string with_material(int index) {
  return R"(, {"attributes": {"POSITION": 0}, "indices": 1, "material": )" + std::to_string(index) + "}";
}

TEST_F(MeshIo, GltfMaterialsMapToMetalGlassAndCoat) {
  const std::string materials = R"("materials": [
      {"name": "Gold", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.6, 0.2, 1], "metallicFactor": 1,
                                                "roughnessFactor": 0.5}},
      {"name": "Pane", "pbrMetallicRoughness": {"metallicFactor": 0, "roughnessFactor": 0},
       "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1},
                      "KHR_materials_ior": {"ior": 1.45},
                      "KHR_materials_volume": {"thicknessFactor": 0.01}}},
      {"pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 1], "metallicFactor": 0}}],
  )";
  for (int index : {0, 1, 2}) {
    SCOPED_TRACE(index);
    // A second primitive, the same triangle with a material.
    const fs::path p =
        write("m.gltf", triangle_gltf(embedded(triangle_buffer()), materials + kTranslatedNode, with_material(index)));
    const LoadedModel model = load_model_file(p, UpAxis::y);
    ASSERT_EQ(model.materials.size(), 3u);
    EXPECT_EQ(model.triangle_material, (std::vector<int32_t>{LoadedModel::kNoMaterial, index}));
  }
  const fs::path p = write("m.gltf", triangle_gltf(embedded(triangle_buffer()), materials + kTranslatedNode));
  const LoadedModel model = load_model_file(p, UpAxis::y);
  EXPECT_EQ(model.triangle_material, std::vector<int32_t>{LoadedModel::kNoMaterial});

  // metallicFactor 1: the Fresnel colour at normal incidence is the base colour.
  const ModelMaterial& gold = model.materials[0];
  EXPECT_EQ(gold.kind, ModelMaterial::Kind::metal);
  EXPECT_NEAR(gold.roughness, 0.25, 1e-12);  // α = roughness²
  const auto metal = std::get<CookTorranceMaterial>(material_from_model(gold));
  const Spectrum base = reflectance_from_linear_srgb({0.9, 0.6, 0.2});
  const Spectrum f0 = metal.fresnel().at(1.0);
  for (int i = 0; i < Spectrum::size(); ++i) {
    EXPECT_NEAR(normal_reflectance(metal.ior().n[i], metal.ior().k[i]), base[i], 1e-5) << "bin " << i;
    // The renderer's table agrees (its interpolation error is below 1e-4, fresnel_test.cpp).
    EXPECT_NEAR(f0[i], base[i], 1e-4) << "bin " << i;
  }

  const ModelMaterial& pane = model.materials[1];
  EXPECT_EQ(pane.name, "Pane");
  EXPECT_EQ(pane.kind, ModelMaterial::Kind::glass);
  EXPECT_NEAR(pane.ior, 1.45, 1e-12);
  EXPECT_NEAR(pane.thickness_m, 0.01, 1e-12);

  const ModelMaterial& coat = model.materials[2];
  EXPECT_EQ(coat.name, "material 2");  // unnamed: named by its index
  EXPECT_EQ(coat.kind, ModelMaterial::Kind::coated);
  EXPECT_NEAR(coat.roughness, 1.0, 1e-12);  // the spec's default roughnessFactor 1
  const auto layered = std::get<CookTorranceMaterial>(material_from_model(coat));
  EXPECT_NEAR(layered.ior().n[0], 1.5, 1e-6);
  expect_same_spectrum(layered.diffuse_reflectance(), reflectance_from_linear_srgb({0.2, 0.4, 0.6}), 1e-6);
}

TEST_F(MeshIo, GltfMaterialOutOfRangeIsInputError) {
  expect_input_error(
      write("bad_material.gltf", triangle_gltf(embedded(triangle_buffer()), kTranslatedNode, with_material(4))),
      "material 4");
}

}  // namespace
}  // namespace skylit
