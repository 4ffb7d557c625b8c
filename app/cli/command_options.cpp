#include <cstdio>

#include "app/cli/cli_args.h"
#include "app/cli/commands.h"
#include "app/cli/program_pipelines.h"
#include "core/pipeline/pipeline_registry.h"

namespace sightline::cli {

int OptionsCommand(const std::vector<std::string>& args) {
  static const char kHelp[] =
      "usage: sightline-cli options [PIPELINE] [--yaml]\n"
      "\n"
      "Without PIPELINE, lists the pipelines. With it, prints every option: key, type, default,\n"
      "range and unit, and what it does. --yaml prints a complete profile to start from.\n";
  StatusOr<CliArgs> parsed = CliArgs::Parse(args, {}, {"--yaml", "--help"});
  if (!parsed.ok()) return Fail("options: " + parsed.status().message());
  if (parsed->Has("--help")) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  const PipelineRegistry registry = ProgramPipelines();
  if (parsed->positionals().empty()) {
    for (const PipelineInfo& p : registry.pipelines()) {
      std::printf("%-14s %s\n", p.name.c_str(), p.summary.c_str());
    }
    return 0;
  }
  const PipelineInfo* pipeline = registry.Find(parsed->positionals()[0]);
  if (pipeline == nullptr)
    return Fail("options: unknown pipeline '" + parsed->positionals()[0] + "'");
  OptionSet options;
  if (pipeline->declare_options) {
    Status s = pipeline->declare_options(&options);
    if (!s.ok()) return Fail(s.ToString());
  }
  if (parsed->Has("--yaml")) {
    std::fputs(options.ToYaml().c_str(), stdout);
    return 0;
  }
  for (const OptionSpec& spec : options.specs()) {
    std::string range;
    if (spec.type == OptionType::kInt || spec.type == OptionType::kDouble) {
      range = "[" + FormatOptionValue(spec.min) + ", " + FormatOptionValue(spec.max) + "]";
    } else if (spec.type == OptionType::kChoice) {
      for (const auto& c : spec.choices) range += (range.empty() ? "{" : "|") + c;
      range += "}";
    }
    std::printf("%-40s %-7s %-10s %-22s %-6s %s\n", spec.key.c_str(), OptionTypeName(spec.type),
                FormatOptionValue(spec.default_value).c_str(), range.c_str(), spec.unit.c_str(),
                spec.description.c_str());
  }
  return 0;
}

}  // namespace sightline::cli
