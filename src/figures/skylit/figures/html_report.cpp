// html_report (html_report.h). The page needs nothing outside itself: no network, no
// files beside it, so it can be mailed or archived as one file.
#include "skylit/figures/html_report.h"

#include <cstdio>

#include "skylit/core/base64.h"
#include "skylit/figures/report_luminance.h"
#include "skylit/figures/utf8.h"

namespace skylit {

namespace {

// Markup text: escaped, malformed UTF-8 replaced (names come from users' files).
std::string escaped(const std::string& text) { return xml_text(text); }

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

constexpr const char* kStyle = R"(<style>
body { font-family: sans-serif; margin: 1.5em; color: #222; }
table { border-collapse: collapse; margin-bottom: 1.5em; }
th, td { border: 1px solid #bbb; padding: 0.2em 0.6em; text-align: left; }
td.n { text-align: right; font-variant-numeric: tabular-nums; }
figure { display: inline-block; margin: 0 1em 1em 0; vertical-align: top; }
figure img { max-width: 100%; image-rendering: pixelated; cursor: crosshair; }
#readout { position: sticky; top: 0; background: #fff; padding: 0.3em 0; font-family: monospace; }
</style>
)";

// The read-out: pixel (x, y) of the render is pixel (x, y) of every image's raster
// (a false-colour image's legend lies to the right, outside the render's width).
constexpr const char* kScript = R"(
const layers = report.layers.map(layer => {
  const bytes = Uint8Array.from(atob(layer.codes), c => c.charCodeAt(0));
  return { ...layer, view: new DataView(bytes.buffer) };
});
function decoded(layer, x, y) {
  const code = layer.view.getUint16(2 * (y * report.width + x), true);
  return code === 0 ? 0 : Math.pow(10, report.lowLog10 + (code - 1) * report.stepLog10);
}
const readout = document.getElementById('readout');
for (const img of document.querySelectorAll('img.reads')) {
  img.addEventListener('mousemove', event => {
    const box = img.getBoundingClientRect();
    const x = Math.floor((event.clientX - box.left) * img.naturalWidth / box.width);
    const y = Math.floor((event.clientY - box.top) * img.naturalHeight / box.height);
    if (x < 0 || y < 0 || x >= report.width || y >= report.height) return;
    const parts = layers.map(layer => {
      const value = decoded(layer, x, y);
      readout.dataset[layer.quantity] = value;
      const shown = value === 0 ? 'below ' + Math.pow(10, report.lowLog10) : value.toPrecision(4);
      return layer.quantity + ' ' + shown + ' ' + layer.unit;
    });
    readout.dataset.x = x;
    readout.dataset.y = y;
    readout.textContent = 'pixel (' + x + ', ' + y + '): ' + parts.join(', ');
  });
}
)";

std::string summary_cells(const LuminanceSummary& s) {
  std::string row = "<td class=\"n\">" + std::to_string(s.pixels) + "</td>";
  for (const double v : {s.mean, s.min, s.max, s.p5, s.p50, s.p95}) row += "<td class=\"n\">" + number(v) + "</td>";
  return row;
}

// Luminance, and the illuminance beside it where the statistics hold it.
std::string statistics_table(const std::string& heading, const std::vector<NamedSummary>& rows) {
  if (rows.empty()) return "";
  const bool lux = rows.front().illuminance_lx.has_value();
  const std::string columns =
      "<th>pixels</th><th>mean</th><th>min</th><th>max</th><th>5 %</th><th>50 %</th><th>95 %</th>";
  std::string html = "<h3>" + escaped(heading) + "</h3>\n<table><tr><th></th><th colspan=\"7\">luminance, cd/m²</th>" +
                     (lux ? "<th colspan=\"7\">illuminance, lx</th>" : "") + "</tr>\n<tr><th>name</th>" + columns +
                     (lux ? columns : "") + "</tr>\n";
  for (const NamedSummary& r : rows) {
    html += "<tr><td>" + escaped(r.name) + "</td>" + summary_cells(r.luminance);
    if (r.illuminance_lx) html += summary_cells(*r.illuminance_lx);
    html += "</tr>\n";
  }
  return html + "</table>\n";
}

std::string statistics_section(const RenderStatistics& stats) {
  std::string html =
      "<h2>Statistics</h2>\n<p>Over the pixels whose centre sees each thing (percentiles by the "
      "nearest rank); the illuminance is on the surface seen, on its side facing the camera.</p>\n";
  html += statistics_table("Objects", stats.objects);
  html += statistics_table("Materials", stats.materials);
  html += statistics_table("Sky", {{"sky", stats.sky, std::nullopt}});
  html += statistics_table("Probes", stats.probes);
  if (stats.glare) {
    const GlareResult& g = *stats.glare;
    html += "<h3>Glare</h3>\n<table>";
    html += "<tr><td>daylight glare probability (DGP)</td><td class=\"n\">" + number(g.dgp) + "</td></tr>";
    html += "<tr><td>vertical illuminance at the eye</td><td class=\"n\">" + number(g.vertical_illuminance_lx) +
            " lx</td></tr>";
    html += "</table>\n";
  }
  return html;
}

}  // namespace

std::string html_report(const ReportPage& page) {
  std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
                     escaped(page.title) + "</title>\n" + kStyle + "</head>\n<body>\n<h1>" + escaped(page.title) +
                     "</h1>\n";
  html += "<h2>Conditions</h2>\n<table>\n";
  for (const ConditionRow& row : page.conditions)
    html += "<tr><th>" + escaped(row.subject) + "</th><td>" + escaped(row.description) + "</td></tr>\n";
  html += "</table>\n<h2>Images</h2>\n<p id=\"readout\">Move the mouse over an image to read its pixels.</p>\n";
  for (const ReportImage& image : page.images)
    html += "<figure><img class=\"reads\" alt=\"" + escaped(image.caption) + "\" src=\"data:image/png;base64," +
            base64_encode(image.png) + "\"><figcaption>" + escaped(image.caption) + "</figcaption></figure>\n";
  char precision[64];
  std::snprintf(precision, sizeof precision, "%.2g %%", 100 * LuminanceCodeScale::kRelativePrecision);
  html += "<p>The read-out decodes values stored in the page to within " + std::string(precision) +
          " and shows four significant digits.</p>\n";
  html += statistics_section(page.statistics);
  html += "<script>\nconst report = {width: " + std::to_string(page.width) +
          ", height: " + std::to_string(page.height) + ", lowLog10: " + number(LuminanceCodeScale::kLowLog10) +
          ", stepLog10: (" + number(LuminanceCodeScale::kHighLog10) + " - " + number(LuminanceCodeScale::kLowLog10) +
          ") / 65534, layers: [\n";
  for (const ReportLayer& layer : page.layers)
    html += "{quantity: \"" + escaped(layer.quantity) + "\", unit: \"" + escaped(layer.unit) + "\", codes: \"" +
            base64_encode(layer.codes) + "\"},\n";
  html += "]};\n" + std::string(kScript) + "</script>\n</body>\n</html>\n";
  return html;
}

}  // namespace skylit
