#include "app/check_bsdf_command.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "app/arguments.h"
#include "app/exit_codes.h"
#include "gpu_backend/gpu_error.h"
#include "io/temp_file.h"
#include "shader_bsdf.h"
#include "validation/image/json_writer.h"

namespace tr {
namespace {

namespace validation = twinray::validation;

const char* kUsage =
    "usage: twinray check-bsdf FILE.glsl|FILE.hlsl [options]\n"
    "  Validates a BSDF written in GLSL or HLSL (user_eval, user_sample, user_pdf; see\n"
    "  validation/shader_bsdf/README.md) on a Vulkan device: chi-square of sample() against\n"
    "  pdf() at theta_i = 0, 30, 60, 85, 89.9 degrees, consistency (weight = eval/pdf,\n"
    "  pdf(sampled) = sampled pdf, eval > 0 => pdf > 0, reciprocity), albedo <= 1, and NaN/Inf/\n"
    "  negative values at extreme directions, and that sample() succeeds at all.\n"
    "options:\n"
    "  --params k=v[/v...],...  parameter values (declared in the file with\n"
    "                           '#pragma twinray_param NAME DEFAULT'); several values per\n"
    "                           parameter make a grid (the Cartesian product)\n"
    "  --samples N              chi-square draws per incident direction (default 100000;\n"
    "                           consistency and albedo use N/4 each)\n"
    "  --significance A         overall level: a correct BSDF fails with probability A over\n"
    "                           the whole grid (default 0.01)\n"
    "  --seed S                 seed of the random draws (default 1)\n"
    "  --not-reciprocal         skip the reciprocity check\n"
    "  --convention k=v,...     the file's convention, converted to twinray's: cosine=included|\n"
    "                           excluded (user_eval returns f|cos theta_o| or f; user_sample's\n"
    "                           weight follows), normal=z|y, incident=away|towards (the\n"
    "                           direction of wi); default cosine=included,normal=z,incident=away\n"
    "  --against PLUGIN k=v ... compare with a twinray BSDF plugin at these parameters (Mitsuba\n"
    "                           3 names, e.g. roughconductor distribution=ggx alpha=0.3): eval\n"
    "                           and pdf over a (theta_i, theta_o, phi_o) grid, directional albedo\n"
    "                           at the incident angles above; differences fail the run (pdf ones\n"
    "                           are only reported); one parameter set only\n"
    "  --plot OUT.svg           with --against: heat map of the eval differences\n"
    "  --device N               Vulkan device: index or name substring (twinray devices)\n"
    "  --json OUT.json          write the report as JSON\n"
    "exit status: 0 all checks pass, 1 some fail, 2 usage error, 3 the shader does not compile\n"
    "             (glslang's errors as FILE:LINE), 4 no usable device, 5 JSON report or plot\n"
    "             not writable\n";

float parse_float(const std::string& text, const std::string& what) {
  char* end = nullptr;
  float v = std::strtof(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v))
    throw UsageError(what + ": '" + text + "' is not a finite number");
  return v;
}

// "alpha=0.1/0.5,f0=0.9" -> {alpha: [0.1, 0.5], f0: [0.9]}
void parse_params(const std::string& text, std::map<std::string, std::vector<float>>& out) {
  std::istringstream pairs(text);
  std::string pair;
  while (std::getline(pairs, pair, ',')) {
    std::size_t eq = pair.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("--params expects NAME=VALUE[/VALUE...], got '" + pair + "'");
    std::string name = pair.substr(0, eq);
    std::vector<float>& values = out[name];
    if (!values.empty()) throw UsageError("--params: " + name + " given twice");
    std::istringstream list(pair.substr(eq + 1));
    std::string v;
    while (std::getline(list, v, '/')) values.push_back(parse_float(v, "--params " + name));
    if (values.empty()) throw UsageError("--params: " + name + " has no value");
  }
}

std::string json_report(const std::string& file, const std::string& device,
                        const std::string& convention, const validation::Report& report,
                        double significance) {
  JsonWriter j;
  j.begin_object();
  j.field("file", file).field("device", device).field("convention", convention);
  j.field("significance", significance);
  j.field("passed", report.passed());
  j.key("checks").begin_array();
  for (const validation::CheckResult& c : report.checks) {
    j.begin_object();
    j.field("parameters", c.bsdf).field("check", c.check).field("passed", c.passed);
    j.key("wi").begin_array().value(double(c.wi.x)).value(double(c.wi.y)).value(double(c.wi.z));
    j.end_array();
    if (c.statistical) j.field("p_value", c.p_value).field("alpha", c.alpha);
    j.field("detail", c.detail);
    j.end_object();
  }
  j.end_array();
  j.end_object();
  return j.str();
}

}  // namespace

int check_bsdf_command(int argc, char** argv) {
  Arguments args(argc - 1, argv + 1);
  std::string file, json, device_selector, against_plugin, plot;
  std::vector<shader_bsdf::PluginParameter> against_parameters;
  std::map<std::string, std::vector<float>> params;
  shader_bsdf::CheckOptions options;
  std::size_t samples = 100000;
  std::uint64_t seed = 1;
  try {
    while (args.more()) {
      std::string a = args.next();
      if (a == "--help" || a == "-h") {
        std::fputs(kUsage, stdout);
        return kExitOk;
      } else if (a == "--params") {
        parse_params(args.value(a), params);
      } else if (a == "--samples") {
        samples = args.uint_value(a, 1000);
      } else if (a == "--significance") {
        double s = parse_float(args.value(a), a);
        if (!(s > 0.0 && s < 1.0)) throw UsageError("--significance must lie in (0, 1)");
        options.validation.significance = s;
      } else if (a == "--seed") {
        seed = args.uint_value(a, 0);
      } else if (a == "--not-reciprocal") {
        options.reciprocal = false;
      } else if (a == "--convention") {
        try {
          options.convention = shader_bsdf::parse_convention(args.value(a));
        } catch (const std::invalid_argument& e) {
          throw UsageError(e.what());
        }
      } else if (a == "--against") {
        if (!against_plugin.empty()) throw UsageError("--against given twice");
        against_plugin = args.value(a);
        // Its parameters: the NAME=VALUE words that follow.
        while (args.more() && args.peek().find('=') != std::string::npos && args.peek()[0] != '-') {
          try {
            against_parameters.push_back(shader_bsdf::parse_plugin_parameter(args.next()));
          } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
          }
        }
      } else if (a == "--plot") {
        plot = args.value(a);
      } else if (a == "--device") {
        device_selector = args.value(a);
      } else if (a == "--json") {
        json = args.value(a);
      } else if (!a.empty() && a[0] == '-') {
        throw UsageError("unknown option '" + a + "'");
      } else if (file.empty()) {
        file = a;
      } else {
        throw UsageError("more than one shader file ('" + file + "', '" + a + "')");
      }
    }
    if (file.empty()) throw UsageError("no shader file given");
    if (!plot.empty() && against_plugin.empty()) throw UsageError("--plot needs --against");
  } catch (const UsageError& e) {
    std::fprintf(stderr, "twinray check-bsdf: %s\n%s", e.what(), kUsage);
    return kExitUsage;
  }

  shader_bsdf::ShaderSource source;
  std::vector<uint32_t> spirv;
  try {
    source = shader_bsdf::read_shader_source(file);
    for (const auto& [name, values] : params) {
      bool declared = false;
      for (const shader_bsdf::ShaderParameter& p : source.parameters) declared |= p.name == name;
      if (!declared) {
        std::fprintf(stderr,
                     "twinray check-bsdf: --params %s: %s declares no such parameter "
                     "('#pragma twinray_param %s DEFAULT')\n",
                     name.c_str(), file.c_str(), name.c_str());
        return kExitUsage;
      }
    }
    spirv = shader_bsdf::compile_shader(source);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadScene;
  }

  options.validation.chi_square.sample_count = samples;
  options.validation.chi_square.seed = seed;
  // As tests/bsdf/suite_size.cpp: a bin's expected count is then off by at most 0.1 draws, which
  // adds < 0.002 to X^2 per bin even at the pooling threshold of 5.
  options.validation.chi_square.integration_tolerance = 0.1 / double(samples);
  options.validation.consistency.sample_count = samples / 4;
  options.validation.consistency.random_pairs = samples / 4;
  options.validation.consistency.seed = seed + 1;
  options.validation.albedo_samples = samples / 4;
  options.against_options.albedo_samples = samples / 4;
  options.against_options.seed = seed + 2;
  const auto grid = shader_bsdf::parameter_grid(source.parameters, params);
  std::unique_ptr<shader_bsdf::PluginBsdf> against;
  if (!against_plugin.empty()) {
    if (grid.size() != 1) {
      std::fprintf(stderr,
                   "twinray check-bsdf: --against compares one parameter set; --params gives %zu\n",
                   grid.size());
      return kExitUsage;
    }
    try {
      against = std::make_unique<shader_bsdf::PluginBsdf>(against_plugin, against_parameters);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "twinray check-bsdf: %s\n", e.what());
      return kExitUsage;
    }
    options.against = against.get();
  }
  try {
    shader_bsdf::ShaderDevice device(spirv, device_selector);
    auto start = std::chrono::steady_clock::now();
    shader_bsdf::CheckOutcome outcome =
        shader_bsdf::check_shader_bsdf(device, source, grid, options);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const validation::Report& report = outcome.report;
    std::cout << file << " on " << device.name() << ": " << grid.size() << " parameter set"
              << (grid.size() == 1 ? "" : "s") << ", " << outcome.evaluations
              << " device evaluations in " << outcome.batches << " batches, " << seconds
              << " s; overall significance " << options.validation.significance << "; convention "
              << options.convention.label() << "\n";
    report.print(std::cout);
    for (const shader_bsdf::AgainstResult& a : outcome.against)
      std::cout << shader_bsdf::against_table(a);
    std::size_t failed = 0;
    for (const validation::CheckResult& c : report.checks) {
      if (c.passed) continue;
      ++failed;
      std::cout << "FAILED " << c.check << " [" << c.bsdf << "]";
      if (c.wi != glm::vec3(0.0f)) {
        double theta = std::acos(std::max(-1.0, std::min(1.0, double(c.wi.z)))) * 180.0 / M_PI;
        double phi = std::atan2(double(c.wi.y), double(c.wi.x)) * 180.0 / M_PI;
        std::cout << " at theta_i=" << theta << " phi_i=" << phi << " wi=(" << c.wi.x << ", "
                  << c.wi.y << ", " << c.wi.z << ")";
      }
      if (c.statistical) std::cout << " p=" << c.p_value << " < alpha=" << c.alpha;
      std::cout << ": " << c.detail << "\n";
    }
    std::cout << (failed == 0 ? "PASS" : "FAIL") << ": " << report.checks.size() - failed << "/"
              << report.checks.size() << " checks passed\n";
    if (!json.empty()) {
      try {
        write_text_file(json, json_report(file, device.name(), options.convention.label(), report,
                                          options.validation.significance) +
                                  "\n");
      } catch (const FileError& e) {
        std::fprintf(stderr, "twinray check-bsdf: cannot write the JSON report: %s\n", e.what());
        return kExitOutput;
      }
    }
    if (!plot.empty()) {
      try {
        write_text_file(plot, shader_bsdf::against_heat_map_svg(outcome.against.front()));
      } catch (const FileError& e) {
        std::fprintf(stderr, "twinray check-bsdf: cannot write the plot: %s\n", e.what());
        return kExitOutput;
      }
    }
    return failed == 0 ? kExitOk : kExitFailed;
  } catch (const GpuError& e) {
    std::fprintf(stderr, "twinray check-bsdf: %s\n", e.what());
    return kExitNoBackend;
  } catch (...) {
    return report_failure("twinray check-bsdf");
  }
}

}  // namespace tr
