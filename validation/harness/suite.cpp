#include "validation/harness/suite.h"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace tr {
namespace {

namespace fs = std::filesystem;

std::uint32_t parse_count(const std::string& where, const std::string& key,
                          const std::string& value) {
  size_t used = 0;
  unsigned long v = 0;
  try {
    v = std::stoul(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (value.empty() || used != value.size() || value[0] == '-' || v > 0xffffffffUL)
    throw SuiteError(where + ": " + key + " expects a non-negative integer, got '" + value + "'");
  return std::uint32_t(v);
}

bool valid_name(const std::string& name) {
  if (name.empty()) return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
  return true;
}

std::string default_variance_path(const std::string& reference) {
  fs::path p(reference);
  return (p.parent_path() / (p.stem().string() + "_var" + p.extension().string())).string();
}

}  // namespace

std::vector<SuiteEntry> read_suite(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw SuiteError(path + ": cannot open the suite file");
  fs::path base = fs::path(path).parent_path();
  auto resolve = [&base](const std::string& p) {
    fs::path q(p);
    return (q.is_absolute() ? q : base / q).lexically_normal().string();
  };
  std::vector<SuiteEntry> suite;
  std::set<std::string> names;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::string where = path + ":" + std::to_string(number);
    std::istringstream fields(line);
    std::string field;
    SuiteEntry e;
    std::set<std::string> seen;
    bool any = false;
    while (fields >> field) {
      if (!any && field[0] == '#') break;
      any = true;
      size_t eq = field.find('=');
      if (eq == std::string::npos || eq == 0)
        throw SuiteError(where + ": expected KEY=VALUE, got '" + field + "'");
      std::string key = field.substr(0, eq), value = field.substr(eq + 1);
      if (key != "define" && !seen.insert(key).second)
        throw SuiteError(where + ": " + key + " given twice");
      if (key == "name") {
        if (!valid_name(value))
          throw SuiteError(where + ": name must be letters, digits, '_' or '-', got '" + value +
                           "'");
        e.name = value;
      } else if (key == "scene") {
        e.scene = resolve(value);
      } else if (key == "reference") {
        e.reference = resolve(value);
      } else if (key == "variance") {
        e.variance = resolve(value);
      } else if (key == "reference_spp") {
        e.reference_spp = parse_count(where, key, value);
        if (e.reference_spp < 2) throw SuiteError(where + ": reference_spp must be at least 2");
      } else if (key == "spp") {
        e.spp = value == "auto" ? 0 : parse_count(where, key, value);
        if (value != "auto" && e.spp == 0) throw SuiteError(where + ": spp must be positive");
      } else if (key == "seed") {
        e.seed = parse_count(where, key, value);
      } else if (key == "lockstep_spp") {
        e.lockstep_spp = parse_count(where, key, value);
        if (e.lockstep_spp == 0) throw SuiteError(where + ": lockstep_spp must be positive");
      } else if (key == "define") {
        size_t eq2 = value.find('=');
        if (eq2 == std::string::npos || eq2 == 0)
          throw SuiteError(where + ": define expects NAME=VALUE, got '" + value + "'");
        e.defines[value.substr(0, eq2)] = value.substr(eq2 + 1);
      } else {
        throw SuiteError(where + ": unknown key '" + key + "'");
      }
    }
    if (!any) continue;
    for (const char* required : {"name", "scene", "reference", "reference_spp"})
      if (!seen.count(required)) throw SuiteError(where + ": missing " + required + "=");
    if (e.variance.empty()) e.variance = default_variance_path(e.reference);
    if (!names.insert(e.name).second) throw SuiteError(where + ": duplicate name '" + e.name + "'");
    suite.push_back(e);
  }
  if (suite.empty()) throw SuiteError(path + ": the suite lists no scenes");
  return suite;
}

const SuiteEntry& find_entry(const std::vector<SuiteEntry>& suite, const std::string& name) {
  for (const SuiteEntry& e : suite)
    if (e.name == name) return e;
  throw SuiteError("no scene named '" + name + "' in the suite");
}

std::uint32_t acceptance_spp(std::uint32_t width, std::uint32_t height) {
  std::uint64_t pixels = std::uint64_t(width) * height;
  if (pixels == 0) throw SuiteError("the film has no pixels");
  std::uint64_t spp = 2000000u / pixels;
  return std::uint32_t(spp > 0 ? spp : 1);
}

}  // namespace tr
