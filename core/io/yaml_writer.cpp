#include "core/io/yaml_writer.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace sightline {
namespace {

std::string Indent(int level) { return std::string(2 * level, ' '); }

// A YAML double-quoted string.
std::string Quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

}  // namespace

YamlWriter::YamlWriter(bool opencv_header) {
  if (opencv_header) text_ << "%YAML:1.0\n---\n";
}

void YamlWriter::Comments(const std::vector<std::string>& lines) {
  for (const std::string& line : lines) {
    std::string one = line;
    for (char& c : one) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    text_ << "# " << one << "\n";
  }
}

void YamlWriter::Number(const std::string& key, double value, int indent) {
  text_ << Indent(indent) << key << ": " << Format(value) << "\n";
}

void YamlWriter::Integer(const std::string& key, long long value, int indent) {
  text_ << Indent(indent) << key << ": " << value << "\n";
}

void YamlWriter::Text(const std::string& key, const std::string& value, int indent) {
  text_ << Indent(indent) << key << ": " << Quoted(value) << "\n";
}

void YamlWriter::Map(const std::string& key, int indent) {
  text_ << Indent(indent) << key << ":\n";
}

void YamlWriter::List(const std::string& key, const std::vector<double>& values, int indent) {
  text_ << Indent(indent) << key << ": [";
  for (size_t i = 0; i < values.size(); ++i) text_ << (i == 0 ? "" : ", ") << Format(values[i]);
  text_ << "]\n";
}

void YamlWriter::Matrix(const std::string& key, const Eigen::MatrixXd& m) {
  text_ << key << ": !!opencv-matrix\n   rows: " << m.rows() << "\n   cols: " << m.cols()
        << "\n   dt: d\n   data: [";
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    for (Eigen::Index c = 0; c < m.cols(); ++c) {
      text_ << (r == 0 && c == 0 ? " " : ", ") << Format(m(r, c));
    }
  }
  text_ << " ]\n";
}

Status YamlWriter::WriteTo(const std::string& path) const {
  std::ofstream out(path);
  if (!out) return Unavailable("cannot write " + path);
  out << text_.str();
  out.flush();
  if (!out) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

std::string YamlWriter::Format(double value) {
  // The shortest of 15 to 17 significant digits that reads back as the same value.
  char text[64];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(text, sizeof(text), "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  std::string s = text;
  // "5" would be an integer to OpenCV; "5." keeps matrices and numbers floating point.
  if (s.find_first_of(".eEn") == std::string::npos) s += ".";
  return s;
}

}  // namespace sightline
