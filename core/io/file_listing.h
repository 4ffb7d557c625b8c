// Listing dataset folders: files by extension in natural name order ("frame2" < "frame10").
#pragma once

#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline {

// Image extensions the folder readers accept (lower case, with the dot).
const std::vector<std::string>& ImageExtensions();

// True when `name` ends with one of `extensions` (case-insensitive, e.g. ".PNG" matches ".png").
bool HasExtension(const std::string& name, const std::vector<std::string>& extensions);

// Orders names with digit runs compared as numbers: "img2.png" < "img10.png".
bool NaturalLess(const std::string& a, const std::string& b);

// Names (not paths) of the regular files in `dir` with one of `extensions`, in natural order.
// Hidden files are skipped. NotFound when `dir` is not a folder.
StatusOr<std::vector<std::string>> ListFiles(const std::string& dir,
                                             const std::vector<std::string>& extensions);

// Names of the sub-folders of `dir`, in natural order, hidden ones skipped.
std::vector<std::string> ListSubfolders(const std::string& dir);

// The last component of a path ("a/b/c/" -> "c").
std::string BaseName(const std::string& path);

}  // namespace sightline
