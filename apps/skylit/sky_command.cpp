// `skylit sky`: the sky alone, as an equirectangular or fisheye image in absolute units.
#include <memory>
#include <string>

#include "atmosphere_options.h"
#include "commands.h"
#include "skylit/atmosphere/seen_sun.h"
#include "skylit/io/image/image.h"
#include "skylit/io/image/tone_map.h"
#include "skylit/render/sky_image.h"

namespace skylit::cli {

namespace {

struct SkyArguments {
  AtmosphereOptions atmosphere;
  std::string projection = "equirect";
  int size = 256;
  std::string output;
};

// The pixels that show the sky: the automatic exposure must not count the black
// corners around a fisheye's circle.
XyzImage sky_pixels(const XyzImage& image, SkyProjection projection) {
  if (projection == SkyProjection::equirect) return image;
  std::vector<float> inside;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (sky_projection_direction(projection, image.height, x + 0.5, y + 0.5)) {
        const Xyz c = image.at(x, y);
        inside.insert(inside.end(), {static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z)});
      }
  XyzImage out(static_cast<int>(inside.size() / 3), 1);
  out.xyz.assign(inside.begin(), inside.end());
  return out;
}

int run_sky(const SkyArguments& args) {
  image_format_from_path(args.output);  // a bad extension fails before the work
  const Atmosphere atmosphere(atmosphere_settings(args.atmosphere));
  // The altitude is the sun as seen, as for `spectrum` and a scene's sun; the sky model
  // takes the true one (until 2026-12-07 it was given this one: the sky at a sun 0.5° up
  // rendered as for one 0.5° higher, its zenith 23 % brighter than `spectrum` said).
  const Vec3 seen_to_sun =
      direction_from_altitude_azimuth(args.atmosphere.sun_altitude_deg, args.atmosphere.sun_azimuth_deg);
  const SkyModel sky(atmosphere, SunRefraction(atmosphere).true_direction(seen_to_sun),
                     args.atmosphere.observer_altitude_m);
  const SkyProjection projection = args.projection == "fisheye" ? SkyProjection::fisheye : SkyProjection::equirect;
  const XyzImage image = render_sky(sky, projection, args.size);
  write_image(image, args.output, {automatic_exposure_ev(sky_pixels(image, projection))});
  return 0;
}

}  // namespace

CommandRunner add_sky_command(CLI::App& app) {
  auto args = std::make_shared<SkyArguments>();
  CLI::App* sky =
      app.add_subcommand("sky", "Render the sky alone in absolute units (luminance in cd/m², as for render).");
  add_atmosphere_options(sky, args->atmosphere);
  sky->add_option("--projection", args->projection,
                  "equirect: 2N×N, azimuth 0° (north) at the left edge, clockwise, altitude +90° at the top to −90° "
                  "at the bottom; fisheye: N×N looking up, zenith at the centre, north at the top, east on the left")
      ->check(CLI::IsMember({"fisheye", "equirect"}));
  sky->add_option("--size", args->size, "N in pixels (default 256)")->check(CLI::Range(8, 8192));
  sky->add_option("-o,--output", args->output, "Image (.png, .exr, .pfm or .hdr)")->required();
  return [sky, args] { return sky->parsed() ? run_sky(*args) : -1; };
}

}  // namespace skylit::cli
