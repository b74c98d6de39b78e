// The one-pass OBJ reader (io/model/obj_parser.h) against tinyobjloader, which the
// project read OBJ files with before and whose index semantics the scenes rely on: the
// same corners (vertex, texture and normal indices), faces and usemtl names on files
// that use every index form, and clear errors where tinyobjloader only failed.
#include "skylit/io/model/obj_parser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include <tiny_obj_loader.h>

#include "skylit/core/error.h"

namespace skylit {
namespace {

// The faces tinyobjloader reads (without triangulating), flattened as parse_obj lists
// them, with each face's material name ("" for none).
struct Faces {
  std::vector<std::array<int, 3>> corners;
  std::vector<uint32_t> ends;
  std::vector<std::string> materials;
};

Faces tinyobj_faces(const std::string& obj, const std::string& mtl) {
  std::istringstream obj_stream(obj);
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  std::istringstream mtl_stream(mtl);
  tinyobj::MaterialStreamReader mtl_reader(mtl_stream);
  EXPECT_TRUE(tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &obj_stream, &mtl_reader, false)) << err;
  Faces out;
  for (const tinyobj::shape_t& shape : shapes) {
    size_t first = 0;
    for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      for (size_t k = 0; k < shape.mesh.num_face_vertices[f]; ++k) {
        const tinyobj::index_t& i = shape.mesh.indices[first + k];
        out.corners.push_back({i.vertex_index, i.texcoord_index, i.normal_index});
      }
      first += shape.mesh.num_face_vertices[f];
      out.ends.push_back(static_cast<uint32_t>(out.corners.size()));
      const int m = shape.mesh.material_ids[f];
      out.materials.push_back(m < 0 ? "" : materials[static_cast<size_t>(m)].name);
    }
  }
  return out;
}

Faces our_faces(const ObjGeometry& obj) {
  Faces out;
  for (const ObjCorner& c : obj.corners) out.corners.push_back({c.vertex, c.texcoord, c.normal});
  out.ends.assign(obj.face_ends.begin(), obj.face_ends.end());
  for (const int32_t name : obj.face_material_names)
    out.materials.push_back(name < 0 ? "" : obj.material_names[static_cast<size_t>(name)]);
  return out;
}

TEST(ObjParser, ReadsFacesAsTinyobjloaderDoes) {
  // Absolute and relative indices of each kind, interleaved lists, a comment, groups,
  // CRLF and lone-CR line ends, tabs, a w coordinate and a usemtl with trailing words.
  const std::string mtl = "newmtl Brick\nKd 1 0 0\nnewmtl Glass\nd 0.2\n";
  const std::string obj =
      "mtllib house.mtl\r\n# corners\nv 0 0 0\nv 1 0 0\nv 1 1 0 1\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\nvn 0 0 -1\n"
      "f 1 2 3\nusemtl Brick\nf 1/1 2/2 3/3 4/1\r\n\tf -4/-3/-2 -3/-2/-1 -2/-1/-1\n"
      "o other\ng walls\nv 0 0 1\nvt 0.5 0.5\nusemtl Glass left over\rf 5//1 1//2 2//1\r"
      "usemtl Unknown\nf -1/-1 1/1 2/2\nusemtl Brick\nf 4 3 2 1 5\n";
  const ObjGeometry ours = parse_obj(obj, "house.obj");
  const Faces theirs = tinyobj_faces(obj, mtl);
  const Faces mine = our_faces(ours);
  EXPECT_EQ(mine.corners, theirs.corners);
  EXPECT_EQ(mine.ends, theirs.ends);
  // tinyobjloader has no material for a name the library lacks; the reader keeps it.
  // It reads usemtl's first word; the reader keeps the whole line, which the loader
  // matches whole first (obj_loader.cpp) and then by its first word.
  ASSERT_EQ(mine.materials.size(), theirs.materials.size());
  for (size_t f = 0; f < mine.materials.size(); ++f) {
    const std::string first_word = mine.materials[f].substr(0, mine.materials[f].find(' '));
    EXPECT_EQ(first_word == "Unknown" ? "" : first_word, theirs.materials[f]) << "face " << f;
  }
  EXPECT_EQ(ours.material_names[1], "Glass left over");
  EXPECT_EQ(ours.positions.size(), 5u);
  EXPECT_EQ(ours.texcoords.size(), 4u);
  EXPECT_EQ(ours.normals.size(), 2u);
  EXPECT_EQ(ours.material_libraries, std::vector<std::string>{"house.mtl"});
  EXPECT_EQ(ours.texcoords[3], (std::array<float, 2>{0.5f, 0.5f}));
  EXPECT_EQ(ours.normals[1], (std::array<float, 3>{0.0f, 0.0f, -1.0f}));
}

TEST(ObjParser, BadCornersAndVerticesNameTheLine) {
  const auto message = [](const std::string& obj) {
    try {
      parse_obj(obj, "m.obj");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n").find("m.obj:4:"), std::string::npos);
  EXPECT_NE(message("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 two 3\n").find("m.obj:5:"), std::string::npos);
  EXPECT_NE(message("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x 2 3\n").find("m.obj:4:"), std::string::npos);
  EXPECT_NE(message("v 0 0 0\rv 1 inf 0\n").find("m.obj:2:"), std::string::npos);
  EXPECT_EQ(message("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "no error");
}

// Forms real exporters write that are not errors: empty index fields ("1//", "2/2/",
// "3/": none given) and a face continued on the next line by a backslash (the OBJ
// specification's continuation, CRLF line ends too). An outside trial found both refused.
TEST(ObjParser, EmptyFieldsAndContinuedLines) {
  const ObjGeometry obj = parse_obj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nf 1// 2/2/ 3/\nf 2 4 \\\r\n  3\r\nf 1 2 \\\n3 \\\n",
      "m.obj");
  ASSERT_EQ(obj.face_ends, (HugePageVector<uint32_t>{3, 6, 9}));
  EXPECT_EQ(obj.corners[0].vertex, 0);
  EXPECT_EQ(obj.corners[0].texcoord, -1);
  EXPECT_EQ(obj.corners[0].normal, -1);
  EXPECT_EQ(obj.corners[1].texcoord, 1);
  EXPECT_EQ(obj.corners[1].normal, -1);
  EXPECT_EQ(obj.corners[2].texcoord, -1);
  EXPECT_EQ(obj.corners[5].vertex, 2);  // the continued face's last corner
  EXPECT_EQ(obj.corners[8].vertex, 2);  // continued to the end of the file
}

// A UTF-8 byte-order mark (as Windows tools write) is skipped: the first vertex kept; a
// UTF-16 file is refused as such.
TEST(ObjParser, AByteOrderMarkIsSkippedAndUtf16Named) {
  const ObjGeometry obj = parse_obj("\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "m.obj");
  EXPECT_EQ(obj.positions.size(), 3u);
  try {
    parse_obj(std::string("\xFF\xFEv\0 \0", 6), "w.obj");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("w.obj: the file is UTF-16 text"), std::string::npos) << e.what();
  }
}

TEST(ObjParser, FacesOfManyCornersAreKept) {
  // tinyobjloader counts a face's corners in a byte; a 300-gon keeps all of its corners.
  std::string obj, face = "f";
  for (int i = 0; i < 300; ++i) {
    obj += "v " + std::to_string(std::cos(i * 0.0209)) + " " + std::to_string(std::sin(i * 0.0209)) + " 0\n";
    face += " " + std::to_string(i + 1);
  }
  const ObjGeometry parsed = parse_obj(obj + face + "\n", "round.obj");
  ASSERT_EQ(parsed.face_ends.size(), 1u);
  EXPECT_EQ(parsed.face_ends[0], 300u);
  EXPECT_EQ(parsed.corners[299].vertex, 299);
}

}  // namespace
}  // namespace skylit
