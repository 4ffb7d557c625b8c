#include "app/cli/info_output.h"

#include <cstdio>
#include <string>

#include "core/io/source_description.h"

namespace sightline::cli {

int PrintSourceInfo(const Source& source, bool json) {
  const std::string text = json ? DescribeSourceJson(source) : DescribeSourceText(source);
  std::fputs(text.c_str(), stdout);
  if (!text.empty() && text.back() != '\n') std::fputc('\n', stdout);
  return 0;
}

}  // namespace sightline::cli
