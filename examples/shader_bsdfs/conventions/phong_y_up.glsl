// A BSDF written in another renderer's convention, for `twinray check-bsdf --convention`
// (validation/shader_bsdf/README.md): the normal is +y, wi is the direction the path arrives in
// (pointing towards the surface), user_eval returns f without the cosine and user_sample returns
// f / pdf. Check it with
//   twinray check-bsdf phong_y_up.glsl --convention cosine=excluded,normal=y,incident=towards
// The BSDF: the modified Phong model of Lafortune & Willems, "Using the Modified Phong
// Reflectance Model for Physically Based Rendering", 1994 (eq. 3):
//   f = kd / pi + ks (e + 2) / (2 pi) cos^e alpha,
// alpha the angle between wo and the mirror direction of wi; energy-conserving for kd + ks <= 1.
// Sampled as a mixture: the lobe about the mirror direction with probability ks / (kd + ks),
// density (e + 1) / (2 pi) cos^e alpha (ibid., §4), else a cosine-weighted hemisphere.
#pragma twinray_param kd 0.5
#pragma twinray_param ks 0.4
#pragma twinray_param e 20.0

const float USER_PI = 3.14159265358979;
const vec3 USER_N = vec3(0.0, 1.0, 0.0);

float cos_alpha(vec3 wi, vec3 wo) { return max(0.0, dot(reflect(wi, USER_N), wo)); }

vec3 user_eval(vec3 wi, vec3 wo, UserParams p) {
  if (wi.y >= 0.0 || wo.y <= 0.0) return vec3(0.0);
  return vec3(p.kd / USER_PI +
              p.ks * (p.e + 2.0) / (2.0 * USER_PI) * pow(cos_alpha(wi, wo), p.e));
}

float user_pdf(vec3 wi, vec3 wo, UserParams p) {
  if (wi.y >= 0.0 || wo.y <= 0.0) return 0.0;
  float lobe = p.ks / (p.kd + p.ks);
  return lobe * (p.e + 1.0) / (2.0 * USER_PI) * pow(cos_alpha(wi, wo), p.e) +
         (1.0 - lobe) * wo.y / USER_PI;
}

// A direction at angle acos(c) from axis a, azimuth phi about it.
vec3 about(vec3 a, float c, float phi) {
  vec3 t = normalize(abs(a.x) > 0.9 ? cross(a, vec3(0.0, 1.0, 0.0)) : cross(a, vec3(1.0, 0.0, 0.0)));
  vec3 b = cross(a, t);
  float s = sqrt(max(0.0, 1.0 - c * c));
  return normalize(s * cos(phi) * t + s * sin(phi) * b + c * a);
}

vec3 user_sample(vec3 wi, vec3 u, UserParams p, out vec3 wo, out float pdf) {
  wo = USER_N;
  pdf = 0.0;
  if (wi.y >= 0.0) return vec3(0.0);
  float lobe = p.ks / (p.kd + p.ks);
  float phi = 2.0 * USER_PI * u.z;
  if (u.x < lobe) {
    wo = about(reflect(wi, USER_N), pow(u.y, 1.0 / (p.e + 1.0)), phi);
  } else {
    wo = about(USER_N, sqrt(u.y), phi);  // cos theta = sqrt(u): density cos theta / pi
  }
  if (wo.y <= 0.0) return vec3(0.0);  // the lobe reached below the horizon: a failed draw
  pdf = user_pdf(wi, wo, p);
  if (!(pdf > 0.0)) {
    pdf = 0.0;
    return vec3(0.0);
  }
  return user_eval(wi, wo, p) / pdf;
}
