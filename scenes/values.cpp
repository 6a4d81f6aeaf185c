#include "scenes/values.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace tr {

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> tokens;
  std::string current;
  for (char c : text) {
    if (c == ',' || std::isspace(static_cast<unsigned char>(c))) {
      if (!current.empty()) tokens.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  if (!current.empty()) tokens.push_back(current);
  return tokens;
}

namespace {

std::string trim(const std::string& s) {
  size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

}  // namespace

double parse_double(const std::string& text, const Location& loc, const std::string& what) {
  std::string t = trim(text);
  char* end = nullptr;
  errno = 0;
  double v = t.empty() ? 0.0 : std::strtod(t.c_str(), &end);
  if (t.empty() || end != t.c_str() + t.size())
    fail(loc, what, ": cannot parse \"", text, "\" as a number");
  if (!std::isfinite(v) || errno == ERANGE)
    fail(loc, what, ": \"", text, "\" is not a finite number");
  return v;
}

long long parse_integer(const std::string& text, const Location& loc, const std::string& what) {
  std::string t = trim(text);
  char* end = nullptr;
  errno = 0;
  long long v = t.empty() ? 0 : std::strtoll(t.c_str(), &end, 10);
  if (t.empty() || end != t.c_str() + t.size())
    fail(loc, what, ": cannot parse \"", text, "\" as an integer");
  if (errno == ERANGE) fail(loc, what, ": integer \"", text, "\" is out of range");
  return v;
}

bool parse_boolean(const std::string& text, const Location& loc, const std::string& what) {
  std::string t = to_lower(trim(text));
  if (t == "true") return true;
  if (t == "false") return false;
  fail(loc, what, ": expected \"true\" or \"false\", not \"", text, "\"");
}

std::vector<double> parse_doubles(const std::string& text, size_t count, bool allow_broadcast,
                                  const Location& loc, const std::string& what) {
  std::vector<std::string> tokens = split_list(text);
  if (allow_broadcast && tokens.size() == 1)
    return std::vector<double>(count, parse_double(tokens[0], loc, what));
  if (tokens.size() != count)
    fail(loc, what, ": expected ", count, allow_broadcast ? " values (or 1)" : " values", ", got ",
         tokens.size(), " in \"", text, "\"");
  std::vector<double> values;
  for (const std::string& t : tokens) values.push_back(parse_double(t, loc, what));
  return values;
}

std::string to_lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace tr
