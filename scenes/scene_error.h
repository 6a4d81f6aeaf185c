// Where a scene-file element came from, and the one-line errors that point at it.
#pragma once

#include <sstream>
#include <string>

#include "scenes/scene.h"

namespace tr {

struct Location {
  std::string file;
  int line = 0;
};

inline std::string to_string(const Location& loc) {
  return loc.file + ":" + std::to_string(loc.line);
}

// Throws SceneError("file:line: <the streamed parts>"); newlines in the parts become spaces,
// so the message always stays on one line.
template <typename... Parts>
[[noreturn]] void fail(const Location& loc, const Parts&... parts) {
  std::ostringstream os;
  os << to_string(loc) << ": ";
  (os << ... << parts);
  std::string message = os.str();
  for (char& c : message)
    if (c == '\n' || c == '\r') c = ' ';
  throw SceneError(message);
}

}  // namespace tr
