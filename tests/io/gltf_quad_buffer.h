// The buffer of a 2 m glTF quad used by the texture and material tests: positions in
// the file's x–z plane (skylit's ground, y up), TEXCOORD_0 with v down from the top
// row, two triangles. Written as quad.bin: 48 bytes of positions, 32 of texture
// coordinates, 12 of indices.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>

#include "../test_support.h"

namespace skylit::testing {

inline void write_quad_bin(const TempDir& dir) {
  const float positions[] = {-1, 0, 1, 1, 0, 1, 1, 0, -1, -1, 0, -1};  // glTF +z is skylit's −y
  const float uvs[] = {0, 1, 1, 1, 1, 0, 0, 0};                        // v down from the top row
  const uint16_t indices[] = {0, 1, 2, 0, 2, 3};
  std::string bin(sizeof positions + sizeof uvs + sizeof indices, '\0');
  std::memcpy(bin.data(), positions, sizeof positions);
  std::memcpy(bin.data() + sizeof positions, uvs, sizeof uvs);
  std::memcpy(bin.data() + sizeof positions + sizeof uvs, indices, sizeof indices);
  dir.write("quad.bin", bin);
}

}  // namespace skylit::testing
