// HLSL copy of diffuse_specular_mixture.glsl (checked through glslang's HLSL front end).
// A diffuse + specular mixture in the style of Disney's "principled" BRDF for `twinray
// check-bsdf` (validation/shader_bsdf/README.md): an opaque reflector whose two lobes are
//  - Burley's diffuse with its Fresnel-factor retro-reflection (B. Burley, "Physically-Based
//    Shading at Disney", SIGGRAPH 2012 course notes, §5.3, the base diffuse model), and
//  - a GGX (Trowbridge-Reitz) microfacet specular with Schlick's Fresnel and the height-correlated
//    Smith masking-shadowing term (Burley's §5.6 uses the separable form instead), drawn by
//    Heitz's visible-normal sampling ("Sampling the GGX Distribution of Visible Normals", JCGT
//    7(4), 2018, Listing 1),
// blended as in Disney's BRDF Explorer (brdfs/disney.brdf): the diffuse scaled by 1 - metallic,
// the specular reflectance at normal incidence f0 = lerp(0.08 specular, base_color, metallic).
// Twinray's convention: local frame, +z the normal, wi and wo both pointing away from the
// surface, user_eval includes |cos theta_o|. Parameters lie in [0, 1]; the colour is gray.
//
// Energy: the model is not energy conserving for every parameter set, and the albedo check of
// `twinray check-bsdf` fails where it is not. The diffuse is not reduced by what the specular
// reflects (Burley assumes "no incident diffuse loss"), so near grazing incidence, where
// Schlick's Fresnel takes the specular towards 1, the two lobes add up to more than 1 on smooth
// surfaces; and on rough ones the retro-reflection factor F_D90 = 0.5 + 2 roughness cos^2
// theta_d exceeds 1 and lifts the diffuse albedo per unit base_color to about 1.56 at grazing
// incidence (roughness = 1). The albedo is linear in metallic and in specular (through f0) and
// grows with specular, and at metallic = 1 it is the GGX conductor's, below 1; so it is bounded
// by its value at metallic = 0, specular = 1, where the largest base_color that keeps it <= 1 at
// every theta_i (the worst always at grazing incidence; by Monte Carlo, 90000 stratified draws
// per lobe and angle) is
//   roughness   0     0.1   0.2   0.3   0.5   0.6   0.8   1
//   base_color  0.05  0.25  0.52  0.67  0.74  0.72  0.64  0.56
// (base_color = 0.6 with roughness = 0.1 reaches 1.17 at theta_i = 89.9 degrees). The default
// base_color 0.5 is energy conserving for every roughness >= 0.2, metallic and specular.
// (At roughness 0.05 check-bsdf takes ~20 s: its adaptive quadrature keeps refining the narrow
// specular lobe; the albedo check then fails at grazing incidence, as the table says it must.)
#pragma twinray_param base_color 0.5
#pragma twinray_param roughness 0.5
#pragma twinray_param metallic 0
#pragma twinray_param specular 0.5

static const float USER_PI = 3.14159265358979;
// alpha = roughness^2 (Burley §5.4) floored as disney.brdf does: a narrower GGX would reflect
// almost like a mirror, which this continuous sampler does not model.
static const float USER_MIN_ALPHA = 1e-3;

float mixture_alpha(UserParams p) { return max(p.roughness * p.roughness, USER_MIN_ALPHA); }

float mixture_f0(UserParams p) { return lerp(0.08 * p.specular, p.base_color, p.metallic); }

// (1 - cos theta)^5, the Schlick weight.
float schlick_weight(float cos_theta) {
  float c = 1.0 - clamp(cos_theta, 0.0, 1.0);
  return c * c * c * c * c;
}

// D(m) = 1 / (pi a^2 ((mx^2 + my^2) / a^2 + mz^2)^2) (Walter et al. 2007, eq. 33).
float ggx_d(float3 m, float a) {
  float t = (m.x * m.x + m.y * m.y) / (a * a) + m.z * m.z;
  return 1.0 / (USER_PI * a * a * t * t);
}

// Smith's Lambda for GGX (Heitz 2014, "Understanding the masking-shadowing function", eq. 72).
float ggx_lambda(float3 v, float a) {
  float t2 = a * a * (v.x * v.x + v.y * v.y) / (v.z * v.z);
  return 0.5 * (-1.0 + sqrt(1.0 + t2));
}

// Heitz 2018, Listing 1: a normal from D_wi(m) = G1(wi) max(0, wi.m) D(m) / cos theta_i.
float3 sample_vndf(float3 wi, float a, float2 u) {
  float3 vh = normalize(float3(a * wi.x, a * wi.y, wi.z));
  float lensq = vh.x * vh.x + vh.y * vh.y;
  float3 t1 = lensq > 0.0 ? float3(-vh.y, vh.x, 0.0) * rsqrt(lensq) : float3(1.0, 0.0, 0.0);
  float3 t2 = cross(vh, t1);
  float r = sqrt(u.x);
  float phi = 2.0 * USER_PI * u.y;
  float p1 = r * cos(phi);
  float p2 = r * sin(phi);
  float s = 0.5 * (1.0 + vh.z);
  p2 = (1.0 - s) * sqrt(max(0.0, 1.0 - p1 * p1)) + s * p2;
  float3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  return normalize(float3(a * nh.x, a * nh.y, max(1e-7, nh.z)));
}

// Burley §5.3: f_d = base_color / pi (1 + (F_D90 - 1)(1 - cos theta_i)^5)
// (1 + (F_D90 - 1)(1 - cos theta_o)^5), F_D90 = 0.5 + 2 roughness cos^2 theta_d, theta_d the
// angle between wi (or wo) and the half vector; times 1 - metallic and cos theta_o.
float diffuse_eval(float3 wi, float3 wo, float3 m, UserParams p) {
  float cos_d = dot(wi, m);
  float fd90 = 0.5 + 2.0 * p.roughness * cos_d * cos_d;
  float fi = 1.0 + (fd90 - 1.0) * schlick_weight(wi.z);
  float fo = 1.0 + (fd90 - 1.0) * schlick_weight(wo.z);
  return (1.0 - p.metallic) * p.base_color / USER_PI * fi * fo * wo.z;
}

// f cos theta_o = F(wi.m) D(m) G2(wi, wo) / (4 cos theta_i), F after Schlick (1994, eq. 15),
// G2 = 1 / (1 + Lambda(wi) + Lambda(wo)), Smith's height-correlated masking-shadowing (Heitz 2014).
float specular_eval(float3 wi, float3 wo, float3 m, UserParams p) {
  float a = mixture_alpha(p);
  float f0 = mixture_f0(p);
  float fresnel = f0 + (1.0 - f0) * schlick_weight(dot(wi, m));
  float g2 = 1.0 / (1.0 + ggx_lambda(wi, a) + ggx_lambda(wo, a));
  return fresnel * ggx_d(m, a) * g2 / (4.0 * wi.z);
}

// Cosine-weighted hemisphere: cos theta_o / pi.
float diffuse_pdf(float3 wo) { return wo.z / USER_PI; }

// D_wi(m) / (4 wi.m) = G1(wi) D(m) / (4 cos theta_i): Heitz 2018's density of visible normals
// times the reflection's Jacobian 1 / (4 wo.m) (Walter et al. 2007).
float specular_pdf(float3 wi, float3 m, UserParams p) {
  float a = mixture_alpha(p);
  return ggx_d(m, a) / ((1.0 + ggx_lambda(wi, a)) * 4.0 * wi.z);
}

// The probability of drawing the specular lobe: its share of the two lobes' approximate
// albedos, Schlick's F(cos theta_i) for the specular and (1 - metallic) base_color for the
// diffuse. It depends on wi alone, so user_pdf can recompute it for any wo. Without a diffuse
// lobe every draw is specular.
float specular_probability(float3 wi, UserParams p) {
  float f0 = mixture_f0(p);
  float w_specular = f0 + (1.0 - f0) * schlick_weight(wi.z);
  float w_diffuse = (1.0 - p.metallic) * p.base_color;
  return w_diffuse > 0.0 ? w_specular / (w_specular + w_diffuse) : 1.0;
}

float3 user_eval(float3 wi, float3 wo, UserParams p) {
  if (wi.z <= 0.0 || wo.z <= 0.0) return float3(0.0, 0.0, 0.0);
  float3 m = normalize(wi + wo);
  return (float3)(diffuse_eval(wi, wo, m, p) + specular_eval(wi, wo, m, p));
}

// The one-sample mixture's density: the lobes' densities weighted by the probabilities of
// choosing them (Veach 1997, §9.2.2).
float user_pdf(float3 wi, float3 wo, UserParams p) {
  if (wi.z <= 0.0 || wo.z <= 0.0) return 0.0;
  float3 m = normalize(wi + wo);
  float ps = specular_probability(wi, p);
  return ps * specular_pdf(wi, m, p) + (1.0 - ps) * diffuse_pdf(wo);
}

// u.x picks the lobe, u.yz draw the direction from it; the weight is the whole BSDF over the
// mixture density.
// wo is `precise`: user_pdf(wi, wo) below must see the direction returned, not one the
// compiler rewrites, e.g. the half vector of wi and reflect(-wi, m) simplified back to m. Without
// it the sampled pdf and user_pdf at the returned wo differ by ~0.3% at alpha = 0.0025 and
// theta_i = 89.9 degrees (check-bsdf's consistency check finds it).
float3 user_sample(float3 wi, float3 u, UserParams p, out precise float3 wo, out float pdf) {
  wo = float3(0.0, 0.0, 1.0);
  pdf = 0.0;
  if (wi.z <= 0.0) return float3(0.0, 0.0, 0.0);
  if (u.x < specular_probability(wi, p)) {
    wo = reflect(-wi, sample_vndf(wi, mixture_alpha(p), u.yz));
  } else {
    // Malley's method: a uniform point on the unit disk lifted to the hemisphere (pbrt-v3
    // 13.6.3).
    float r = sqrt(u.y);
    float phi = 2.0 * USER_PI * u.z;
    wo = float3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u.y)));
  }
  if (wo.z <= 0.0) return float3(0.0, 0.0, 0.0);  // reflected below the horizon: a failed draw
  pdf = user_pdf(wi, wo, p);
  if (!(pdf > 0.0)) {
    pdf = 0.0;
    return float3(0.0, 0.0, 0.0);
  }
  return user_eval(wi, wo, p) / pdf;
}
