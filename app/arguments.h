// A small command-line cursor shared by the verbs.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace tr {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Arguments {
 public:
  Arguments(int argc, char** argv) : argc_(argc), argv_(argv) {}
  bool more() const { return index_ < argc_; }
  std::string next() { return argv_[index_++]; }
  // The next word, not consumed (more() must hold).
  std::string peek() const { return argv_[index_]; }
  // The value following option `name`.
  std::string value(const std::string& name) {
    if (!more()) throw UsageError(name + " needs a value");
    return next();
  }
  // The NAME=VALUE following option `name` (-D).
  std::pair<std::string, std::string> name_value(const std::string& name) {
    std::string kv = value(name);
    size_t eq = kv.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError(name + " expects NAME=VALUE, got '" + kv + "'");
    return {kv.substr(0, eq), kv.substr(eq + 1)};
  }
  unsigned uint_value(const std::string& name, unsigned minimum) {
    std::string v = value(name);
    size_t used = 0;
    unsigned long parsed = 0;
    try {
      parsed = std::stoul(v, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != v.size() || v.empty() || v[0] == '-' || parsed < minimum || parsed > 0xffffffffUL)
      throw UsageError(name + " expects an integer >= " + std::to_string(minimum) + ", got '" + v +
                       "'");
    return unsigned(parsed);
  }

 private:
  int argc_;
  char** argv_;
  int index_ = 0;
};

}  // namespace tr
