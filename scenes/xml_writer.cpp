#include "scenes/xml_writer.h"

#include <cstdio>
#include <set>

namespace tr {

namespace {

std::string escaped(const std::string& s) {  // XML 1.0 attribute value
  std::string out;
  for (char c : s) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

std::string number(double v) {  // 17 significant digits: strtod gives back the same double
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

class Writer {
 public:
  Writer(std::ostream& out, const std::vector<SceneParameter>& parameters)
      : out_(out), parameters_(parameters) {}

  void node(const Node& n, const std::string& name, int depth) {
    std::string indent(2 * depth, ' ');
    std::string name_attr = name.rfind("_arg_", 0) == 0 ? "" : " name=\"" + escaped(name) + "\"";
    if (!n.id.empty() && !written_.insert(&n).second) {
      out_ << indent << "<ref" << name_attr << " id=\"" << escaped(n.id) << "\"/>\n";
      return;
    }
    out_ << indent << "<" << n.tag << " type=\"" << escaped(n.type) << "\"";
    if (!n.id.empty()) out_ << " id=\"" << escaped(n.id) << "\"";
    out_ << name_attr << ">\n";
    for (const Property& p : n.props) property(n, p, depth + 1);
    out_ << indent << "</" << n.tag << ">\n";
  }

 private:
  // The text of a value attribute: $name where a parameter stands for it.
  std::string value(const Node& n, const Property& p, const std::string& literal) {
    for (const SceneParameter& s : parameters_)
      if (s.node == &n && s.property == p.name) return "$" + s.name;
    return literal;
  }

  void property(const Node& n, const Property& p, int depth) {
    std::string indent(2 * depth, ' ');
    std::string name = " name=\"" + escaped(p.name) + "\"";
    auto xyz = [&](const char* tag) {
      out_ << indent << "<" << tag << name << " x=\"" << number(p.vec.x) << "\" y=\""
           << number(p.vec.y) << "\" z=\"" << number(p.vec.z) << "\"/>\n";
    };
    switch (p.kind) {
      case PropertyKind::Boolean:
        out_ << indent << "<boolean" << name << " value=\""
             << value(n, p, p.boolean ? "true" : "false") << "\"/>\n";
        break;
      case PropertyKind::Integer:
        out_ << indent << "<integer" << name << " value=\""
             << value(n, p, std::to_string(p.integer)) << "\"/>\n";
        break;
      case PropertyKind::Float:
        out_ << indent << "<float" << name << " value=\"" << value(n, p, number(p.number))
             << "\"/>\n";
        break;
      case PropertyKind::String:
        out_ << indent << "<string" << name << " value=\"" << escaped(value(n, p, p.text))
             << "\"/>\n";
        break;
      case PropertyKind::Color:
        out_ << indent << "<rgb" << name << " value=\"" << number(p.vec.x) << ", "
             << number(p.vec.y) << ", " << number(p.vec.z) << "\"/>\n";
        break;
      case PropertyKind::Point:
        xyz("point");
        break;
      case PropertyKind::Vector:
        xyz("vector");
        break;
      case PropertyKind::Transform: {
        out_ << indent << "<transform" << name << ">\n" << indent << "  <matrix value=\"";
        for (int row = 0; row < 4; ++row)  // Mitsuba lists the matrix row by row
          for (int col = 0; col < 4; ++col)
            out_ << number(p.matrix[col][row]) << (row == 3 && col == 3 ? "" : " ");
        out_ << "\"/>\n" << indent << "</transform>\n";
        break;
      }
      case PropertyKind::Object:
        node(*p.object, p.name, depth);
        break;
    }
  }

  std::ostream& out_;
  const std::vector<SceneParameter>& parameters_;
  std::set<const Node*> written_;
};

}  // namespace

void write_scene_xml(std::ostream& out, const Node& root,
                     const std::vector<SceneParameter>& parameters, const std::string& comment) {
  std::string text = comment;  // "--" may not occur inside an XML comment
  for (size_t i; (i = text.find("--")) != std::string::npos;) text.replace(i, 2, "- -");
  out << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<!-- " << text << " -->\n"
      << "<scene version=\"3.0.0\">\n";
  for (const SceneParameter& s : parameters)
    out << "  <default name=\"" << escaped(s.name) << "\" value=\"" << escaped(s.value) << "\"/>\n";
  Writer writer(out, parameters);
  for (const Property& p : root.props) writer.node(*p.object, p.name, 1);
  out << "</scene>\n";
}

}  // namespace tr
