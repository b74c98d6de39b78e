// How much of the sky's light reaches a surface under the clouds, by ground position
// and by the way the surface faces: the sky irradiance with the clouds in front of the
// sky over that under the clear sky, per bin. Under a cloud's base and in its shadow the
// share is above one (the sunlit bases and sides, and the sun's light scattered forward
// through the cloud, send more than the clear sky they hide); far from the clouds and on
// walls turned away from them it tends to one.
//
// One share for the whole scene (a horizontal surface below the camera) left the ground
// under and beyond Fig. 10a's clouds 6.6 % too dark against the path-traced reference
// (the share there is 1.04–1.25, blue to red, and up to 1.2–2.5 under and beyond the
// clouds), and lit a wall facing away from the clouds as if it saw them.
//
// Position: a horizontal grid over the clouds' footprint widened by twice their altitude
// (a horizontal surface there still sees them 27° high), read by bilinear interpolation;
// outside it, the nearest edge's value. Cells are at most a third of the clouds' mean
// altitude and at most kMaxCells on a side, over at most ±kMaxReach_m around the camera
// (a generated layer spans tens of kilometres; the ground in view lies nearer).
// Not followed: in a cloud's shadow the light scattered forward through the cloud comes
// from within a few degrees of the sun and changes with the cloud's thickness along the
// sun's line over tens of metres (up to 27 % between nodes; cells half as wide did not
// help).
//
// Facing: each node holds the clouded sky's irradiance on kPlanes planes: facing up, and
// eight azimuths at each of the elevations 45°, 0° and −45°. A surface's normal takes
// the bilinear interpolation of those irradiances in its elevation and azimuth (below
// −45° toward no sky at −90°), and the same of the clear sky's; their ratio is the share.
// An irradiance is the sky's radiance convolved with a cosine, smooth in the normal; the
// five axis planes alone, as an "ambient cube" (Σ n_i² E_i), were off by up to 80 % on
// tilted planes against a dense quadrature: a tilted plane took its share from planes
// that see parts of the sky it does not (the horizontal plane sees the sky behind it).
//
// The quadrature: the upper hemisphere by kZenithRings × kAzimuths cells of equal solid
// angle, except that the cone within kSunCone_deg of the sun is taken by its own rings,
// denser toward the sun: the light the droplets scatter forward through a thin cloud's
// edge lies within a few degrees of the sun, and the hemisphere's cells alone missed or
// hit it by chance (38 % off a dense quadrature in the clouds' shadow).
//
// The nodes are measured up front, in parallel. Measured lazily, when a point first
// needed one, a frame under a generated layer took as long: the nodes' rays meet
// clouds the view never does, each building its sun grid, whichever nodes are asked
// for (52 nodes cost as much as 214 of 625), and a thread waiting for a node measured
// by another could not help build those grids.
#pragma once

#include <array>
#include <vector>

#include "skylit/atmosphere/atmosphere.h"
#include "skylit/clouds/cloud_layer.h"

namespace skylit {

class CloudSkyShare {
 public:
  // The grid over `layer`'s clouds lit by `lighting` under `sky`, around `camera_ground`
  // (its z is the ground's altitude), with at most `max_cells` cells on a side.
  CloudSkyShare(const CloudLayer& layer, const CloudLighting& lighting, const SkyModel& sky, const Vec3& camera_ground,
                int max_cells = kMaxCells);

  // The planes whose irradiances a node holds (plane 0 faces up; then kPlaneAzimuths
  // per elevation of kPlaneElevations_deg, from east counter-clockwise), and the
  // clouded sky's irradiance on each at one ground point, W m⁻² nm⁻¹.
  static constexpr int kPlaneAzimuths = 8;
  static constexpr std::array<double, 3> kPlaneElevations_deg{45, 0, -45};
  static constexpr int kPlanes = 1 + kPlaneAzimuths * static_cast<int>(kPlaneElevations_deg.size());
  static Vec3 plane_normal(int plane);
  using PlaneIrradiances = std::array<Spectrum, kPlanes>;
  PlaneIrradiances measure(const CloudLayer& layer, const CloudLighting& lighting, const SkyModel& sky,
                           const Vec3& ground_point) const;

  // The share for a surface of unit normal `normal` at a point's horizontal position.
  Transmittance at(const Vec3& point, const Vec3& normal) const;
  // The share on a surface of unit normal `normal` under clouds that give the planes `e`.
  Transmittance share_of(const PlaneIrradiances& e, const Vec3& normal) const;

  static constexpr int kMaxCells = 24;
  static constexpr double kMaxReach_m = 6000;
  static constexpr int kZenithRings = 16, kAzimuths = 32;
  static constexpr double kSunCone_deg = 10;
  static constexpr int kSunConeRings = 8, kSunConeAzimuths = 16;
  // A guard against a clear sky that is black in a bin. Sunlit clouds are white and the
  // clear sky is blue: under a generated layer of 50 % cover (sun 28° high) the share
  // measured 1.5–1.8 in the blue and 3.1–4.2 in the red (it was capped at 2 before).
  static constexpr float kMaxShare = 8.0f;

  // The clouded sky's irradiance on a horizontal surface facing up, averaged over the
  // nodes: what the open ground around the camera receives from the sky and the clouds
  // (the sun's beam not counted), W m⁻² nm⁻¹. Under a generated layer it stands for the
  // mean over an hour in which the clouds drift over a point.
  Irradiance mean_irradiance_up() const;

  int nodes_x() const { return nodes_x_; }
  int nodes_y() const { return nodes_y_; }

 private:
  struct Direction {
    Vec3 toward;
    double solid_angle_sr;
    Radiance clear;                              // the clear sky's radiance from there
    std::array<float, kPlanes> plane_weight_sr;  // max(0, n_p·ω) dω for each plane
  };
  // The planes a surface of unit normal n interpolates, with their weights (at most 5).
  struct PlaneWeight {
    int plane;
    float weight;
  };
  struct PlaneWeights {
    std::array<PlaneWeight, 5> terms;
    int count = 0;
    void add(int plane, float weight) { terms[static_cast<size_t>(count++)] = {plane, weight}; }
  };
  static PlaneWeights plane_weights(const Vec3& normal);
  // clouded / clear per bin, at most kMaxShare; 1 where the clear sky is black.
  static Transmittance ratio(const Spectrum& clouded, const Spectrum& clear);
  // The quadrature's directions and solid angles (before the clear sky's radiance).
  void add_directions(const Vec3& to_sun);
  // The grid's origin, cells and nodes over the clouds' footprint.
  void place_grid(const CloudLayer& layer, const Vec3& camera_ground, int max_cells);
  const PlaneIrradiances& node(int i, int j) const { return nodes_[static_cast<size_t>(j * nodes_x_ + i)]; }

  std::vector<Direction> directions_;
  PlaneIrradiances clear_{};  // the clear sky's irradiance on each plane
  double x0_m_ = 0, y0_m_ = 0, cell_x_m_ = 1, cell_y_m_ = 1;
  int nodes_x_ = 1, nodes_y_ = 1;
  std::vector<PlaneIrradiances> nodes_;
};

}  // namespace skylit
