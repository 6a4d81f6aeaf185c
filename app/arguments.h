// A small command-line cursor shared by the verbs.
#pragma once

#include <stdexcept>
#include <string>

namespace tr {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Arguments {
 public:
  Arguments(int argc, char** argv) : argc_(argc), argv_(argv) {}
  bool more() const { return index_ < argc_; }
  std::string next() { return argv_[index_++]; }
  // The value following option `name`.
  std::string value(const std::string& name) {
    if (!more()) throw UsageError(name + " needs a value");
    return next();
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
