// Minimal argument parsing for sightline-cli commands.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline::cli {

// The arguments of one command: positionals and --flags, in order.
class CliArgs {
 public:
  // `value_flags` take a value (--out DIR or --out=DIR); other --flags are switches.
  static StatusOr<CliArgs> Parse(const std::vector<std::string>& args,
                                 const std::vector<std::string>& value_flags,
                                 const std::vector<std::string>& switches);

  const std::vector<std::string>& positionals() const { return positionals_; }
  bool Has(const std::string& flag) const;
  // The last value given for a flag.
  std::optional<std::string> Value(const std::string& flag) const;
  // Every value given for a repeatable flag (e.g. --set).
  std::vector<std::string> Values(const std::string& flag) const;

 private:
  std::vector<std::string> positionals_;
  std::vector<std::pair<std::string, std::string>> flags_;
};

}  // namespace sightline::cli
