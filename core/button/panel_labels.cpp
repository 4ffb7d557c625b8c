#include "core/button/panel_labels.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace sightline {

namespace {

bool ParseNumber(const std::string& text, double* value) {
  char* end = nullptr;
  *value = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size() && std::isfinite(*value);
}

}  // namespace

StatusOr<std::vector<PanelLabel>> ReadPanelLabels(const std::string& path) {
  std::ifstream in(path);
  if (!in.good()) return NotFound("cannot read panel labels " + path);
  std::vector<PanelLabel> labels;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const std::string where = path + " line " + std::to_string(number) + ": ";
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, ',')) f.push_back(field);
    if (f.size() < 4) return InvalidArgument(where + "expected file,kind,x0,y0[,x1,y1,name]");
    f.resize(7);
    PanelLabel l;
    l.file = f[0];
    l.name = f[6];
    double v[4] = {0, 0, 0, 0};
    const int needed = f[1] == "blank" ? 2 : 4;
    for (int i = 0; i < needed; ++i) {
      if (!ParseNumber(f[2 + i], &v[i])) {
        return InvalidArgument(where + "field " + std::to_string(3 + i) + " '" + f[2 + i] +
                               "' is not a number");
      }
    }
    if (f[1] == "button" || f[1] == "label") {
      if (v[2] < v[0] || v[3] < v[1]) return InvalidArgument(where + "box corners out of order");
      l.kind = f[1] == "button" ? PanelLabel::Kind::kButton : PanelLabel::Kind::kLabel;
      l.box = cv::Rect2d(v[0], v[1], v[2] - v[0] + 1, v[3] - v[1] + 1);
      l.tap = {0.5 * (v[0] + v[2]), 0.5 * (v[1] + v[3])};
    } else if (f[1] == "blank") {
      l.kind = PanelLabel::Kind::kBlank;
      l.tap = {v[0], v[1]};
    } else {
      return InvalidArgument(where + "unknown kind '" + f[1] + "' (button, label or blank)");
    }
    labels.push_back(std::move(l));
  }
  return labels;
}

std::map<std::string, std::vector<const PanelLabel*>> ByPhoto(const std::vector<PanelLabel>& all) {
  std::map<std::string, std::vector<const PanelLabel*>> out;
  for (const PanelLabel& l : all) out[l.file].push_back(&l);
  return out;
}

}  // namespace sightline
