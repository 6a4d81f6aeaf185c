#pragma once

namespace tr {

// `twinray conformance FOLDER [options]`: see the usage text in conformance_command.cpp.
int conformance_command(int argc, char** argv);

}  // namespace tr
