#include "core/io/file_listing.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/common/text_file.h"

namespace sightline {
namespace fs = std::filesystem;

const std::vector<std::string>& ImageExtensions() {
  static const std::vector<std::string> kExtensions = {".png", ".jpg", ".jpeg",
                                                       ".bmp", ".pgm", ".ppm"};
  return kExtensions;
}

bool HasExtension(const std::string& name, const std::vector<std::string>& extensions) {
  for (const std::string& ext : extensions) {
    if (name.size() <= ext.size()) continue;
    const std::string tail = name.substr(name.size() - ext.size());
    if (std::equal(tail.begin(), tail.end(), ext.begin(), [](char a, char b) {
          return std::tolower(static_cast<unsigned char>(a)) ==
                 std::tolower(static_cast<unsigned char>(b));
        })) {
      return true;
    }
  }
  return false;
}

bool NaturalLess(const std::string& a, const std::string& b) {
  size_t i = 0, j = 0;
  auto is_digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  while (i < a.size() && j < b.size()) {
    if (is_digit(a[i]) && is_digit(b[j])) {
      size_t ei = i, ej = j;
      while (ei < a.size() && is_digit(a[ei])) ++ei;
      while (ej < b.size() && is_digit(b[ej])) ++ej;
      // Compare without leading zeros: longer run is larger, else lexicographic.
      size_t si = i, sj = j;
      while (si + 1 < ei && a[si] == '0') ++si;
      while (sj + 1 < ej && b[sj] == '0') ++sj;
      const size_t li = ei - si, lj = ej - sj;
      if (li != lj) return li < lj;
      const int cmp = a.compare(si, li, b, sj, lj);
      if (cmp != 0) return cmp < 0;
      if (ei - i != ej - j) return ei - i < ej - j;  // "01" after "1": stable tie-break.
      i = ei;
      j = ej;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i;
      ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

StatusOr<std::vector<std::string>> ListFiles(const std::string& dir,
                                             const std::vector<std::string>& extensions) {
  if (!DirectoryExists(dir)) return NotFound(dir + ": no such folder");
  std::vector<std::string> names;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code type_ec;
    if (!entry.is_regular_file(type_ec)) continue;
    if (HasExtension(name, extensions)) names.push_back(name);
  }
  if (ec) return Unavailable(dir + ": cannot list folder (" + ec.message() + ")");
  std::sort(names.begin(), names.end(), NaturalLess);
  return names;
}

std::vector<std::string> ListSubfolders(const std::string& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code type_ec;
    if (entry.is_directory(type_ec)) names.push_back(name);
  }
  std::sort(names.begin(), names.end(), NaturalLess);
  return names;
}

std::string BaseName(const std::string& path) {
  std::string p = path;
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  fs::path fp(p);
  std::string name = fp.filename().string();
  if (name == "." || name == "..") {
    std::error_code ec;
    name = fs::weakly_canonical(fp, ec).filename().string();
  }
  return name;
}

}  // namespace sightline
