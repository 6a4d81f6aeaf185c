// A rough conductor for `twinray check-bsdf` (validation/shader_bsdf/README.md), written to be
// Mitsuba 3's `roughconductor` with distribution=ggx: the GGX (Trowbridge-Reitz) distribution
// (Walter et al., "Microfacet Models for Refraction through Rough Surfaces", EGSR 2007, eq. 33),
// the separable Smith masking-shadowing G = G1(wi) G1(wo) (ibid., eq. 23, as Mitsuba evaluates
// it), the exact Fresnel reflectance of a conductor of complex index eta + i k, and sampling of
// the visible normals (Heitz, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4),
// 2018, Listing 1). Check it against twinray's plugin with
//   twinray check-bsdf ggx_conductor.glsl --against roughconductor distribution=ggx alpha=0.3 \
//       eta=0.2 k=3
// Twinray's convention: local frame, +z the normal, wi and wo both pointing away from the
// surface, user_eval includes |cos theta_o|.
#pragma twinray_param alpha 0.3
#pragma twinray_param eta 0.2
#pragma twinray_param k 3.0

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

// Unpolarized reflectance of a conductor, from the Fresnel equations with a complex index
// (Born & Wolf, "Principles of Optics", §14.2; the closed form of pbrt-v3 §8.2.1):
//   a^2 + b^2 = sqrt((eta^2 - k^2 - sin^2)^2 + 4 eta^2 k^2),  a^2 = (a^2 + b^2 + eta^2 - k^2 -
//   sin^2) / 2, Rs = (a^2 + b^2 - 2 a cos + cos^2) / (a^2 + b^2 + 2 a cos + cos^2),
//   Rp = Rs (cos^2 (a^2 + b^2) - 2 a cos sin^2 + sin^4) / (cos^2 (a^2 + b^2) + 2 a cos sin^2 +
//   sin^4).
float fresnel_conductor(float c, float eta, float k) {
  float c2 = c * c;
  float s2 = 1.0 - c2;
  float t = eta * eta - k * k - s2;
  float ab2 = sqrt(t * t + 4.0 * eta * eta * k * k);
  float a = sqrt(max(0.0, 0.5 * (ab2 + t)));
  float rs = (ab2 - 2.0 * a * c + c2) / (ab2 + 2.0 * a * c + c2);
  float rp = rs * (c2 * ab2 - 2.0 * a * c * s2 + s2 * s2) / (c2 * ab2 + 2.0 * a * c * s2 + s2 * s2);
  return 0.5 * (rs + rp);
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
  return vec3(fresnel_conductor(dot(wi, m), p.eta, p.k) * ggx_d(m, p.alpha) * g / (4.0 * wi.z));
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
  return vec3(fresnel_conductor(dot(wi, m), p.eta, p.k) * ggx_g1(wo, p.alpha));
}
