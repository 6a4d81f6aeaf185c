// One of twinray's BSDF plugins at given parameters, as validation/bsdf's callables over core/'s
// C++ build: what `twinray check-bsdf --against PLUGIN k=v ...` compares a user's BSDF with.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "twinray_validation.h"

namespace tr::shader_bsdf {

// A plugin parameter as given on the command line: "alpha=0.3", "eta=0.2,0.9,1.1" (rgb),
// "sample_visible=false", "distribution=ggx", "material=Au".
struct PluginParameter {
  std::string name, value;
};

// Splits "name=value"; throws std::invalid_argument for anything else.
PluginParameter parse_plugin_parameter(const std::string& text);

class PluginBsdf {
 public:
  // Builds the plugin as a Mitsuba 3 scene would (scenes/, the same parameter checks and
  // defaults); throws std::runtime_error "--against PLUGIN: what" on an unknown plugin or a
  // parameter it does not read. Binds its scene for core/'s C++ build (one at a time).
  PluginBsdf(const std::string& plugin, const std::vector<PluginParameter>& parameters);
  ~PluginBsdf();
  PluginBsdf(const PluginBsdf&) = delete;
  PluginBsdf& operator=(const PluginBsdf&) = delete;

  // Named "roughconductor alpha=0.3 distribution=ggx", as given.
  twinray::validation::BsdfUnderTest under_test() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string label_;
};

}  // namespace tr::shader_bsdf
