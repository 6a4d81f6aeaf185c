// gtest main of the suite: `--full` (or TWINRAY_FULL_TESTS=1 in the environment) selects the
// full statistical size.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#include "suite_size.h"

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  const char* env = std::getenv("TWINRAY_FULL_TESTS");
  if (env != nullptr && std::strcmp(env, "1") == 0) tr::bsdf_suite::full_size() = true;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--full") == 0) tr::bsdf_suite::full_size() = true;
  }
  return RUN_ALL_TESTS();
}
