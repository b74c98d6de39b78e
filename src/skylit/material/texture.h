// Image textures on model surfaces (base colour, emission, masks): 8-bit RGBA texels
// with a mip-map pyramid, read with a filter as wide as the pixel's footprint on the
// surface, so that a facade or a paved ground far away shows its mean colour instead
// of aliasing into moiré.
//
// Filtering: the footprint is an ellipse in texture space given by two axis vectors
// (from the camera's pixel, PreparedScene::surface_point). Up to kMaxAnisotropy
// trilinear look-ups are spread along the longer axis, each at the mip level whose
// texels match the longer axis divided by the number of look-ups (or the shorter axis,
// whichever is larger), the scheme GPUs use for anisotropic filtering: sharp across a
// grazing surface, blurred only along its foreshortened direction. Box-filtered mip
// levels keep the texture's mean, so far surfaces keep their mean colour.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace skylit {

using Rgba = std::array<float, 4>;  // linear (colour textures decoded from sRGB)

// How a texture's colour channels are stored: colours in sRGB (base colour, emission,
// as glTF and image files have them), data linearly (roughness, normals).
enum class TextureEncoding { srgb, linear };

// What lies outside [0, 1) along one texture axis (glTF's sampler wrapS and wrapT; MTL's
// -clamp): the image repeated, its edge texels stretched on, or the image mirrored at
// each whole coordinate.
enum class TextureWrap { repeat, clamp_to_edge, mirrored_repeat };

class Texture {
 public:
  static constexpr int kMaxAnisotropy = 8;

  // rgba: width × height texels, 4 bytes each, row by row from the top. Throws
  // std::invalid_argument when the sizes do not match or are not positive.
  Texture(int width, int height, std::vector<uint8_t> rgba, TextureEncoding encoding);

  int width() const { return levels_[0].width; }
  int height() const { return levels_[0].height; }
  int levels() const { return static_cast<int>(levels_.size()); }
  // Bytes held by all levels (for the memory statistics).
  size_t bytes() const;

  // The texel (x, y) of a level, decoded.
  Rgba texel(int level, int x, int y) const;
  // The mean over the whole texture (its last, 1 × 1 level).
  Rgba mean() const { return texel(levels() - 1, 0, 0); }

  // The same texels read with other wraps (a copy; the same image may be read through
  // several glTF samplers).
  Texture with_wrap(TextureWrap u, TextureWrap v) const;
  TextureWrap wrap_u() const { return wrap_u_; }
  TextureWrap wrap_v() const { return wrap_v_; }

  // Bilinear at (u, v) on one level; u, v in [0, 1) across the image (u to the right, v
  // down from the top row), wrapped outside as wrap_u and wrap_v say (repeated unless
  // set otherwise).
  Rgba bilinear(int level, double u, double v) const;
  // Filtered over the footprint whose axes are (du_a, dv_a) and (du_b, dv_b) in uv
  // units, centred on (u, v). A zero footprint is a bilinear look-up on the finest level.
  Rgba filtered(double u, double v, double du_a, double dv_a, double du_b, double dv_b) const;

 private:
  struct Level {
    int width, height;
    std::vector<uint8_t> rgba;
  };
  Rgba trilinear(double u, double v, double level) const;

  std::vector<Level> levels_;
  TextureEncoding encoding_;
  TextureWrap wrap_u_ = TextureWrap::repeat, wrap_v_ = TextureWrap::repeat;
};

}  // namespace skylit
