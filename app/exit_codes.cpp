#include "app/exit_codes.h"

#include <cstdio>
#include <exception>

#include "io/temp_file.h"
#include "render/checkpoint.h"
#include "render/render.h"
#include "scenes/scene.h"

namespace tr {

int report_failure(const char* prefix) {
  try {
    throw;
  } catch (const SceneError& e) {
    std::fprintf(stderr, "%s: %s\n", prefix, e.what());
    return kExitBadScene;
  } catch (const BackendUnavailable& e) {
    std::fprintf(stderr, "%s: %s\n", prefix, e.what());
    return kExitNoBackend;
  } catch (const CheckpointError& e) {
    std::fprintf(stderr, "%s: %s\n", prefix, e.what());
    return kExitCheckpoint;
  } catch (const FileError& e) {
    std::fprintf(stderr, "%s: %s\n", prefix, e.what());
    return kExitOutput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: internal error: %s\n", prefix, e.what());
    return kExitInternal;
  }
}

}  // namespace tr
