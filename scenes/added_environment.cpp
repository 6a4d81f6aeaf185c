#include "scenes/added_environment.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "scenes/properties.h"
#include "scenes/scene_error.h"

namespace tr {

glm::dvec3 parse_radiance(const std::string& text) {
  double v[3];
  int n = 0;
  const char* p = text.c_str();
  while (true) {
    char* end = nullptr;
    double x = std::strtod(p, &end);
    if (end == p || n == 3 || !std::isfinite(x) || x < 0.0) break;
    v[n++] = x;
    p = end;
    while (*p == ' ') ++p;
    if (*p == '\0') {
      if (n == 1) return glm::dvec3(v[0]);
      if (n == 3) return {v[0], v[1], v[2]};
      break;
    }
    if (*p++ != ',') break;
  }
  throw std::invalid_argument("expected V or R,G,B (finite, non-negative numbers), got '" + text +
                              "'");
}

void add_environment(Node& root, const AddedEnvironment& environment) {
  for (const Property& p : root.props)
    if (p.kind == PropertyKind::Object && p.object->tag == "emitter" &&
        (p.object->type == "constant" || p.object->type == "envmap"))
      fail(p.object->loc, describe(*p.object),
           ": the scene has an environment already; Mitsuba holds one a scene, so --envmap and "
           "--constant cannot add another");
  auto e = std::make_shared<Node>();
  e->tag = "emitter";
  e->loc = root.loc;
  auto add = [&](const std::string& name, PropertyKind kind) -> Property& {
    return add_property(*e, name, kind, root.loc);
  };
  if (!environment.envmap.empty()) {
    e->type = "envmap";
    e->loc.file = environment.envmap;  // an image that cannot be read is named with the error
    e->loc.line = 0;
    add("filename", PropertyKind::String).text =
        std::filesystem::absolute(environment.envmap).string();
    add("scale", PropertyKind::Float).number = environment.envmap_scale;
  } else {
    e->type = "constant";
    add("radiance", PropertyKind::Color).vec = *environment.constant;
  }
  add_property(root, "_added_environment", PropertyKind::Object, root.loc).object = e;
}

}  // namespace tr
