#include "app/cli/cli_args.h"

#include <algorithm>
#include <cstdio>

#include "app/cli/commands.h"

namespace sightline::cli {

int Fail(const std::string& message) {
  std::fprintf(stderr, "sightline-cli: %s\n", message.c_str());
  return 1;
}

StatusOr<CliArgs> CliArgs::Parse(const std::vector<std::string>& args,
                                 const std::vector<std::string>& value_flags,
                                 const std::vector<std::string>& switches) {
  auto contains = [](const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
  };
  CliArgs parsed;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() < 2 || a.rfind("--", 0) != 0) {
      parsed.positionals_.push_back(a);
      continue;
    }
    std::string flag = a;
    std::optional<std::string> value;
    if (const size_t eq = a.find('='); eq != std::string::npos) {
      flag = a.substr(0, eq);
      value = a.substr(eq + 1);
    }
    if (contains(value_flags, flag)) {
      if (!value) {
        if (i + 1 >= args.size()) return InvalidArgument(flag + " needs a value");
        value = args[++i];
      }
      parsed.flags_.emplace_back(flag, *value);
    } else if (contains(switches, flag)) {
      if (value) return InvalidArgument(flag + " takes no value");
      parsed.flags_.emplace_back(flag, "");
    } else {
      return InvalidArgument("unknown option " + flag + " (see --help)");
    }
  }
  return parsed;
}

bool CliArgs::Has(const std::string& flag) const {
  return std::any_of(flags_.begin(), flags_.end(), [&](const auto& f) { return f.first == flag; });
}

std::optional<std::string> CliArgs::Value(const std::string& flag) const {
  std::optional<std::string> value;
  for (const auto& [f, v] : flags_) {
    if (f == flag) value = v;
  }
  return value;
}

std::vector<std::string> CliArgs::Values(const std::string& flag) const {
  std::vector<std::string> values;
  for (const auto& [f, v] : flags_) {
    if (f == flag) values.push_back(v);
  }
  return values;
}

}  // namespace sightline::cli
