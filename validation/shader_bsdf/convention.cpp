#include "convention.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tr::shader_bsdf {

namespace validation = twinray::validation;

bool Convention::is_default() const {
  return eval_includes_cosine && normal_axis == 'z' && !incident_towards_surface;
}

std::string Convention::label() const {
  return std::string("cosine=") + (eval_includes_cosine ? "included" : "excluded") +
         ",normal=" + normal_axis + ",incident=" + (incident_towards_surface ? "towards" : "away");
}

Convention parse_convention(const std::string& text) {
  Convention c;
  std::istringstream items(text);
  std::string item;
  bool any = false;
  while (std::getline(items, item, ',')) {
    any = true;
    const std::size_t eq = item.find('=');
    const std::string key = item.substr(0, eq);
    const std::string value = eq == std::string::npos ? "" : item.substr(eq + 1);
    if (key == "cosine" && (value == "included" || value == "excluded")) {
      c.eval_includes_cosine = value == "included";
    } else if (key == "normal" && (value == "z" || value == "y")) {
      c.normal_axis = value[0];
    } else if (key == "incident" && (value == "away" || value == "towards")) {
      c.incident_towards_surface = value == "towards";
    } else {
      throw std::invalid_argument("--convention: '" + item +
                                  "' is none of cosine=included|excluded, normal=z|y, "
                                  "incident=away|towards");
    }
  }
  if (!any) throw std::invalid_argument("--convention: no key=value given");
  return c;
}

namespace {

glm::vec3 to_user_frame(const glm::vec3& w, char normal_axis) {
  return normal_axis == 'y' ? glm::vec3(w.x, w.z, -w.y) : w;
}

glm::vec3 from_user_frame(const glm::vec3& w, char normal_axis) {
  return normal_axis == 'y' ? glm::vec3(w.x, -w.z, w.y) : w;
}

}  // namespace

validation::BsdfUnderTest in_twinray_convention(const validation::BsdfUnderTest& user,
                                                const Convention& convention) {
  if (convention.is_default()) return user;
  const Convention c = convention;
  validation::BsdfUnderTest b = user;
  auto user_wi = [c](const glm::vec3& wi) {
    return to_user_frame(c.incident_towards_surface ? -wi : wi, c.normal_axis);
  };
  // In twinray's frame cos theta_o is wo.z.
  auto cosine_factor = [c](const glm::vec3& wo) {
    return c.eval_includes_cosine ? 1.0f : std::abs(wo.z);
  };
  const validation::SampleFunction sample = user.sample;
  b.sample = [=](const glm::vec3& wi, float u1, const glm::vec2& u2) {
    validation::BsdfSample s = sample(user_wi(wi), u1, u2);
    s.wo = from_user_frame(s.wo, c.normal_axis);
    s.weight *= cosine_factor(s.wo);
    return s;
  };
  const validation::PdfFunction pdf = user.pdf;
  b.pdf = [=](const glm::vec3& wi, const glm::vec3& wo) {
    return pdf(user_wi(wi), to_user_frame(wo, c.normal_axis));
  };
  if (user.eval) {
    const validation::EvalFunction eval = user.eval;
    b.eval = [=](const glm::vec3& wi, const glm::vec3& wo) {
      return eval(user_wi(wi), to_user_frame(wo, c.normal_axis)) * cosine_factor(wo);
    };
  }
  b.eval_includes_cosine = true;
  return b;
}

}  // namespace tr::shader_bsdf
