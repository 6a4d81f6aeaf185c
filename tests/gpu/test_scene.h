// A small hand-built scene for the GPU tests: a camera at the origin looking along +z, a
// unit sphere at (0, 0, 5) (shape 0), a large two-triangle quad at z = 8 (shape 1), and a
// disk of radius 0.5 at z = 4.5 (shape 2) inside a second instance translated by (1.5, 0, 0),
// all diffuse with albedo 0.5, under a constant environment of radiance 1 (path, max_depth 4).
#pragma once

#include "scenes/scene.h"

namespace tr::test {

Scene probe_scene(uint width, uint height);

}  // namespace tr::test
