// The parts of a scene's `render` block that say how the result is shown and measured
// rather than how it is rendered: `false_colour` (docs/scene-format.md).
#include "skylit/io/scene/scene_parts.h"

namespace skylit {

FalseColourSettings read_false_colour(const JsonReader& j) {
  j.allow_only({"quantity", "scale", "max", "decades", "contours", "underlay"});
  FalseColourSettings f;
  if (auto q = j.optional("quantity")) q->one_of({"luminance"});
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

}  // namespace skylit
