// Exit statuses of the twinray command line (documented in README.md and `twinray --help`).
#pragma once

namespace tr {

enum ExitCode : int {
  kExitOk = 0,
  kExitFailed = 1,       // a check failed (compare/validate verdict: fail)
  kExitUsage = 2,        // bad command-line arguments
  kExitBadScene = 3,     // the scene file (or a file it names) is invalid
  kExitNoBackend = 4,    // the requested backend/device is unavailable
  kExitOutput = 5,       // an output file could not be written
  kExitInternal = 6,     // an unexpected internal error
  kExitInterrupted = 7,  // render stopped by SIGINT/SIGTERM; outputs hold the samples so far
  kExitCheckpoint = 8,   // --resume: the checkpoint is damaged or belongs to another render
};

// Call inside a catch (...) block: prints the exception being handled as one line
// "<prefix>: <message>" on stderr and returns its exit status (SceneError: kExitBadScene,
// BackendUnavailable: kExitNoBackend, FileError: kExitOutput, CheckpointError: kExitCheckpoint,
// anything else: kExitInternal).
int report_failure(const char* prefix);

}  // namespace tr
