#pragma once

namespace tr {

// `twinray converge SCENE.xml --reference REF.exr --budget SECONDS [options]` (argv[0] is the
// verb): for each render variant (variant.h), renders at doubling sample counts until the
// time budget is spent, and writes error against time as CSV, a log-log SVG plot and the time
// to reach given relMSE levels. Exit status: 0 ok, 2 usage error, 3 invalid scene, 4 backend
// unavailable, 5 an output could not be written, 6 internal error.
int converge_command(int argc, char** argv);

}  // namespace tr
