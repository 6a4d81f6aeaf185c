// The parsed form of a Mitsuba XML scene: a tree of plugin objects (Node), each holding named,
// typed parameters (Property). Builders read parameters through the take_* functions, which
// mark them consumed; check_consumed() then turns any parameter nobody read into an error
// (Mitsuba only warns about unqueried properties; twinray refuses them).
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "scenes/scene_error.h"

namespace tr {

struct Node;
using NodePtr = std::shared_ptr<Node>;

enum class PropertyKind {
  Boolean,
  Integer,
  Float,
  String,
  Color,
  Point,
  Vector,
  Transform,
  Object
};

struct Property {
  std::string name;
  PropertyKind kind = PropertyKind::Float;
  Location loc;
  bool boolean = false;
  long long integer = 0;
  double number = 0.0;
  std::string text;
  glm::dvec3 vec{0.0};     // color, point or vector
  glm::dmat4 matrix{1.0};  // transform (column-major, glm convention)
  NodePtr object;
  bool used = false;
};

// A plugin instance: <shape type="obj">, <bsdf type="diffuse" id="x">, ...
struct Node {
  std::string tag;   // shape, bsdf, texture, emitter, sensor, film, rfilter, sampler, integrator
  std::string type;  // the plugin name
  std::string id;
  Location loc;
  std::vector<Property> props;  // in document order; unnamed objects are named "_arg_<n>"
};

const char* kind_name(PropertyKind kind);
std::string describe(const Node& node);  // e.g. <bsdf type="diffuse">

Property* find_property(Node& node, const std::string& name);
// Appends a property (as a parser would) and returns it for its value to be set.
Property& add_property(Node& node, const std::string& name, PropertyKind kind, const Location& loc);
bool has_property(const Node& node, const std::string& name);

// Typed reads; each marks the parameter consumed, fails on a wrong type, and returns the
// default when the parameter is absent.
double take_float(Node& node, const std::string& name, double default_value);
double take_float(Node& node, const std::string& name);  // required
long long take_integer(Node& node, const std::string& name, long long default_value);
bool take_bool(Node& node, const std::string& name, bool default_value);
std::string take_string(Node& node, const std::string& name, const std::string& default_value);
std::string take_string(Node& node, const std::string& name);  // required
glm::dvec3 take_point(Node& node, const std::string& name, glm::dvec3 default_value);
glm::dvec3 take_vector(Node& node, const std::string& name, glm::dvec3 default_value);
glm::dmat4 take_transform(Node& node, const std::string& name);  // identity when absent
// A color: rgb, spectrum, or a float/integer broadcast to all channels (Mitsuba accepts a
// float wherever a spectrum is expected). Textures are not accepted here.
glm::dvec3 take_color(Node& node, const std::string& name, glm::dvec3 default_value);

// All nested objects with the given tag (named or not), marked consumed.
std::vector<Property*> take_objects(Node& node, const std::string& tag);

// Fails on the first parameter that no builder consumed.
void check_consumed(const Node& node);

}  // namespace tr
