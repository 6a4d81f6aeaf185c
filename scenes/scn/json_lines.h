// The line (and byte) at which each value of a JSON document starts, keyed by its JSON pointer (RFC
// 6901, e.g. "/entities/1/radius"), so that errors about a value can say file:line, and the keys
// that an object repeats (nlohmann::json keeps the last silently; RFC 8259 section 4 leaves it to
// the reader). nlohmann::json keeps no positions; this scans text it has already accepted as valid.
#pragma once

#include <map>
#include <string>

namespace tr {

// Arrays and objects nested deeper than this are not scanned (the scan recurses; a .scn scene
// nests 4 deep).
constexpr int kJsonMaxDepth = 64;

struct JsonLines {
  std::map<std::string, int> lines;     // pointer -> line of the value's first character
  std::map<std::string, size_t> bytes;  // pointer -> byte offset of the value's first character
  std::map<std::string, int> repeated;  // pointer of a repeated key -> line of its second value
  int too_deep = 0;  // the line of the first value nested deeper than kJsonMaxDepth, or 0
};

JsonLines json_value_lines(const std::string& text);

}  // namespace tr
