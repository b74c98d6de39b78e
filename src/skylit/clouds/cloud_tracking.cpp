#include "skylit/clouds/cloud_tracking.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace skylit {

namespace {

// The ray's pieces between the bounding volumes' entries and exits, each with the
// clouds that cover it and their summed extinction (the majorant there).
struct Piece {
  double begin, end, majorant;
  std::vector<const Cloud*> clouds;
};

std::vector<Piece> pieces_of(const CloudLayer& layer, const Vec3& o, const Vec3& d, double t_end) {
  const std::vector<CloudLayer::Crossing> crossings = layer.crossings(o, d, 0.0, t_end);
  std::vector<double> cuts;
  for (const CloudLayer::Crossing& c : crossings) {
    cuts.push_back(std::clamp(c.t_enter, 0.0, t_end));
    cuts.push_back(std::clamp(c.t_exit, 0.0, t_end));
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::vector<Piece> pieces;
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    Piece piece{cuts[i], cuts[i + 1], 0.0, {}};
    const double middle = 0.5 * (piece.begin + piece.end);
    for (const CloudLayer::Crossing& c : crossings) {
      const Cloud& cloud = layer.clouds()[c.index];
      if (c.t_enter <= middle && middle <= c.t_exit && cloud.shape().extinction > 0) {
        piece.clouds.push_back(&cloud);
        piece.majorant += cloud.shape().extinction;
      }
    }
    if (piece.majorant > 0) pieces.push_back(std::move(piece));
  }
  return pieces;
}

// The extinction at p (m⁻¹): the clouds of the piece whose solid holds it.
double extinction_at(const Piece& piece, const Vec3& p) {
  double sum = 0;
  for (const Cloud* c : piece.clouds)
    if (c->contains(p)) sum += c->shape().extinction;
  return sum;
}

// Of the clouds holding p, the one that scattered: chosen in proportion to its share
// of the extinction σ there, by pick uniform in [0, σ).
const Cloud* scattering_cloud(const Piece& piece, const Vec3& p, double pick) {
  double running = 0;
  const Cloud* last = nullptr;
  for (const Cloud* c : piece.clouds) {
    if (!c->contains(p)) continue;
    last = c;
    running += c->shape().extinction;
    if (pick < running) return c;
  }
  return last;
}

}  // namespace

CloudCollision sample_cloud_collision(const CloudLayer& layer, const Vec3& o, const Vec3& d, double t_end,
                                      CounterRandom& random) {
  for (const Piece& piece : pieces_of(layer, o, d, t_end)) {
    double t = piece.begin;
    while (true) {
      t -= std::log1p(-random.uniform()) / piece.majorant;
      if (t >= piece.end) break;
      const Vec3 p = o + t * d;
      const double sigma = extinction_at(piece, p);
      if (random.uniform() * piece.majorant < sigma)
        return {true, t, scattering_cloud(piece, p, random.uniform() * sigma)->shape().albedo};
    }
  }
  return {};
}

double estimate_cloud_transmittance(const CloudLayer& layer, const Vec3& o, const Vec3& d, double t_end,
                                    CounterRandom& random) {
  // Ratio tracking (Novák, Selle & Jarosz 2014) against twice the majorant while the
  // estimate is above a tenth. Against the majorant itself, each tentative collision
  // inside a cloud (whose extinction is the majorant there) multiplies by 1 − σ/σ̄ = 0:
  // the estimate is 0 or 1, with a relative variance of e^τ − 1 over optical depth τ,
  // and it is multiplied by the droplets' forward peak where the sun is seen through
  // them (path_integrator.h). With 2σ̄ each halves it (variance e^{τ/2} − 1, twice the
  // steps); below a tenth the majorant's own tracking ends it cheaply. The rate of each
  // flight may depend on the estimate so far: every flight's expected factor is still
  // the transmittance over it.
  constexpr double kHalvingAbove = 0.1;
  double transmittance = 1;
  for (const Piece& piece : pieces_of(layer, o, d, t_end)) {
    double t = piece.begin;
    while (transmittance > 0) {
      const double tracking = (transmittance > kHalvingAbove ? 2 : 1) * piece.majorant;
      t -= std::log1p(-random.uniform()) / tracking;
      if (t >= piece.end) break;
      transmittance *= 1 - extinction_at(piece, o + t * d) / tracking;
    }
  }
  return transmittance;
}

}  // namespace skylit
