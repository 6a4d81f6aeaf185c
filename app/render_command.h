#pragma once

namespace tr {

// `twinray render SCENE.xml [options]`: see the usage text in render_command.cpp.
int render_command(int argc, char** argv);

}  // namespace tr
