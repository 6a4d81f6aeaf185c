#pragma once

namespace tr {

// `twinray validate SUITE [options]` (argv[0] is the verb): renders every scene of a suite
// (suite.h) on the CPU and optionally the GPU, compares each render with the scene's
// reference and the two backends with each other, and writes a self-contained HTML report and
// a JSON summary. Exit status: 0 every scene passed, 1 a check failed or a scene could not be
// rendered, 2 usage or suite error, 5 an output could not be written. See the usage text.
int validate_command(int argc, char** argv);

}  // namespace tr
