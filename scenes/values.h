// Mitsuba's textual values: numbers, booleans, and lists separated by commas and/or spaces.
#pragma once

#include <string>
#include <vector>

#include "scenes/scene_error.h"

namespace tr {

std::vector<std::string> split_list(const std::string& text);  // on commas and whitespace
// Finite double; `what` names the value in the error message.
double parse_double(const std::string& text, const Location& loc, const std::string& what);
long long parse_integer(const std::string& text, const Location& loc, const std::string& what);
bool parse_boolean(const std::string& text, const Location& loc, const std::string& what);
// Exactly `count` numbers, or one number broadcast when `allow_broadcast`.
std::vector<double> parse_doubles(const std::string& text, size_t count, bool allow_broadcast,
                                  const Location& loc, const std::string& what);
std::string to_lower(std::string s);

}  // namespace tr
