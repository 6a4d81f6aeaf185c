// The scene the CPU definitions of core/scene_access.h read. One scene is bound per process
// at a time (the core reads scene data through free functions, as the GPU does through its
// descriptor set); ScopedSceneBinding binds for a render and unbinds after it.
#pragma once

#include "scenes/scene.h"

namespace tr {

void bind_scene_buffers(const SceneBuffers* buffers);

class ScopedSceneBinding {
 public:
  explicit ScopedSceneBinding(const SceneBuffers& buffers) { bind_scene_buffers(&buffers); }
  ~ScopedSceneBinding() { bind_scene_buffers(nullptr); }
  ScopedSceneBinding(const ScopedSceneBinding&) = delete;
  ScopedSceneBinding& operator=(const ScopedSceneBinding&) = delete;
};

}  // namespace tr
