// The CIE road-surface tables read from data/road_r_tables.csv, their look-up and
// the road BRDF (road_reflection.h).
#include "skylit/material/road_reflection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

#include "skylit/core/angles.h"
#include "skylit/core/embedded_data.h"

namespace skylit {

namespace {

// Nominal Q0 of the standard classes, sr⁻¹ (CIE 144:2001, Table 2; the same values
// are listed by W. van Bommel, Road Lighting, Springer 2015, Table 12.2).
constexpr std::array<std::pair<std::string_view, double>, 6> kNominalQ0 = {
    {{"R1", 0.10}, {"R2", 0.07}, {"R3", 0.07}, {"R4", 0.08}, {"C1", 0.10}, {"C2", 0.07}}};

std::vector<std::string_view> split(std::string_view line, char sep) {
  std::vector<std::string_view> out;
  size_t start = 0;
  for (;;) {
    const size_t end = line.find(sep, start);
    out.push_back(line.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return out;
    start = end + 1;
  }
}

double number(std::string_view cell) {
  if (cell.empty()) return 0;  // an empty cell: outside the table's domain
  return std::stod(std::string(cell));
}

// Every class's table from the embedded CSV: class, tan γ, then r × 10⁴ at each β.
std::map<std::string, std::shared_ptr<const RoadReflectionTable>, std::less<>> load_tables() {
  const std::string_view text = data::embedded_file("road_r_tables.csv");
  std::vector<std::string_view> lines = split(text, '\n');
  if (lines.empty()) throw std::logic_error("road_r_tables.csv is empty");
  std::vector<double> betas;
  const std::vector<std::string_view> header = split(lines[0], ',');
  for (size_t j = 2; j < header.size(); ++j)  // "beta_15"
    betas.push_back(std::stod(std::string(header[j].substr(header[j].find('_') + 1))));
  struct Rows {
    std::vector<double> tans, r;
  };
  std::map<std::string, Rows, std::less<>> rows;
  for (size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    const std::vector<std::string_view> cells = split(lines[i], ',');
    if (cells.size() != betas.size() + 2) throw std::logic_error("road_r_tables.csv: ragged row");
    Rows& t = rows[std::string(cells[0])];
    t.tans.push_back(number(cells[1]));
    for (size_t j = 2; j < cells.size(); ++j) t.r.push_back(number(cells[j]) * 1e-4);
  }
  std::map<std::string, std::shared_ptr<const RoadReflectionTable>, std::less<>> out;
  for (const auto& [name, q0] : kNominalQ0) {
    auto it = rows.find(name);
    if (it == rows.end()) throw std::logic_error("road_r_tables.csv lacks a class");
    out.emplace(
        name, std::make_shared<const RoadReflectionTable>(std::string(name), q0, it->second.tans, betas, it->second.r));
  }
  return out;
}

const std::map<std::string, std::shared_ptr<const RoadReflectionTable>, std::less<>>& tables() {
  static const auto all = load_tables();
  return all;
}

// The interval [i, i + 1] of a sorted axis holding x, and the weight of i + 1.
std::pair<size_t, double> locate(const std::vector<double>& axis, double x) {
  const auto upper = std::upper_bound(axis.begin(), axis.end(), x);
  size_t i = upper == axis.begin() ? 0 : static_cast<size_t>(upper - axis.begin()) - 1;
  i = std::min(i, axis.size() - 2);
  const double t = std::clamp((x - axis[i]) / (axis[i + 1] - axis[i]), 0.0, 1.0);
  return {i, t};
}

}  // namespace

RoadReflectionTable::RoadReflectionTable(std::string name, double nominal_q0, std::vector<double> tan_gammas,
                                         std::vector<double> betas_deg, std::vector<double> r_values)
    : name_(std::move(name)),
      nominal_q0_(nominal_q0),
      tan_gammas_(std::move(tan_gammas)),
      betas_deg_(std::move(betas_deg)),
      r_(std::move(r_values)) {
  if (tan_gammas_.size() < 2 || betas_deg_.size() < 2 || r_.size() != tan_gammas_.size() * betas_deg_.size())
    throw std::invalid_argument("RoadReflectionTable: the values do not fill the axes");
}

std::shared_ptr<const RoadReflectionTable> RoadReflectionTable::standard(std::string_view name) {
  const auto it = tables().find(name);
  return it == tables().end() ? nullptr : it->second;
}

std::string RoadReflectionTable::standard_names() {
  std::string out;
  for (const auto& [name, q0] : kNominalQ0) out += (out.empty() ? "" : ", ") + std::string(name);
  return out;
}

double RoadReflectionTable::at(double beta_deg, double tan_gamma) const {
  if (!(tan_gamma >= 0) || tan_gamma > tan_gammas_.back()) return 0;
  double beta = std::fmod(std::abs(beta_deg), 360.0);
  if (beta > 180) beta = 360 - beta;
  const auto [i, u] = locate(tan_gammas_, tan_gamma);
  const auto [j, v] = locate(betas_deg_, beta);
  const size_t n = betas_deg_.size();
  const auto r = [&](size_t a, size_t b) { return r_[a * n + b]; };
  return (1 - u) * ((1 - v) * r(i, j) + v * r(i, j + 1)) + u * ((1 - v) * r(i + 1, j) + v * r(i + 1, j + 1));
}

RoadAngles road_angles(const Vec3& n, const Vec3& to_light, const Vec3& to_viewer) {
  const double cos_gamma = dot(n, to_light);
  const Vec3 l_along = to_light - cos_gamma * n;  // the parts parallel to the road
  const Vec3 v_along = to_viewer - dot(n, to_viewer) * n;
  const double l_len = length(l_along), v_len = length(v_along);
  const double tan_gamma = cos_gamma > 0 ? l_len / cos_gamma : 0.0;
  double beta_deg = 0;  // undefined straight below the lamp or seen from straight above: r does not depend on it
  if (l_len > 1e-12 && v_len > 1e-12)
    beta_deg = degrees(std::acos(std::clamp(-dot(l_along, v_along) / (l_len * v_len), -1.0, 1.0)));
  return {beta_deg, tan_gamma, cos_gamma};
}

RoadMaterial::RoadMaterial(std::shared_ptr<const RoadReflectionTable> table, double q0)
    : table_(std::move(table)), q0_(q0) {
  if (!table_) throw std::invalid_argument("RoadMaterial: no table");
  if (!(q0 > 0)) throw std::invalid_argument("RoadMaterial: q0 must be > 0");
}

double RoadMaterial::table_weight(double sin_elevation) {
  // w = 1 up to α = 1.5° (CIE 144's range of validity, 0.5°–1.5°), then linear in α to 0 at 20°.
  constexpr double kTableUpTo = radians(1.5), kDiffuseFrom = radians(20.0);
  const double alpha = std::asin(std::clamp(sin_elevation, 0.0, 1.0));
  return std::clamp((kDiffuseFrom - alpha) / (kDiffuseFrom - kTableUpTo), 0.0, 1.0);
}

double RoadMaterial::table_luminance_coefficient(const Vec3& n, const Vec3& to_light, const Vec3& to_viewer) const {
  const RoadAngles a = road_angles(n, to_light, to_viewer);
  if (!(a.cos_gamma > 0) || !(dot(n, to_viewer) > 0)) return 0;
  return q0_ / table_->nominal_q0() * table_->at(a.beta_deg, a.tan_gamma) / (a.cos_gamma * a.cos_gamma * a.cos_gamma);
}

double RoadMaterial::brdf(const Vec3& n, const Vec3& to_light, const Vec3& to_viewer) const {
  const double sin_view = dot(n, to_viewer);
  if (!(dot(n, to_light) > 0) || !(sin_view > 0)) return 0;
  const double w = table_weight(sin_view);
  return w * table_luminance_coefficient(n, to_light, to_viewer) + (1 - w) * q0_;
}

}  // namespace skylit
