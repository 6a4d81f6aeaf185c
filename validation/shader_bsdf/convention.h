// The conventions a user's BSDF may be written in, and their conversion to twinray's (that of
// validation/bsdf and Mitsuba 3: +z the normal, wi and wo both pointing away from the surface,
// eval and the sample weight including |cos theta_o|), so that one suite checks BSDFs from any
// renderer. `twinray check-bsdf --convention` (README.md, "Conventions").
#pragma once

#include <string>

#include "twinray_validation.h"

namespace tr::shader_bsdf {

struct Convention {
  // user_eval returns f |cos theta_o| and user_sample f |cos theta_o| / pdf (true), or f and
  // f / pdf (false).
  bool eval_includes_cosine = true;
  // The axis of the normal in the user's local frame: 'z', or 'y' (the frame (x, z, -y) of
  // twinray's, a rotation about x that keeps the tangent x).
  char normal_axis = 'z';
  // The user's wi points towards the surface (the direction the path arrives in) instead of
  // away from it; wo points away in both.
  bool incident_towards_surface = false;

  bool is_default() const;
  std::string label() const;  // "cosine=excluded,normal=y,incident=towards"
};

// Parses "key=value[,key=value...]" with keys cosine (included|excluded), normal (z|y) and
// incident (away|towards); throws std::invalid_argument naming the bad item.
Convention parse_convention(const std::string& text);

// The user's BSDF seen in twinray's convention: directions are mapped into the user's frame
// before each call and sampled directions back; eval and sample weights gain |cos theta_o| where
// the user's exclude it. Densities are per solid angle in both frames and pass unchanged.
twinray::validation::BsdfUnderTest in_twinray_convention(
    const twinray::validation::BsdfUnderTest& user, const Convention& convention);

}  // namespace tr::shader_bsdf
