#include "skylit/material/texture.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "skylit/spectrum/color_space.h"

namespace skylit {
namespace {

const std::array<float, 256>& srgb_to_linear_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[static_cast<size_t>(i)] = static_cast<float>(srgb_decode(i / 255.0));
    return t;
  }();
  return table;
}

uint8_t to_byte(double x) { return static_cast<uint8_t>(std::lround(std::clamp(x, 0.0, 1.0) * 255.0)); }

int wrap(int i, int n) {
  const int r = i % n;
  return r < 0 ? r + n : r;
}

// A coordinate in [0, 1] for `wrap` (repeat's in [0, 1), mirrored's folded at each whole
// number), and the texel index a bilinear tap i stands for on an axis of n texels.
double wrapped_coordinate(double x, TextureWrap mode) {
  switch (mode) {
    case TextureWrap::repeat:
      return x - std::floor(x);
    case TextureWrap::clamp_to_edge:
      return std::clamp(x, 0.0, 1.0);
    case TextureWrap::mirrored_repeat: {
      const double period = x - 2 * std::floor(x / 2);  // in [0, 2)
      return period <= 1 ? period : 2 - period;
    }
  }
  return 0;
}

int wrapped_index(int i, int n, TextureWrap mode) {
  // Mirrored coordinates lie in [0, 1]: at the fold the neighbour is the edge texel
  // itself, as clamping gives.
  return mode == TextureWrap::repeat ? wrap(i, n) : std::clamp(i, 0, n - 1);
}

}  // namespace

Texture::Texture(int width, int height, std::vector<uint8_t> rgba, TextureEncoding encoding) : encoding_(encoding) {
  if (width <= 0 || height <= 0 || rgba.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * 4)
    throw std::invalid_argument("Texture: the texels do not match the size");
  levels_.push_back({width, height, std::move(rgba)});
  // Each level halves the one above (odd sizes round up), averaging 2 × 2 texels in
  // linear units: a box filter, which keeps the mean.
  while (levels_.back().width > 1 || levels_.back().height > 1) {
    const int level = levels() - 1;
    const Level& above = levels_.back();
    Level next{std::max(1, (above.width + 1) / 2), std::max(1, (above.height + 1) / 2), {}};
    next.rgba.resize(static_cast<size_t>(next.width) * next.height * 4);
    for (int y = 0; y < next.height; ++y)
      for (int x = 0; x < next.width; ++x) {
        Rgba sum{};
        int n = 0;
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) {
            const int sx = 2 * x + dx, sy = 2 * y + dy;
            if (sx >= above.width || sy >= above.height) continue;
            const Rgba t = texel(level, sx, sy);
            for (size_t c = 0; c < 4; ++c) sum[c] += t[c];
            ++n;
          }
        uint8_t* out = &next.rgba[(static_cast<size_t>(y) * next.width + x) * 4];
        for (size_t c = 0; c < 4; ++c) {
          const double mean = sum[c] / n;
          out[c] = to_byte(c < 3 && encoding_ == TextureEncoding::srgb ? srgb_encode(mean) : mean);
        }
      }
    levels_.push_back(std::move(next));
  }
}

Texture Texture::with_wrap(TextureWrap u, TextureWrap v) const {
  Texture out = *this;
  out.wrap_u_ = u;
  out.wrap_v_ = v;
  return out;
}

size_t Texture::bytes() const {
  size_t total = 0;
  for (const Level& l : levels_) total += l.rgba.size();
  return total;
}

Rgba Texture::texel(int level, int x, int y) const {
  const Level& l = levels_[static_cast<size_t>(level)];
  const uint8_t* p = &l.rgba[(static_cast<size_t>(y) * l.width + x) * 4];
  const auto& decode = srgb_to_linear_table();
  if (encoding_ == TextureEncoding::srgb) return {decode[p[0]], decode[p[1]], decode[p[2]], p[3] / 255.0f};
  return {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f, p[3] / 255.0f};
}

Rgba Texture::bilinear(int level, double u, double v) const {
  const Level& l = levels_[static_cast<size_t>(level)];
  if (!std::isfinite(u) || !std::isfinite(v)) u = v = 0;
  // Texel centres at (i + ½) / size; the repeat is applied per texel index.
  const double fx = wrapped_coordinate(u, wrap_u_) * l.width - 0.5,
               fy = wrapped_coordinate(v, wrap_v_) * l.height - 0.5;
  const double x0 = std::floor(fx), y0 = std::floor(fy);
  const float tx = static_cast<float>(fx - x0), ty = static_cast<float>(fy - y0);
  const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
  Rgba out{};
  for (int dy = 0; dy <= 1; ++dy)
    for (int dx = 0; dx <= 1; ++dx) {
      const float w = (dx ? tx : 1 - tx) * (dy ? ty : 1 - ty);
      const Rgba t = texel(level, wrapped_index(ix + dx, l.width, wrap_u_), wrapped_index(iy + dy, l.height, wrap_v_));
      for (size_t c = 0; c < 4; ++c) out[c] += w * t[c];
    }
  return out;
}

Rgba Texture::trilinear(double u, double v, double level) const {
  const double top = levels() - 1;
  level = std::clamp(level, 0.0, top);
  const int lo = static_cast<int>(level);
  const float t = static_cast<float>(level - lo);
  const Rgba a = bilinear(lo, u, v);
  if (t == 0.0f || lo + 1 > top) return a;
  const Rgba b = bilinear(lo + 1, u, v);
  Rgba out{};
  for (size_t c = 0; c < 4; ++c) out[c] = (1 - t) * a[c] + t * b[c];
  return out;
}

Rgba Texture::filtered(double u, double v, double du_a, double dv_a, double du_b, double dv_b) const {
  // Axes in texels of the finest level.
  const double w = width(), h = height();
  double ax = du_a * w, ay = dv_a * h, bx = du_b * w, by = dv_b * h;
  if (!std::isfinite(ax + ay + bx + by)) return mean();
  double a_len = std::hypot(ax, ay), b_len = std::hypot(bx, by);
  if (a_len < b_len) {
    std::swap(ax, bx), std::swap(ay, by);
    std::swap(a_len, b_len);
  }
  // The major axis a: how many look-ups along it, and the width each one covers.
  const int taps = b_len > 0 ? std::clamp(static_cast<int>(std::ceil(a_len / b_len)), 1, kMaxAnisotropy)
                             : (a_len > 0 ? kMaxAnisotropy : 1);
  const double width_texels = std::max(b_len, a_len / taps);
  const double level = width_texels > 1 ? std::log2(width_texels) : 0.0;
  if (taps == 1) return trilinear(u, v, level);
  Rgba sum{};
  for (int i = 0; i < taps; ++i) {
    const double s = (i + 0.5) / taps - 0.5;  // evenly across the footprint
    const Rgba t = trilinear(u + s * ax / w, v + s * ay / h, level);
    for (size_t c = 0; c < 4; ++c) sum[c] += t[c];
  }
  for (float& c : sum) c /= static_cast<float>(taps);
  return sum;
}

}  // namespace skylit
