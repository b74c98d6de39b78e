// The parts of a scene's `render` block that say how the result is shown and measured
// rather than how it is rendered: `false_colour`; and the top level's `probes`
// (docs/scene-format.md).
#include "skylit/io/scene/scene_parts.h"

namespace skylit {

FalseColourSettings read_false_colour(const JsonReader& j) {
  j.allow_only({"quantity", "scale", "max", "decades", "contours", "underlay"});
  FalseColourSettings f;
  if (auto q = j.optional("quantity"))
    f.quantity = q->one_of({"luminance", "illuminance"}) == "illuminance" ? FalseColourQuantity::illuminance
                                                                          : FalseColourQuantity::luminance;
  if (auto s = j.optional("scale"))
    f.scale = s->one_of({"log", "linear"}) == "log" ? FalseColourScale::log : FalseColourScale::linear;
  if (auto m = j.optional("max")) {
    // "auto" is the default, accepted explicitly so that --set can restore it.
    if (!(m->is_string() && m->string() == "auto")) f.max = m->number_in(1e-9, 1e12);
  }
  if (auto d = j.optional("decades")) f.decades = d->integer_in(1, 8);
  if (auto c = j.optional("contours")) f.contours = c->boolean();
  if (auto u = j.optional("underlay")) f.underlay = u->boolean();
  return f;
}

std::vector<Probe> read_probes(const JsonReader& j) {
  std::vector<Probe> probes;
  for (const JsonReader& p : j.elements()) {
    p.allow_only({"name", "pixel", "rect"});
    Probe probe;
    probe.name = p.required("name").string();
    if (p.has("pixel") == p.has("rect")) p.fail("give either pixel [x, y] or rect [x0, y0, x1, y1]");
    const JsonReader where = p.has("pixel") ? p.required("pixel") : p.required("rect");
    const std::vector<JsonReader> v = where.elements();
    if (v.size() != (p.has("pixel") ? 2u : 4u)) where.fail_expected(p.has("pixel") ? "[x, y]" : "[x0, y0, x1, y1]");
    std::vector<int> n;
    n.reserve(4);
    for (const JsonReader& e : v) n.push_back(e.integer_in(0, 16384));
    if (n.size() == 2) n = {n[0], n[1], n[0] + 1, n[1] + 1};
    if (n[2] <= n[0] || n[3] <= n[1]) where.fail("the rectangle is empty: x1 must exceed x0 and y1 exceed y0");
    probe.x0 = n[0];
    probe.y0 = n[1];
    probe.x1 = n[2];
    probe.y1 = n[3];
    probes.push_back(probe);
  }
  return probes;
}

}  // namespace skylit
