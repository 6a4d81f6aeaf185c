#include "scenes/properties.h"

namespace tr {

const char* kind_name(PropertyKind kind) {
  switch (kind) {
    case PropertyKind::Boolean:
      return "boolean";
    case PropertyKind::Integer:
      return "integer";
    case PropertyKind::Float:
      return "float";
    case PropertyKind::String:
      return "string";
    case PropertyKind::Color:
      return "color (rgb/spectrum)";
    case PropertyKind::Point:
      return "point";
    case PropertyKind::Vector:
      return "vector";
    case PropertyKind::Transform:
      return "transform";
    case PropertyKind::Object:
      return "nested object";
  }
  return "?";
}

std::string describe(const Node& node) {
  return "<" + node.tag + (node.type.empty() ? "" : " type=\"" + node.type + "\"") + ">";
}

Property* find_property(Node& node, const std::string& name) {
  for (Property& p : node.props)
    if (p.name == name) return &p;
  return nullptr;
}

Property& add_property(Node& node, const std::string& name, PropertyKind kind,
                       const Location& loc) {
  Property p;
  p.name = name;
  p.kind = kind;
  p.loc = loc;
  node.props.push_back(std::move(p));
  return node.props.back();
}

bool has_property(const Node& node, const std::string& name) {
  for (const Property& p : node.props)
    if (p.name == name) return true;
  return false;
}

namespace {

[[noreturn]] void wrong_type(const Node& node, const Property& p, const char* expected) {
  std::string got = p.kind == PropertyKind::Object ? "a nested <" + p.object->tag + ">"
                                                   : std::string("a ") + kind_name(p.kind);
  fail(p.loc, "parameter '", p.name, "' of ", describe(node), " must be ", expected, ", not ", got);
}

Property* take(Node& node, const std::string& name) {
  Property* p = find_property(node, name);
  if (p) p->used = true;
  return p;
}

Property& take_required(Node& node, const std::string& name) {
  Property* p = take(node, name);
  if (!p) fail(node.loc, describe(node), " requires the parameter '", name, "'");
  return *p;
}

double as_float(const Node& node, const Property& p) {
  if (p.kind == PropertyKind::Float) return p.number;
  if (p.kind == PropertyKind::Integer) return double(p.integer);
  wrong_type(node, p, "a float");
}

}  // namespace

double take_float(Node& node, const std::string& name, double default_value) {
  Property* p = take(node, name);
  return p ? as_float(node, *p) : default_value;
}

double take_float(Node& node, const std::string& name) {
  return as_float(node, take_required(node, name));
}

long long take_integer(Node& node, const std::string& name, long long default_value) {
  Property* p = take(node, name);
  if (!p) return default_value;
  if (p->kind != PropertyKind::Integer) wrong_type(node, *p, "an integer");
  return p->integer;
}

bool take_bool(Node& node, const std::string& name, bool default_value) {
  Property* p = take(node, name);
  if (!p) return default_value;
  if (p->kind != PropertyKind::Boolean) wrong_type(node, *p, "a boolean");
  return p->boolean;
}

std::string take_string(Node& node, const std::string& name, const std::string& default_value) {
  Property* p = take(node, name);
  if (!p) return default_value;
  if (p->kind != PropertyKind::String) wrong_type(node, *p, "a string");
  return p->text;
}

std::string take_string(Node& node, const std::string& name) {
  Property& p = take_required(node, name);
  if (p.kind != PropertyKind::String) wrong_type(node, p, "a string");
  return p.text;
}

glm::dvec3 take_point(Node& node, const std::string& name, glm::dvec3 default_value) {
  Property* p = take(node, name);
  if (!p) return default_value;
  // Mitsuba's <point> and <vector> are one property type.
  if (p->kind != PropertyKind::Point && p->kind != PropertyKind::Vector)
    wrong_type(node, *p, "a point");
  return p->vec;
}

glm::dvec3 take_vector(Node& node, const std::string& name, glm::dvec3 default_value) {
  Property* p = take(node, name);
  if (!p) return default_value;
  if (p->kind != PropertyKind::Vector && p->kind != PropertyKind::Point)
    wrong_type(node, *p, "a vector");
  return p->vec;
}

glm::dmat4 take_transform(Node& node, const std::string& name) {
  Property* p = take(node, name);
  if (!p) return glm::dmat4(1.0);
  if (p->kind != PropertyKind::Transform) wrong_type(node, *p, "a transform");
  return p->matrix;
}

glm::dvec3 take_color(Node& node, const std::string& name, glm::dvec3 default_value) {
  Property* p = take(node, name);
  if (!p) return default_value;
  if (p->kind == PropertyKind::Color) return p->vec;
  if (p->kind == PropertyKind::Float || p->kind == PropertyKind::Integer)
    return glm::dvec3(as_float(node, *p));
  wrong_type(node, *p, "an rgb, spectrum or float");
}

std::vector<Property*> take_objects(Node& node, const std::string& tag) {
  std::vector<Property*> objects;
  for (Property& p : node.props) {
    if (p.kind == PropertyKind::Object && p.object->tag == tag) {
      p.used = true;
      objects.push_back(&p);
    }
  }
  return objects;
}

void check_consumed(const Node& node) {
  for (const Property& p : node.props) {
    if (p.used) continue;
    if (p.kind == PropertyKind::Object)
      fail(p.loc, "nested <", p.object->tag, p.object->type.empty() ? "" : " type=\"",
           p.object->type, p.object->type.empty() ? "" : "\"", "> is not accepted by ",
           describe(node));
    fail(p.loc, "unused parameter '", p.name, "' (", kind_name(p.kind), ") in ", describe(node),
         ": not a parameter of this plugin");
  }
}

}  // namespace tr
