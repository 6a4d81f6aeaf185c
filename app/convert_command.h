#pragma once

namespace tr {

// `twinray convert SCENE.scn -o OUT.xml`: see the usage text in convert_command.cpp.
int convert_command(int argc, char** argv);

}  // namespace tr
