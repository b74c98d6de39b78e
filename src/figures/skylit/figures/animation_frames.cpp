// Labels, the labels' CSV and the HTML viewer of a sun study (animation_frames.h).
#include "skylit/figures/animation_frames.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "skylit/figures/utf8.h"
#include "skylit/sun/time_steps.h"

namespace skylit {

namespace {

// A JSON string literal, safe inside a <script> element ("</" cannot close it).
std::string script_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\')
      out += std::string("\\") + c;
    else if (c == '<')
      out += "\\u003c";
    else if (static_cast<unsigned char>(c) < 0x20)
      out += ' ';
    else
      out += c;
  }
  return out + "\"";
}

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

}  // namespace

std::string frame_label(const AnimationFrame& frame, std::size_t frame_count) {
  return std::to_string(frame.number) + "/" + std::to_string(frame_count) + "  " + format_date(frame.time) + " " +
         format_clock(frame.time) + format_offset(frame.time.utc_offset_minutes) + "  sun " +
         fixed(frame.sun_altitude_deg, 1) + "°";
}

Raster labelled_frame(const XyzImage& image, const DisplayOptions& display, const std::string& label) {
  Raster raster(image.width, image.height);
  blit_rgb8(raster, 0, 0, image.width, image.height, display_srgb8(image, display));
  // The font's scale grows with the image so that the label stays legible in a video.
  const int scale = std::max(1, image.height / 240);
  const int band = text_height(scale) + 2 * scale;
  const int top = image.height - band;
  for (int y = std::max(0, top); y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) blend_pixel(raster, x, y, kBlack, 0.6);
  draw_text(raster, 2 * scale, top + scale, label, kWhite, scale);
  return raster;
}

std::string frames_csv(const std::vector<AnimationFrame>& frames, const std::vector<std::string>& files,
                       double exposure_ev) {
  if (frames.size() != files.size()) throw std::invalid_argument("frames_csv: one file per frame");
  char exposure[40];
  std::snprintf(exposure, sizeof exposure, "%.17g", exposure_ev);
  std::string out = "frame,file,date,time,utc_offset,sun_altitude_deg,sun_azimuth_deg,exposure_ev\n";
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const AnimationFrame& f = frames[i];
    out += std::to_string(f.number) + "," + files[i] + "," + format_date(f.time) + "," + format_clock(f.time) + "," +
           format_offset(f.time.utc_offset_minutes) + "," + fixed(f.sun_altitude_deg, 3) + "," +
           fixed(f.sun_azimuth_deg, 3) + "," + exposure + "\n";
  }
  return out;
}

std::string base64(const std::vector<uint8_t>& bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    uint32_t group = uint32_t{bytes[i]} << 16;
    if (n > 1) group |= uint32_t{bytes[i + 1]} << 8;
    if (n > 2) group |= bytes[i + 2];
    out += kDigits[(group >> 18) & 63];
    out += kDigits[(group >> 12) & 63];
    out += n > 1 ? kDigits[(group >> 6) & 63] : '=';
    out += n > 2 ? kDigits[group & 63] : '=';
  }
  return out;
}

std::string frame_viewer_html(const std::string& title, const std::vector<std::string>& labels,
                              const std::vector<std::vector<uint8_t>>& pngs, double frames_per_second) {
  if (labels.size() != pngs.size() || pngs.empty())
    throw std::invalid_argument("frame_viewer_html: one label per frame, and at least one frame");
  std::string frames = "[\n";
  for (std::size_t i = 0; i < pngs.size(); ++i)
    frames += "{\"label\":" + script_string(labels[i]) + ",\"src\":\"data:image/png;base64," + base64(pngs[i]) + "\"}" +
              (i + 1 < pngs.size() ? ",\n" : "\n");
  frames += "]";
  const std::string last = std::to_string(pngs.size() - 1);
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + xml_text(title) +
         "</title>\n<style>\nbody{font-family:sans-serif;margin:1em;background:#222;color:#eee}\n"
         "img{max-width:100%;display:block}\n#controls{display:flex;gap:1em;align-items:center;margin:.5em 0}\n"
         "#slider{flex:1}\n</style>\n</head>\n<body>\n<h1>" +
         xml_text(title) +
         "</h1>\n<img id=\"frame\" alt=\"frame\">\n<div id=\"controls\">\n"
         "<button id=\"play\" type=\"button\">play</button>\n"
         "<input id=\"slider\" type=\"range\" min=\"0\" max=\"" +
         last +
         "\" value=\"0\" step=\"1\" aria-label=\"frame\">\n<span id=\"label\"></span>\n</div>\n<script>\n"
         "const frames = " +
         frames + ";\nconst interval_ms = " + fixed(1000.0 / frames_per_second, 1) + ";\n" +
         R"(const image = document.getElementById("frame");
const slider = document.getElementById("slider");
const label = document.getElementById("label");
const play = document.getElementById("play");
let timer = null;
function show(i) {
  slider.value = i;
  image.src = frames[i].src;
  label.textContent = frames[i].label;
}
slider.addEventListener("input", () => show(Number(slider.value)));
play.addEventListener("click", () => {
  if (timer !== null) { clearInterval(timer); timer = null; play.textContent = "play"; return; }
  play.textContent = "pause";
  timer = setInterval(() => show((Number(slider.value) + 1) % frames.length), interval_ms);
});
show(0);
</script>
</body>
</html>
)";
}

}  // namespace skylit
