// ggx_conductor.glsl with Schlick's Fresnel approximation in place of the conductor's exact
// Fresnel reflectance: f0 = 0.9234 is the reflectance of eta + i k = 0.2 + 3i at normal
// incidence, so the two differ at oblique incidence only. A correct BSDF (check-bsdf passes it),
// but not twinray's roughconductor, and
//   twinray check-bsdf ggx_conductor_schlick.glsl --against roughconductor distribution=ggx \
//       alpha=0.3 eta=0.2 k=3
// reports where and by how much. Twinray's convention: local frame, +z the normal, wi and wo
// both pointing away from the surface, user_eval includes |cos theta_o|.
#pragma twinray_param alpha 0.3
#pragma twinray_param f0 0.9234

const float USER_PI = 3.14159265358979;

// D(m) = 1 / (pi a^2 ((mx^2 + my^2) / a^2 + mz^2)^2).
float ggx_d(vec3 m, float a) {
  float t = (m.x * m.x + m.y * m.y) / (a * a) + m.z * m.z;
  return 1.0 / (USER_PI * a * a * t * t);
}

// G1(v) = 2 / (1 + sqrt(1 + a^2 tan^2 theta_v)) (Walter et al. 2007, eq. 34).
float ggx_g1(vec3 v, float a) {
  float tan2 = (v.x * v.x + v.y * v.y) / (v.z * v.z);
  return 2.0 / (1.0 + sqrt(1.0 + a * a * tan2));
}

// Schlick's approximation from the reflectance at normal incidence f0 (Schlick, "An Inexpensive
// BRDF Model for Physically-based Rendering", Computer Graphics Forum 13(3), 1994, eq. 15).
float schlick(float c, float f0) {
  float m = 1.0 - clamp(c, 0.0, 1.0);
  return f0 + (1.0 - f0) * m * m * m * m * m;
}

// Heitz 2018, Listing 1: a normal from D_wi(m) = G1(wi) max(0, wi.m) D(m) / cos theta_i.
vec3 sample_vndf(vec3 wi, float a, vec2 u) {
  vec3 vh = normalize(vec3(a * wi.x, a * wi.y, wi.z));
  float lensq = vh.x * vh.x + vh.y * vh.y;
  vec3 t1 = lensq > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(lensq) : vec3(1.0, 0.0, 0.0);
  vec3 t2 = cross(vh, t1);
  float r = sqrt(u.x);
  float phi = 2.0 * USER_PI * u.y;
  float p1 = r * cos(phi);
  float p2 = r * sin(phi);
  float s = 0.5 * (1.0 + vh.z);
  p2 = (1.0 - s) * sqrt(max(0.0, 1.0 - p1 * p1)) + s * p2;
  vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  return normalize(vec3(a * nh.x, a * nh.y, max(1e-7, nh.z)));
}

// f cos theta_o = F(wi.m) D(m) G1(wi) G1(wo) / (4 cos theta_i).
vec3 user_eval(vec3 wi, vec3 wo, UserParams p) {
  if (wi.z <= 0.0 || wo.z <= 0.0) return vec3(0.0);
  vec3 m = normalize(wi + wo);
  float g = ggx_g1(wi, p.alpha) * ggx_g1(wo, p.alpha);
  return vec3(schlick(dot(wi, m), p.f0) * ggx_d(m, p.alpha) * g / (4.0 * wi.z));
}

// D_wi(m) / (4 wi.m) = G1(wi) D(m) / (4 cos theta_i) (the reflection's Jacobian, Walter 2007,
// eq. 14).
float user_pdf(vec3 wi, vec3 wo, UserParams p) {
  if (wi.z <= 0.0 || wo.z <= 0.0) return 0.0;
  vec3 m = normalize(wi + wo);
  return ggx_g1(wi, p.alpha) * ggx_d(m, p.alpha) / (4.0 * wi.z);
}

// wo is `precise`: user_pdf(wi, wo) below must see the direction returned, not one the
// compiler rewrites, e.g. the half vector of wi and reflect(-wi, m) simplified back to m. Without
// it the sampled pdf and user_pdf at the returned wo differ by ~0.3% at alpha = 0.0025 and
// theta_i = 89.9 degrees (check-bsdf's consistency check finds it).
vec3 user_sample(vec3 wi, vec3 u, UserParams p, out precise vec3 wo, out float pdf) {
  wo = vec3(0.0, 0.0, 1.0);
  pdf = 0.0;
  if (wi.z <= 0.0) return vec3(0.0);
  vec3 m = sample_vndf(wi, p.alpha, u.yz);
  wo = reflect(-wi, m);
  if (wo.z <= 0.0) return vec3(0.0);  // reflected below the horizon: a failed draw
  pdf = user_pdf(wi, wo, p);
  if (!(pdf > 0.0)) {
    pdf = 0.0;
    return vec3(0.0);
  }
  // eval / pdf = F G1(wo)
  return vec3(schlick(dot(wi, m), p.f0) * ggx_g1(wo, p.alpha));
}
