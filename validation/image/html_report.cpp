#include "validation/image/html_report.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "io/temp_file.h"
#include "validation/image/xml_escape.h"

namespace tr {

std::string base64_encode(const std::string& bytes) {
  // RFC 4648 §4.
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 |
                 (unsigned char)bytes[i + 2];
    for (int k = 3; k >= 0; --k) out += alphabet[(v >> (6 * k)) & 63];
  }
  if (i < bytes.size()) {
    unsigned v = (unsigned char)bytes[i] << 16;
    if (i + 1 < bytes.size()) v |= (unsigned char)bytes[i + 1] << 8;
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? alphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

namespace {

std::string number(double v, const char* fmt = "%.4g") {
  if (std::isnan(v)) return "n/a";
  if (std::isinf(v)) return v > 0 ? "&infin;" : "-&infin;";
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

std::string verdict_badge(bool passed) {
  return std::string("<span class=\"verdict ") + (passed ? "pass\">PASS" : "fail\">FAIL") +
         "</span>";
}

std::string embedded_image(const ReportImage& image) {
  std::ifstream in(image.png_path, std::ios::binary);
  if (!in) throw FileError(image.png_path + ": cannot read image for the report");
  std::stringstream bytes;
  bytes << in.rdbuf();
  return "<figure><img src=\"data:image/png;base64," + base64_encode(bytes.str()) + "\" alt=\"" +
         xml_escape(image.caption) + "\"><figcaption>" + xml_escape(image.caption) +
         "</figcaption></figure>";
}

std::string test_row(const HypothesisTestResult& t) {
  const char* channels = "XYZ";
  std::string where = t.min_p_channel >= 0
                          ? "cell (" + std::to_string(t.min_p_x) + ", " +
                                std::to_string(t.min_p_y) + ") " + channels[t.min_p_channel]
                          : "";
  return "<tr><td>" + t.name + "</td><td>" + verdict_badge(t.passed) + "</td><td>" +
         std::to_string(t.failing_values) + " / " + std::to_string(t.values) + "</td><td>" +
         number(t.alpha, "%.3g") + "</td><td>" + number(t.min_p, "%.3g") + "</td><td>" + where +
         "</td></tr>\n";
}

std::string comparison_html(const ReportComparison& c) {
  const CompareReport& r = c.report;
  std::ostringstream h;
  h << "<div class=\"comparison\"><h3>" << xml_escape(c.title) << " "
    << (r.criteria.empty() ? "<span class=\"verdict none\">no criteria</span>"
                           : verdict_badge(r.passed))
    << "</h3>\n<div class=\"images\">";
  for (const ReportImage& img : c.heatmaps) h << embedded_image(img);
  h << "</div>\n<table class=\"metrics\"><tr><th>MSE</th><th>RMSE</th><th>relMSE</th>"
       "<th>MAPE</th><th>PSNR (dB)</th><th>SSIM</th><th>LDR-FLIP</th></tr><tr><td>"
    << number(r.metrics.mse) << "</td><td>" << number(r.metrics.rmse) << "</td><td>"
    << number(r.metrics.relmse) << "</td><td>" << number(r.metrics.mape) << "</td><td>"
    << number(r.metrics.psnr, "%.2f") << "</td><td>"
    << (r.ssim ? number(r.ssim->mean, "%.5f") : "n/a") << "</td><td>" << number(r.flip.mean, "%.5f")
    << "</td></tr></table>\n";
  h << "<table class=\"tests\"><tr><th>check</th><th>verdict</th><th>failing values</th>"
       "<th>&alpha; per value</th><th>min p</th><th>at</th></tr>\n";
  for (const std::optional<HypothesisTestResult>* t : r.tests())
    if (*t) h << test_row(**t);
  const LockstepResult& l = r.lockstep;
  h << "<tr><td>lockstep" << (r.lockstep_decides ? "" : " (informational)") << "</td><td>"
    << (r.lockstep_decides ? verdict_badge(l.passed) : "<span class=\"verdict none\">info</span>")
    << "</td><td>" << l.pixels_outside << " / " << l.pixels << " pixels, " << l.systematic_cells
    << " systematic, " << l.clustered_windows << " clustered windows</td><td>"
    << number(l.block_alpha, "%.3g") << "</td><td></td><td>"
    << (l.worst.empty()
            ? std::string()
            : "worst (" + std::to_string(l.worst[0].x) + ", " + std::to_string(l.worst[0].y) + ")")
    << "</td></tr>\n</table>\n";
  if (!r.failures.empty()) {
    h << "<ul class=\"failures\">";
    for (const std::string& f : r.failures) h << "<li>" << xml_escape(f) << "</li>";
    h << "</ul>\n";
  }
  if (!r.notes.empty()) {
    h << "<ul class=\"notes\">";
    for (const std::string& n : r.notes) h << "<li>" << xml_escape(n) << "</li>";
    h << "</ul>\n";
  }
  h << "</div>\n";
  return h.str();
}

const char* kStyle = R"(
body { font-family: sans-serif; margin: 2em; color: #222; }
table { border-collapse: collapse; margin: 0.5em 0; }
td, th { border: 1px solid #ccc; padding: 0.2em 0.6em; text-align: left; font-size: 0.9em; }
.verdict { font-weight: bold; padding: 0.1em 0.5em; border-radius: 0.3em; color: white; }
.verdict.pass { background: #2a7d2a; } .verdict.fail { background: #b22222; }
.verdict.none { background: #777; }
.images { display: flex; flex-wrap: wrap; gap: 1em; }
figure { margin: 0; text-align: center; }
figure img { width: 192px; image-rendering: pixelated; border: 1px solid #ccc; }
figcaption { font-size: 0.8em; }
section.scene { border-top: 2px solid #444; margin-top: 2em; }
.error { color: #b22222; font-weight: bold; }
)";

// Marks <body> with how many embedded images decoded.
const char* kScript = R"(
window.addEventListener('load', () => {
  const images = Array.from(document.images);
  const decoded = images.filter(i => i.complete && i.naturalWidth > 0).length;
  document.body.dataset.imagesDecoded = decoded + '/' + images.length;
});
)";

}  // namespace

std::string html_report(const std::string& title, const std::vector<ReportScene>& scenes) {
  std::ostringstream h;
  size_t passed = 0;
  for (const ReportScene& s : scenes) passed += s.passed && s.error.empty();
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>"
    << xml_escape(title) << "</title><style>" << kStyle << "</style><script>" << kScript
    << "</script></head>\n<body>\n<h1>" << xml_escape(title) << "</h1>\n<p id=\"summary\">"
    << passed << " of " << scenes.size()
    << " scenes pass.</p>\n<table class=\"summary\"><tr><th>scene</th>"
    << "<th>verdict</th></tr>\n";
  for (size_t i = 0; i < scenes.size(); ++i)
    h << "<tr><td><a href=\"#scene-" << i << "\">" << xml_escape(scenes[i].name) << "</a></td><td>"
      << verdict_badge(scenes[i].passed && scenes[i].error.empty()) << "</td></tr>\n";
  h << "</table>\n";
  for (size_t i = 0; i < scenes.size(); ++i) {
    const ReportScene& s = scenes[i];
    bool ok = s.passed && s.error.empty();
    h << "<section class=\"scene\" id=\"scene-" << i << "\" data-verdict=\""
      << (ok ? "pass" : "fail") << "\">\n<h2>" << xml_escape(s.name) << " " << verdict_badge(ok)
      << "</h2>\n";
    if (!s.error.empty()) h << "<p class=\"error\">" << xml_escape(s.error) << "</p>\n";
    if (!s.facts.empty()) {
      h << "<table class=\"facts\">";
      for (const auto& [label, value] : s.facts)
        h << "<tr><th>" << xml_escape(label) << "</th><td>" << xml_escape(value) << "</td></tr>";
      h << "</table>\n";
    }
    h << "<div class=\"images\">";
    for (const ReportImage& img : s.images) h << embedded_image(img);
    h << "</div>\n";
    for (const ReportComparison& c : s.comparisons) h << comparison_html(c);
    h << "</section>\n";
  }
  h << "</body></html>\n";
  return h.str();
}

}  // namespace tr
