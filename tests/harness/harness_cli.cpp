// The validate and converge verbs as a stand-alone program, so the harness tests do not
// depend on how app/main.cpp dispatches verbs. usage: twinray_harness_cli validate|converge ...
#include <cstdio>
#include <cstring>

#include "app/converge_command.h"
#include "app/validate_command.h"

int main(int argc, char** argv) {
  if (argc >= 2 && !std::strcmp(argv[1], "validate"))
    return tr::validate_command(argc - 1, argv + 1);
  if (argc >= 2 && !std::strcmp(argv[1], "converge"))
    return tr::converge_command(argc - 1, argv + 1);
  std::fprintf(stderr, "usage: twinray_harness_cli validate|converge [arguments]\n");
  return 2;
}
