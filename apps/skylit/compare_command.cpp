// `skylit compare A B`: how much brighter or darker render B is than render A, region by
// region, in absolute luminance, with standard errors from the path integrator's
// standard-error images: the table on stdout, optionally JSON and a false-colour ratio
// map (docs/validation.md). Every input is read and checked, and every output's folder
// too, before anything is written, so a mistake leaves no file behind.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "commands.h"
#include "skylit/compare/comparison_report.h"
#include "skylit/compare/region_comparison.h"
#include "skylit/core/error.h"
#include "skylit/figures/figure_file.h"
#include "skylit/figures/ratio_map.h"
#include "skylit/io/atomic_file.h"
#include "skylit/io/image/image_reader.h"
#include "skylit/io/regions/regions_reader.h"

namespace skylit::cli {

namespace {

struct CompareArguments {
  std::string a, b;
  std::optional<std::string> mask, regions_file, standard_error_a, standard_error_b, ratio_map, json;
};

std::string size_text(const XyzImage& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

void require_same_size(const XyzImage& image, const std::string& file, const XyzImage& a, const std::string& a_file) {
  if (image.width != a.width || image.height != a.height)
    throw InputError(file + " is " + size_text(image) + " pixels but " + a_file + " is " + size_text(a) +
                     "; images to compare must be the same size");
}

std::optional<XyzImage> read_optional(const std::optional<std::string>& file, const XyzImage& a,
                                      const std::string& a_file) {
  if (!file) return std::nullopt;
  XyzImage image = read_image(*file);
  require_same_size(image, *file, a, a_file);
  return image;
}

// The regions file's, then the mask's; without either, the whole image.
std::vector<ImageRegion> regions_of(const CompareArguments& args, int width, int height) {
  std::vector<ImageRegion> regions;
  if (args.regions_file) regions = read_regions_file(*args.regions_file, width, height);
  if (args.mask) {
    std::set<std::string> names;
    for (const ImageRegion& r : regions) names.insert(r.name);
    for (ImageRegion& r : read_region_mask(*args.mask, width, height)) {
      if (names.contains(r.name))
        throw InputError(*args.regions_file + ": the region name \"" + r.name + "\" is also a colour of the mask " +
                         *args.mask + "; rename it");
      regions.push_back(std::move(r));
    }
  }
  if (regions.empty()) regions.push_back(whole_image_region(width, height));
  return regions;
}

void write_text_file(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  file.commit(std::span(reinterpret_cast<const uint8_t*>(text.data()), text.size()));
}

int run_compare(const CompareArguments& args) {
  if (args.ratio_map) {
    figure_extension(*args.ratio_map, {".png"}, "a ratio map");
    check_output_folder(*args.ratio_map);
  }
  if (args.json) check_output_folder(*args.json);
  std::vector<std::string> inputs = {args.a, args.b};
  for (const auto* input : {&args.standard_error_a, &args.standard_error_b, &args.regions_file, &args.mask})
    if (*input) inputs.push_back(**input);
  for (const auto* output : {&args.ratio_map, &args.json})
    if (*output)
      for (const std::string& input : inputs) check_not_an_input(**output, input);

  const XyzImage a = read_image(args.a);
  const XyzImage b = read_image(args.b);
  require_same_size(b, args.b, a, args.a);
  const std::optional<XyzImage> se_a = read_optional(args.standard_error_a, a, args.a);
  const std::optional<XyzImage> se_b = read_optional(args.standard_error_b, a, args.a);
  const std::vector<ImageRegion> regions = regions_of(args, a.width, a.height);

  const StandardErrorImages standard_errors{se_a ? &*se_a : nullptr, se_b ? &*se_b : nullptr};
  std::vector<RegionComparison> results;
  for (const ImageRegion& region : regions) results.push_back(compare_region(region, a, b, standard_errors));

  const ComparedFiles files{args.a, args.b, args.standard_error_a, args.standard_error_b, a.width, a.height};
  if (args.ratio_map) write_ratio_map(a, b, *args.ratio_map);
  if (args.json) write_text_file(*args.json, comparison_json(files, results));
  std::fputs(comparison_table(files, results).c_str(), stdout);
  return 0;
}

}  // namespace

CommandRunner add_compare_command(CLI::App& app) {
  auto args = std::make_shared<CompareArguments>();
  CLI::App* compare = app.add_subcommand(
      "compare",
      "Compare two renders of one view (e.g. the bands integrator against the path-traced reference) in absolute "
      "luminance: per region, the mean luminance of A and B (cd/m²), the ratio mean(B)/mean(A) with its standard "
      "error, and the per-pixel ratio's median, 5th and 95th percentiles (docs/validation.md).");
  compare->add_option("a", args->a, "Image A, the denominator of B/A (.exr or .pfm, as skylit writes them)")
      ->required();
  compare->add_option("b", args->b, "Image B, the same size (.exr or .pfm); ratios are B/A")->required();
  compare->add_option(
      "--regions", args->regions_file,
      "JSON file of named rectangles: {\"regions\": [{\"name\": \"wall\", \"rect\": [x0, y0, x1, y1]}]} "
      "in pixels (half-open), or \"rect_fraction\" in fractions of width and height");
  compare->add_option("--mask", args->mask,
                      "PNG the images' size: each distinct non-black colour is a region named by its hex colour");
  compare->add_option(
      "--standard-error-a", args->standard_error_a,
      "Per-pixel standard error of A's luminance (skylit render --standard-error); omitted: A has no noise");
  compare->add_option("--standard-error-b", args->standard_error_b,
                      "Per-pixel standard error of B's luminance; omitted: B has no noise");
  compare->add_option(
      "-o,--output", args->ratio_map,
      "Write a false-colour map of B/A per pixel (.png; log scale from 1/2 blue to 2 red, with a legend)");
  compare->add_option("--json", args->json, "Also write the results as JSON to this file");
  return [compare, args] { return compare->parsed() ? run_compare(*args) : -1; };
}

}  // namespace skylit::cli
