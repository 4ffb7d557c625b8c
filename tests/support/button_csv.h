// button.csv as the tests read it: numeric columns by name ("nan" and words read as NaN).
#pragma once

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace sightline::testing {

struct CsvColumns {
  std::vector<std::string> header;
  std::map<std::string, std::vector<double>> columns;
  size_t rows = 0;

  double At(const std::string& column, size_t row) const {
    auto it = columns.find(column);
    return it == columns.end() || row >= it->second.size() ? std::nan("") : it->second[row];
  }
};

inline CsvColumns ReadCsvColumns(const std::string& path) {
  CsvColumns csv;
  std::ifstream in(path);
  std::string line, field;
  if (!std::getline(in, line)) return csv;
  std::stringstream head(line);
  while (std::getline(head, field, ',')) csv.header.push_back(field);
  while (std::getline(in, line)) {
    std::stringstream row(line);
    for (size_t i = 0; i < csv.header.size() && std::getline(row, field, ','); ++i) {
      char* end = nullptr;
      const double v = std::strtod(field.c_str(), &end);
      csv.columns[csv.header[i]].push_back(end == field.c_str() ? std::nan("") : v);
    }
    ++csv.rows;
  }
  return csv;
}

}  // namespace sightline::testing
