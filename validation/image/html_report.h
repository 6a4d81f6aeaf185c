// A self-contained HTML validation report: every image is embedded as a base64 data URI, so
// the single file can be archived or attached to CI. Per scene: verdict, side-by-side images,
// error heatmaps, metrics and every hypothesis test with its p-value; a summary table first.
//
// On load, a small script checks that every embedded image decoded and records the result in
// <body data-images-decoded="k/n">, so a headless browser can prove the page renders.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "validation/image/compare.h"

namespace tr {

struct ReportImage {
  std::string caption;
  std::string png_path;  // read and embedded when the report is written
};

struct ReportComparison {
  std::string title;  // e.g. "CPU vs Mitsuba reference"
  CompareReport report;
  std::vector<ReportImage> heatmaps;
};

struct ReportScene {
  std::string name;
  bool passed = false;
  std::string error;  // non-empty: the scene could not be rendered or compared (fails)
  std::vector<std::pair<std::string, std::string>> facts;  // (label, value): spp, seconds, ...
  std::vector<ReportImage> images;                         // renders and reference, side by side
  std::vector<ReportComparison> comparisons;
};

// The report as one HTML document. Throws FileError when an image cannot be read.
std::string html_report(const std::string& title, const std::vector<ReportScene>& scenes);

std::string base64_encode(const std::string& bytes);

}  // namespace tr
