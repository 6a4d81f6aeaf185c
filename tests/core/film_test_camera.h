// The camera whose filter tables core/film.h reads through scene_filter_table and
// scene_filter_cdf in the core tests (tests/core/scene_access_stub.cpp).
#pragma once

#include "core/scene_types.h"

namespace tr {
void bind_film_test_camera(const Camera& c);
}
