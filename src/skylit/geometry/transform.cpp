// Affine transform construction, composition and application (see transform.h).
#include "skylit/geometry/transform.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace skylit {
namespace {

// cos/sin of an angle in degrees, exact at multiples of 90° so that axis-aligned
// rotations of boxes give exactly axis-aligned results (sin(π) is 1.2e-16, not 0).
std::pair<double, double> cos_sin_deg(double angle_deg) {
  const double r = std::fmod(angle_deg, 360.0);
  const double q = r / 90.0;
  if (q == std::floor(q)) {
    switch ((static_cast<int>(q) % 4 + 4) % 4) {
      case 0:
        return {1.0, 0.0};
      case 1:
        return {0.0, 1.0};
      case 2:
        return {-1.0, 0.0};
      default:
        return {0.0, -1.0};
    }
  }
  return {std::cos(radians(angle_deg)), std::sin(radians(angle_deg))};
}

}  // namespace

Transform Transform::translation(Vec3 o) {
  Transform t;
  t.m[0][3] = o.x;
  t.m[1][3] = o.y;
  t.m[2][3] = o.z;
  return t;
}

Transform Transform::scale(Vec3 f) {
  Transform t;
  t.m[0][0] = f.x;
  t.m[1][1] = f.y;
  t.m[2][2] = f.z;
  return t;
}

Transform Transform::rotation_x_deg(double angle_deg) {
  const auto [c, s] = cos_sin_deg(angle_deg);
  Transform t;
  t.m[1][1] = c, t.m[1][2] = -s;
  t.m[2][1] = s, t.m[2][2] = c;
  return t;
}

Transform Transform::rotation_y_deg(double angle_deg) {
  const auto [c, s] = cos_sin_deg(angle_deg);
  Transform t;
  t.m[0][0] = c, t.m[0][2] = s;
  t.m[2][0] = -s, t.m[2][2] = c;
  return t;
}

Transform Transform::rotation_z_deg(double angle_deg) {
  const auto [c, s] = cos_sin_deg(angle_deg);
  Transform t;
  t.m[0][0] = c, t.m[0][1] = -s;
  t.m[1][0] = s, t.m[1][1] = c;
  return t;
}

Transform Transform::rotation_xyz_deg(Vec3 a) {
  return rotation_z_deg(a.z) * rotation_y_deg(a.y) * rotation_x_deg(a.x);
}

Transform Transform::rotation_quaternion(double x, double y, double z, double w) {
  const double n = std::sqrt(x * x + y * y + z * z + w * w);
  if (!(n > 0) || !std::isfinite(n)) throw std::invalid_argument("rotation quaternion is zero or not finite");
  x /= n, y /= n, z /= n, w /= n;
  Transform t;
  t.m[0] = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w), 0};
  t.m[1] = {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w), 0};
  t.m[2] = {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y), 0};
  return t;
}

Transform Transform::from_column_major_4x4(const std::array<double, 16>& c) {
  Transform t;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 4; ++col) t.m[row][col] = c[col * 4 + row];
  return t;
}

Transform Transform::operator*(const Transform& o) const {
  Transform r;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 4; ++j) {
      double sum = j == 3 ? m[i][3] : 0.0;
      for (int k = 0; k < 3; ++k) sum += m[i][k] * o.m[k][j];
      r.m[i][j] = sum;
    }
  }
  return r;
}

Vec3 Transform::apply_point(Vec3 p) const { return apply_vector(p) + Vec3{m[0][3], m[1][3], m[2][3]}; }

Vec3 Transform::apply_vector(Vec3 v) const {
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

Vec3 Transform::apply_normal(Vec3 n) const {
  // det(A) A^-T, the cofactor matrix, has the columns a1 × a2, a2 × a0, a0 × a1 of A's
  // columns a_i; its sign is turned by det(A)'s.
  const Vec3 a0{m[0][0], m[1][0], m[2][0]}, a1{m[0][1], m[1][1], m[2][1]}, a2{m[0][2], m[1][2], m[2][2]};
  const Vec3 out = (determinant() < 0 ? -1.0 : 1.0) * (n.x * cross(a1, a2) + n.y * cross(a2, a0) + n.z * cross(a0, a1));
  const double len = length(out);
  return len > 0 && std::isfinite(len) ? out / len : Vec3{0, 0, 0};
}

double Transform::determinant() const {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

TriangleMesh transformed(const TriangleMesh& mesh, const Transform& world_from_object) {
  TriangleMesh out;
  out.vertices.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) out.vertices.push_back(world_from_object.apply_point(v));
  out.triangles = mesh.triangles;
  if (world_from_object.determinant() < 0)
    for (auto& t : out.triangles) std::swap(t[1], t[2]);
  return out;
}

}  // namespace skylit
