// `twinray compare A.exr B.exr [options]`: compares test image A with reference image B.
//
// Exit status: 0 when every check that decides the verdict passes (or none was requested),
// 1 when one fails, 2 on bad input (unreadable or mismatched images, bad arguments), 5 when an
// output file (heatmap, JSON) cannot be written; the codes of app/exit_codes.h.
// Run with --help for the options.
#pragma once

namespace tr {

// argv[0] is the verb name ("compare"); the arguments follow.
int compare_command(int argc, char** argv);

}  // namespace tr
