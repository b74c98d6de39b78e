// render_statistics and its JSON and CSV forms (render_statistics.h).
#include "skylit/assess/render_statistics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "skylit/core/error.h"

namespace skylit {
namespace {

LuminanceSummary summarise(std::vector<double> values) {
  LuminanceSummary s;
  s.pixels = values.size();
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  auto rank = [&](double q) { return values[std::size_t(std::lround(q * double(values.size() - 1)))]; };
  double sum = 0;
  for (double v : values) sum += v;
  s.mean = sum / double(values.size());
  s.min = values.front();
  s.max = values.back();
  s.p5 = rank(0.05);
  s.p50 = rank(0.5);
  s.p95 = rank(0.95);
  return s;
}

bool is_wide_fisheye(const Camera& c) {
  const bool fisheye = c.projection == Projection::fisheye_equidistant ||
                       c.projection == Projection::fisheye_equisolid ||
                       c.projection == Projection::fisheye_hemispherical;
  return fisheye && c.vertical_fov_deg >= 180 - 1e-9;
}

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", std::isfinite(v) ? v : 0.0);
  return buffer;
}

// A JSON string literal (quotes, backslashes and control characters escaped).
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
      out += buffer;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string summary_json(const LuminanceSummary& s) {
  return "{\"pixels\": " + std::to_string(s.pixels) + ", \"mean\": " + number(s.mean) + ", \"min\": " + number(s.min) +
         ", \"max\": " + number(s.max) + ", \"p5\": " + number(s.p5) + ", \"p50\": " + number(s.p50) +
         ", \"p95\": " + number(s.p95) + "}";
}

std::string named_list_json(const std::vector<NamedSummary>& list) {
  std::string out = "[";
  for (std::size_t i = 0; i < list.size(); ++i) {
    out += std::string(i ? ",\n    " : "\n    ") + "{\"name\": " + quoted(list[i].name) +
           ", \"luminance_cd_m2\": " + summary_json(list[i].luminance);
    if (list[i].illuminance_lx) out += ", \"illuminance_lx\": " + summary_json(*list[i].illuminance_lx);
    out += "}";
  }
  return out + (list.empty() ? "]" : "\n  ]");
}

std::string summary_fields(const LuminanceSummary& s) {
  return number(s.mean) + "," + number(s.min) + "," + number(s.max) + "," + number(s.p5) + "," + number(s.p50) + "," +
         number(s.p95);
}

// The illuminance columns are empty where there is none (the sky, or not computed).
std::string summary_csv(const std::string& kind, const std::string& name, const LuminanceSummary& s,
                        const std::optional<LuminanceSummary>& lux = std::nullopt) {
  return kind + "," + csv_field(name) + "," + std::to_string(s.pixels) + "," + summary_fields(s) + "," +
         (lux ? std::to_string(lux->pixels) + "," + summary_fields(*lux) : std::string(",,,,,,")) + "\n";
}

}  // namespace

RenderStatistics render_statistics(const XyzImage& image, const PixelLayers& layers, const Scene& scene) {
  RenderStatistics stats;
  std::vector<std::vector<double>> by_object(scene.objects.size()), by_material(scene.materials.size());
  std::vector<double> sky;
  // Illuminance per object and material, where the layers carry it (the sky has none).
  const bool has_lux = !layers.illuminance_lx.empty();
  std::vector<std::vector<double>> lux_by_object(scene.objects.size()), lux_by_material(scene.materials.size());
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
      const double l = image.xyz[3 * i + 1];
      if (!std::isfinite(l)) continue;
      const int32_t object = layers.object[i];
      if (object == PixelLayers::kNotSeen) continue;
      if (object == PixelLayers::kNoObject) {
        sky.push_back(l);
        continue;
      }
      by_object[object].push_back(l);
      by_material[scene.objects[object].material_index].push_back(l);
      if (has_lux) {
        lux_by_object[object].push_back(layers.illuminance_lx[i]);
        lux_by_material[scene.objects[object].material_index].push_back(layers.illuminance_lx[i]);
      }
    }
  auto lux_summary = [&](const std::vector<double>& values) {
    return has_lux ? std::optional(summarise(values)) : std::nullopt;
  };
  for (std::size_t o = 0; o < by_object.size(); ++o)
    if (!by_object[o].empty())
      stats.objects.push_back({scene.objects[o].name, summarise(by_object[o]), lux_summary(lux_by_object[o])});
  for (std::size_t m = 0; m < by_material.size(); ++m)
    if (!by_material[m].empty())
      stats.materials.push_back({scene.materials[m].name, summarise(by_material[m]), lux_summary(lux_by_material[m])});
  stats.sky = summarise(sky);
  for (const Probe& p : scene.probes) {
    if (p.x1 > image.width || p.y1 > image.height)
      throw InputError("probe \"" + p.name + "\" reaches outside the " + std::to_string(image.width) + "x" +
                       std::to_string(image.height) + " image");
    std::vector<double> values, lux;
    for (int y = p.y0; y < p.y1; ++y)
      for (int x = p.x0; x < p.x1; ++x) {
        if (const double l = image.at(x, y).y; std::isfinite(l)) values.push_back(l);
        const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
        if (has_lux && layers.object[i] >= 0) lux.push_back(layers.illuminance_lx[i]);
      }
    stats.probes.push_back({p.name, summarise(values), lux_summary(lux)});
  }
  if (is_wide_fisheye(scene.camera))
    stats.glare = daylight_glare_probability(image, ImageCamera(scene.camera, image.width, image.height));
  return stats;
}

std::string statistics_json(const RenderStatistics& stats) {
  std::string out = "{\n  \"objects\": " + named_list_json(stats.objects) +
                    ",\n  \"materials\": " + named_list_json(stats.materials) +
                    ",\n  \"sky\": {\"luminance_cd_m2\": " + summary_json(stats.sky) +
                    "},\n  \"probes\": " + named_list_json(stats.probes);
  if (stats.glare) {
    const GlareResult& g = *stats.glare;
    out += ",\n  \"glare\": {\"dgp\": " + number(g.dgp) +
           ", \"vertical_illuminance_lx\": " + number(g.vertical_illuminance_lx) +
           ", \"mean_luminance_cd_m2\": " + number(g.mean_luminance) +
           ", \"source_solid_angle_sr\": " + number(g.source_solid_angle_sr) +
           ", \"source_mean_luminance_cd_m2\": " + number(g.source_mean_luminance) + "}";
  }
  return out + "\n}\n";
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string statistics_csv(const RenderStatistics& stats) {
  std::string out =
      "kind,name,pixels,mean_cd_m2,min_cd_m2,max_cd_m2,p5_cd_m2,p50_cd_m2,p95_cd_m2,"
      "lx_pixels,mean_lx,min_lx,max_lx,p5_lx,p50_lx,p95_lx\n";
  for (const NamedSummary& s : stats.objects) out += summary_csv("object", s.name, s.luminance, s.illuminance_lx);
  for (const NamedSummary& s : stats.materials) out += summary_csv("material", s.name, s.luminance, s.illuminance_lx);
  out += summary_csv("sky", "sky", stats.sky);
  for (const NamedSummary& s : stats.probes) out += summary_csv("probe", s.name, s.luminance, s.illuminance_lx);
  if (stats.glare) {
    // Single values in the mean column.
    out += "glare,dgp,," + number(stats.glare->dgp) + ",,,,,,,,,,,,\n";
    out += "glare,vertical_illuminance_lx,," + number(stats.glare->vertical_illuminance_lx) + ",,,,,,,,,,,,\n";
  }
  return out;
}

}  // namespace skylit
