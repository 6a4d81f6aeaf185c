// build_id() (render/checkpoint.h), which ties a checkpoint to the executable that wrote it, reads
// the executable's own build-ID note: the one binutils' readelf reports for this test's file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "render/checkpoint.h"

namespace tr {
namespace {

std::string readelf_build_id() {
  const std::string command = "readelf -n /proc/" + std::to_string(getpid()) + "/exe 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return "";
  std::string output;
  char line[512];
  while (std::fgets(line, sizeof line, pipe)) output += line;
  pclose(pipe);
  const std::string key = "Build ID: ";
  const std::size_t at = output.find(key);
  if (at == std::string::npos) return "";
  return output.substr(at + key.size(), output.find('\n', at) - at - key.size());
}

TEST(BuildId, IsTheExecutablesBuildIdNote) {
  const std::string id = build_id();
  EXPECT_EQ(id.size(), 40u) << id;  // SHA-1, as render/CMakeLists.txt links
  EXPECT_EQ(id, readelf_build_id());
  EXPECT_EQ(id, build_id());
}

}  // namespace
}  // namespace tr
