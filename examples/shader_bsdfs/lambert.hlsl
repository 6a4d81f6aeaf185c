// HLSL copy of lambert.glsl (checked through glslang's HLSL front end).
// A Lambertian reflector for `twinray check-bsdf` (validation/shader_bsdf/README.md): twinray's
// convention (local frame, +z the normal, wi and wo both pointing away from the surface,
// user_eval includes |cos theta_o|).
#pragma twinray_param albedo 0.8

static const float USER_PI = 3.14159265358979;

// f = albedo / pi on the upper hemisphere, times cos theta_o.
float3 user_eval(float3 wi, float3 wo, UserParams p) {
  if (wi.z <= 0.0 || wo.z <= 0.0) return float3(0.0, 0.0, 0.0);
  return (float3)(p.albedo / USER_PI * wo.z);
}

// Cosine-weighted hemisphere: pdf = cos theta_o / pi.
float user_pdf(float3 wi, float3 wo, UserParams p) {
  if (wi.z <= 0.0 || wo.z <= 0.0) return 0.0;
  return wo.z / USER_PI;
}

// Malley's method: a uniform point on the unit disk lifted to the hemisphere (pbrt-v3 13.6.3).
float3 user_sample(float3 wi, float3 u, UserParams p, out float3 wo, out float pdf) {
  wo = float3(0.0, 0.0, 1.0);
  pdf = 0.0;
  if (wi.z <= 0.0) return float3(0.0, 0.0, 0.0);
  float r = sqrt(u.y);
  float phi = 2.0 * USER_PI * u.z;
  wo = float3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u.y)));
  pdf = wo.z / USER_PI;
  if (!(pdf > 0.0)) {
    pdf = 0.0;
    return float3(0.0, 0.0, 0.0);
  }
  return (float3)(p.albedo);  // f cos / pdf
}
