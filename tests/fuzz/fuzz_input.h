// Shared by the libFuzzer targets: the fuzzer's bytes as a file of a given extension in a
// private folder (the readers take paths), removed afterwards.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace tr::fuzz {

class InputFile {
 public:
  InputFile(const std::uint8_t* data, std::size_t size, const std::string& extension) {
    static std::string folder = [] {
      char pattern[] = "/tmp/twinray_fuzz_XXXXXX";
      const char* made = mkdtemp(pattern);
      if (!made) std::abort();
      return std::string(made);
    }();
    path_ = folder + "/input" + extension;
    FILE* f = std::fopen(path_.c_str(), "wb");
    if (!f || std::fwrite(data, 1, size, f) != size) std::abort();
    std::fclose(f);
  }
  ~InputFile() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace tr::fuzz
