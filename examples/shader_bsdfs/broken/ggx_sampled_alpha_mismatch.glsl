// BROKEN on purpose (a GGX conductor with Schlick's Fresnel and the height-correlated Smith
// term — examples/shader_bsdfs/ggx_conductor_schlick.glsl but for that term — with a bug):
// user_sample draws visible normals of a GGX distribution 1.5 times rougher than the one
// user_pdf and user_eval use, a copy-paste slip between two roughness parameters; the
// chi-square test fails.
#pragma twinray_param alpha 0.3
#pragma twinray_param f0 0.9

const float USER_PI = 3.14159265358979;

// D(m) = 1 / (pi a^2 ((mx^2 + my^2) / a^2 + mz^2)^2) (Walter et al. 2007, eq. 33).
float ggx_d(vec3 m, float a) {
  float t = (m.x * m.x + m.y * m.y) / (a * a) + m.z * m.z;
  return 1.0 / (USER_PI * a * a * t * t);
}

// Smith's Lambda for GGX (Heitz 2014, "Understanding the masking-shadowing function", eq. 72).
float ggx_lambda(vec3 v, float a) {
  float t2 = a * a * (v.x * v.x + v.y * v.y) / (v.z * v.z);
  return 0.5 * (-1.0 + sqrt(1.0 + t2));
}

float schlick(float cos_theta, float f0) {
  float c = 1.0 - clamp(cos_theta, 0.0, 1.0);
  return f0 + (1.0 - f0) * c * c * c * c * c;
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

// f cos theta_o = F D G2 / (4 cos theta_i).
vec3 user_eval(vec3 wi, vec3 wo, UserParams p) {
  if (wi.z <= 0.0 || wo.z <= 0.0) return vec3(0.0);
  vec3 m = normalize(wi + wo);
  float g2 = 1.0 / (1.0 + ggx_lambda(wi, p.alpha) + ggx_lambda(wo, p.alpha));
  return vec3(schlick(dot(wi, m), p.f0) * ggx_d(m, p.alpha) * g2 / (4.0 * wi.z));
}

// D_wi(m) / (4 wi.m) = G1(wi) D(m) / (4 cos theta_i) (the reflection's Jacobian, Walter 2007).
float user_pdf(vec3 wi, vec3 wo, UserParams p) {
  if (wi.z <= 0.0 || wo.z <= 0.0) return 0.0;
  vec3 m = normalize(wi + wo);
  float g1 = 1.0 / (1.0 + ggx_lambda(wi, p.alpha));
  return g1 * ggx_d(m, p.alpha) / (4.0 * wi.z);
}

vec3 user_sample(vec3 wi, vec3 u, UserParams p, out vec3 wo, out float pdf) {
  wo = vec3(0.0, 0.0, 1.0);
  pdf = 0.0;
  if (wi.z <= 0.0) return vec3(0.0);
  vec3 m = sample_vndf(wi, 1.5 * p.alpha, u.yz);
  wo = reflect(-wi, m);
  if (wo.z <= 0.0) return vec3(0.0);  // reflected below the horizon: a failed draw
  pdf = user_pdf(wi, wo, p);
  if (!(pdf > 0.0)) {
    pdf = 0.0;
    return vec3(0.0);
  }
  float lambda_i = ggx_lambda(wi, p.alpha);
  float g1 = 1.0 / (1.0 + lambda_i);
  float g2 = 1.0 / (1.0 + lambda_i + ggx_lambda(wo, p.alpha));
  return vec3(schlick(dot(wi, m), p.f0) * g2 / g1);  // eval / pdf
}
