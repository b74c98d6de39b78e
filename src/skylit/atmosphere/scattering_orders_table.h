// Multiple scattering by iterated scattering orders (Bruneton & Neyret 2008; Bruneton
// 2017), computed on the CPU for every wavelength bin.
//
// In a spherically symmetric atmosphere lit by one distant sun the radiance field
// depends on four numbers: the radius r of a point, the cosine μ_s of the sun's zenith
// angle there, and the direction's zenith cosine μ and azimuth φ from the sun's
// vertical (mirror-symmetric, so φ ∈ [0, π]). The table holds, on a grid of points
// (r, μ_s) and directions (μ, φ), the light of all orders ≥ 1 scattered at the point
// into each direction, per unit scattering coefficient: S_R = ∫ P_R L dω and
// S_A = ∫ P_A L dω (Rayleigh and aerosol phase functions). A point with scattering
// coefficients σ_R, σ_A then sends σ_R·S_R + σ_A·S_A (the multiply scattered source)
// along the view ray, which ScatteringIntegrator integrates with single scattering.
//
// Each order n: radiance L_n at every grid point and direction by integrating
// σ·S_{n−1} along the ray (and the ground's Lambertian reflection of the order n − 1
// irradiance where it ends there), then S_n = ∫ P L_n dω by a fixed quadrature over the
// grid's directions (taken by azimuthal modes: direction_grid_phase_quadrature.h).
// L_1 is single scattering plus the sunlit ground, computed along the ray exactly as
// for the sky. Orders past the last computed one are added as the geometric series of
// the last two (measured ratios < 0.6: docs/atmosphere.md).
#pragma once

#include <array>
#include <vector>

#include "skylit/atmosphere/transmittance_table.h"
#include "skylit/core/huge_pages.h"
#include "skylit/spectrum/spectrum.h"

namespace skylit {

struct AerosolSettings;

class ScatteringOrdersTable {
 public:
  // Grid: altitude ∝ x³ (dense near the ground, where the aerosols are), μ_s crowded
  // toward the horizon (the terminator), directions in bands of μ about twice as fine as
  // equal bands at the horizon and the poles (below the sun at −8° equal bands left
  // views low in the sky up to 13 % too dark: the .cpp) and equal bands of φ. 48 sun
  // cosines rather than 32: across the terminator the light changes by orders of
  // magnitude between rows, and 32 left the sky at −2° to −4° up to 4–8 % too dark
  // against the Monte Carlo reference; 64 gain about a point more at −4° and −5°, at a
  // third more build time (docs/atmosphere.md).
  static constexpr int kAltitudeSize = 12, kMuSunSize = 48, kMuSize = 16, kAzimuthSize = 8;
  static constexpr int kSegments = 16;  // along each ray, crowded where it is lowest
  // Orders computed; the rest by the geometric tail of the last two. Three rather than
  // four pay for the finer sun cosines: by day the skies move by at most 0.2 points at
  // 30° and 60° and 0.5 at 0°, with the rows (docs/atmosphere.md).
  static constexpr int kOrders = 3;
  // Multiply scattered light is smooth in wavelength: it is computed in 8 of the 40
  // bins, spread evenly (50–60 nm apart), and interpolated linearly between them: S per
  // unit solar irradiance is far flatter than λ^−4, and against all 40 bins computed the
  // sky's zenith radiance and diffuse irradiance move by at most 0.2 % at 5°, 0.5 % at
  // −3° and 0.9 % at −6° (near 495 nm; measured 2026-12-05).
  static constexpr int kBins = 8;
  using Bins = std::array<float, kBins>;

  ScatteringOrdersTable(const AtmosphereMedium& medium, const TransmittanceTable& transmittance,
                        const AerosolSettings& aerosol, double ground_albedo);

  // ∫ P L dω for both phase functions (sr⁻¹ per unit solar irradiance, per unit σ) at
  // radius r, direction μ, sun μ_s, ν = cos(direction, sun).
  struct Source {
    Spectrum rayleigh, aerosol;
  };
  Source at(double r, double mu, double mu_sun, double nu) const;

  // One entry of the table: log S_R and log S_A in the table's bins.
  struct alignas(64) LogSource {  // one cache line: a look-up's corners touch one each
    Bins rayleigh, aerosol;
  };

 private:
  struct Grid;
  double ground_radius_, top_radius_;
  // log S (floored) per [point][direction]: S falls by orders of magnitude across the
  // terminator, and interpolating its logarithm follows that fall where interpolating
  // S overshot it (docs/atmosphere.md, Twilight). Both phase functions' values side by
  // side, so that a look-up's 16 corners touch 16 cache lines rather than 32.
  HugePageVector<LogSource> log_source_;
};

}  // namespace skylit
