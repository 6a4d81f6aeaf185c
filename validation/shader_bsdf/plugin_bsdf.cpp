#include "plugin_bsdf.h"

#include <cstdio>
#include <fstream>
#include <regex>
#include <stdexcept>

#include "core/bsdf.h"
#include "cpu_backend/bound_scene.h"
#include "io/temp_file.h"
#include "scenes/load_scene.h"
#include "validation/image/xml_escape.h"

namespace tr::shader_bsdf {

namespace validation = twinray::validation;

PluginParameter parse_plugin_parameter(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == 0 || eq == std::string::npos || eq + 1 == text.size())
    throw std::invalid_argument("--against: '" + text + "' is not NAME=VALUE");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

namespace {

// The XML element of one parameter: a number is a <float>, three comma-separated numbers an
// <rgb>, true/false a <boolean>, anything else a <string> (Mitsuba's own types for them).
std::string parameter_element(const PluginParameter& p) {
  static const std::regex number(R"([-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?)");
  static const std::regex rgb(R"(\s*([^,]+)\s*,\s*([^,]+)\s*,\s*([^,]+)\s*)");
  std::smatch parts;
  std::string tag = "string";
  if (std::regex_match(p.value, number)) {
    tag = "float";
  } else if (p.value == "true" || p.value == "false") {
    tag = "boolean";
  } else if (std::regex_match(p.value, parts, rgb) && std::regex_match(parts[1].str(), number) &&
             std::regex_match(parts[2].str(), number) && std::regex_match(parts[3].str(), number)) {
    tag = "rgb";
  }
  return "<" + tag + " name=\"" + xml_escape(p.name) + "\" value=\"" + xml_escape(p.value) + "\"/>";
}

}  // namespace

struct PluginBsdf::Impl {
  Scene scene;
  uint material = 0;
  std::unique_ptr<ScopedSceneBinding> binding;
};

PluginBsdf::PluginBsdf(const std::string& plugin, const std::vector<PluginParameter>& parameters)
    : impl_(std::make_unique<Impl>()), label_(plugin) {
  for (const PluginParameter& p : parameters) label_ += " " + p.name + "=" + p.value;
  // One line per element, so that the loader's line numbers name the parameter at fault.
  std::vector<std::string> lines = {
      "<scene version=\"3.0.0\">",
      "<sensor type=\"perspective\"><film type=\"hdrfilm\"><integer name=\"width\" value=\"1\"/>"
      "<integer name=\"height\" value=\"1\"/></film></sensor>",
      "<bsdf type=\"" + xml_escape(plugin) + "\" id=\"against\">"};
  const std::size_t first_parameter_line = lines.size() + 1;
  for (const PluginParameter& p : parameters) lines.push_back(parameter_element(p));
  lines.push_back("</bsdf>");
  lines.push_back("<shape type=\"rectangle\"><ref id=\"against\"/></shape>");
  lines.push_back("</scene>");
  TemporaryDirectory folder;
  const std::string path = folder.path() + "/against.xml";
  {
    std::ofstream out(path);
    for (const std::string& l : lines) out << l << "\n";
    if (!out) throw std::runtime_error("--against: cannot write " + path);
  }
  try {
    impl_->scene = load_scene(path, LoadOptions{});
  } catch (const SceneError& e) {
    // "TEMPFILE:LINE: what" -> "--against PLUGIN [NAME=VALUE]: what"
    std::string message = e.what();
    const std::string prefix = path + ":";
    std::string where = "--against " + plugin;
    if (message.compare(0, prefix.size(), prefix) == 0) {
      const std::size_t colon = message.find(':', prefix.size());
      const std::size_t line = std::stoul(message.substr(prefix.size(), colon - prefix.size()));
      if (line >= first_parameter_line && line < first_parameter_line + parameters.size()) {
        const PluginParameter& p = parameters[line - first_parameter_line];
        where += " " + p.name + "=" + p.value;
      }
      message = message.substr(colon + 1);
      if (!message.empty() && message[0] == ' ') message.erase(0, 1);
    }
    throw std::runtime_error(where + ": " + message);
  }
  if (impl_->scene.buffers.shapes.empty())
    throw std::runtime_error("--against " + plugin + ": the plugin built no surface");
  impl_->material = impl_->scene.buffers.shapes.front().material;
  impl_->binding = std::make_unique<ScopedSceneBinding>(impl_->scene.buffers);
}

PluginBsdf::~PluginBsdf() = default;

validation::BsdfUnderTest PluginBsdf::under_test() const {
  const Material m = impl_->scene.buffers.materials.at(impl_->material);
  // Untextured parameters do not depend on the surface point.
  const vec2 uv(0.5f);
  validation::BsdfUnderTest b;
  b.name = label_;
  b.sample = [m, uv](const glm::vec3& wi, float u1, const glm::vec2& u2) {
    BsdfSample s = bsdf_sample(m, uv, wi, u1, u2);
    validation::BsdfSample r;
    r.wo = s.wo;
    r.pdf = s.pdf;
    r.weight = s.weight;
    r.delta = (s.lobe & BSDF_DELTA) != 0u;
    r.lobe = s.lobe;
    return r;
  };
  b.pdf = [m, uv](const glm::vec3& wi, const glm::vec3& wo) { return bsdf_pdf(m, uv, wi, wo); };
  b.eval = [m, uv](const glm::vec3& wi, const glm::vec3& wo) { return bsdf_eval(m, uv, wi, wo); };
  b.eval_includes_cosine = true;
  return b;
}

}  // namespace tr::shader_bsdf
