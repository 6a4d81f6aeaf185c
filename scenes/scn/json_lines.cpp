#include "scenes/scn/json_lines.h"

#include <cstring>

namespace tr {

namespace {

// Recursive descent over valid JSON (RFC 8259): only what is needed to find where each value
// starts; the text was validated before, so no error handling here.
class Scanner {
 public:
  explicit Scanner(const std::string& text) : s_(text) {}

  JsonLines scan() {
    value("");
    return out_;
  }

 private:
  void blank() {
    while (i_ < s_.size() && std::strchr(" \t\r\n", s_[i_])) {
      if (s_[i_] == '\n') ++line_;
      ++i_;
    }
  }

  std::string string() {  // at the opening quote; returns the raw (unescaped) content
    std::string out;
    for (++i_; i_ < s_.size() && s_[i_] != '"'; ++i_) {
      if (s_[i_] == '\\') out += s_[i_++];
      out += s_[i_];
    }
    ++i_;
    return out;
  }

  static std::string pointer_token(const std::string& key) {  // RFC 6901 section 3
    std::string out;
    for (char c : key) out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    return out;
  }

  void value(const std::string& pointer, int depth = 0) {
    blank();
    if (!out_.lines.emplace(pointer, line_).second) out_.repeated.emplace(pointer, line_);
    out_.bytes.emplace(pointer, i_);
    if (i_ >= s_.size() || out_.too_deep) return;
    if (depth > kJsonMaxDepth) {
      out_.too_deep = line_;
      return;
    }
    if (s_[i_] == '{') {
      ++i_;
      for (blank(); i_ < s_.size() && s_[i_] != '}'; blank()) {
        if (s_[i_] == ',') ++i_, blank();
        std::string key = string();
        blank();
        ++i_;  // ':'
        value(pointer + "/" + pointer_token(key), depth + 1);
        if (out_.too_deep) return;
      }
      ++i_;
    } else if (s_[i_] == '[') {
      ++i_;
      int index = 0;
      for (blank(); i_ < s_.size() && s_[i_] != ']'; blank()) {
        if (s_[i_] == ',') ++i_;
        value(pointer + "/" + std::to_string(index++), depth + 1);
        if (out_.too_deep) return;
      }
      ++i_;
    } else if (s_[i_] == '"') {
      string();
    } else {
      while (i_ < s_.size() && !std::strchr(",]} \t\r\n", s_[i_])) ++i_;
    }
  }

  const std::string& s_;
  size_t i_ = 0;
  int line_ = 1;
  JsonLines out_;
};

}  // namespace

JsonLines json_value_lines(const std::string& text) { return Scanner(text).scan(); }

}  // namespace tr
