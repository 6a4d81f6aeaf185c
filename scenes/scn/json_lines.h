// The line on which each value of a JSON document starts, keyed by its JSON pointer (RFC 6901,
// e.g. "/entities/1/radius"), so that errors about a value can say file:line. nlohmann::json
// keeps no positions; this scans text that nlohmann::json has already accepted as valid.
#pragma once

#include <map>
#include <string>

namespace tr {

std::map<std::string, int> json_value_lines(const std::string& text);

}  // namespace tr
