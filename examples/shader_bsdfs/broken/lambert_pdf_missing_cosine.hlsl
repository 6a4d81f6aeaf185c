// HLSL copy of lambert_pdf_missing_cosine.glsl (checked through glslang's HLSL front end).
// BROKEN on purpose (examples/shader_bsdfs/lambert.glsl with a bug): the density forgets the
// cosine, pdf = 1/pi instead of cos theta_o / pi, in user_pdf and in user_sample alike, and the
// weight follows it (eval / pdf), so only the chi-square test can tell; it fails there.
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
  return 1.0 / USER_PI;
}

// Malley's method: a uniform point on the unit disk lifted to the hemisphere (pbrt-v3 13.6.3).
float3 user_sample(float3 wi, float3 u, UserParams p, out float3 wo, out float pdf) {
  wo = float3(0.0, 0.0, 1.0);
  pdf = 0.0;
  if (wi.z <= 0.0) return float3(0.0, 0.0, 0.0);
  float r = sqrt(u.y);
  float phi = 2.0 * USER_PI * u.z;
  wo = float3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u.y)));
  pdf = 1.0 / USER_PI;
  if (!(wo.z > 0.0)) {
    pdf = 0.0;
    return float3(0.0, 0.0, 0.0);
  }
  return (float3)(p.albedo * wo.z);  // f cos / pdf
}
