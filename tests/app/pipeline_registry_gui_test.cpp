// The GUI runs the core registry's pipelines: its Pipeline menu lists them all, and a profile
// saved by either front end loads in the other, for every pipeline.
#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>

#include "app/sightline/builtin_presenters.h"
#include "app/sightline/main_window.h"
#include "core/pipeline/pipeline_registry.h"
#include "tests/support/test_data.h"
#include "widgets/parameter_panel.h"

namespace sightline {
namespace {

TEST(GuiPipelines, OnePresenterPerRegistryPipelineInItsOrder) {
  const PipelineRegistry registry = BuiltinPipelines();
  const std::vector<PipelinePresenter*> presenters = MakeBuiltinPresenters();
  ASSERT_EQ(presenters.size(), registry.pipelines().size());
  for (size_t i = 0; i < presenters.size(); ++i) {
    EXPECT_EQ(presenters[i]->info().name, registry.pipelines()[i].name);
    EXPECT_TRUE(static_cast<bool>(presenters[i]->info().create))
        << registry.pipelines()[i].name << ": the GUI must run the core object";
  }
  for (PipelinePresenter* p : presenters) delete p;
}

// An option value other than the default, inside the option's range.
OptionValue OtherValue(const OptionSpec& spec) {
  switch (spec.type) {
    case OptionType::kBool:
      return !std::get<bool>(spec.default_value);
    case OptionType::kInt: {
      const int64_t d = std::get<int64_t>(spec.default_value);
      return d + 1 <= spec.max ? d + 1 : d - 1;
    }
    case OptionType::kDouble: {
      const double d = std::get<double>(spec.default_value);
      const double step = spec.step > 0 ? spec.step : 0.001;
      return d + step <= spec.max ? d + step : d - step;
    }
    case OptionType::kChoice:
      for (const std::string& c : spec.choices) {
        if (c != std::get<std::string>(spec.default_value)) return c;
      }
      return spec.default_value;
    case OptionType::kString:
      return std::string("profile-round-trip");
  }
  return spec.default_value;
}

// Changes up to 8 options spread over the set; returns their keys.
std::vector<std::string> ChangeSome(OptionSet* options) {
  std::vector<std::string> keys;
  const size_t n = options->specs().size();
  for (size_t i = 0; i < n && keys.size() < 8; i += std::max<size_t>(1, n / 8)) {
    const OptionSpec spec = options->specs()[i];
    if (spec.type == OptionType::kString) continue;  // Paths must exist to be useful.
    if (options->Set(spec.key, OtherValue(spec)).ok()) keys.push_back(spec.key);
  }
  return keys;
}

TEST(GuiPipelines, ProfilesRoundTripBetweenTheGuiAndTheCliForEveryPipeline) {
  MainWindow window;
  std::vector<PipelinePresenter*> presenters = MakeBuiltinPresenters();
  for (PipelinePresenter* p : presenters) window.AddPipeline(p);
  auto* panel = window.findChild<ParameterPanel*>();
  ASSERT_NE(panel, nullptr);
  const std::string dir = testing::TempDir("profile_round_trip");
  for (PipelinePresenter* p : presenters) {
    const PipelineInfo& info = p->info();
    SCOPED_TRACE(info.name);
    ASSERT_TRUE(window.ActivatePipeline(p->Title()));

    // The CLI writes a profile (as `sightline-cli options NAME --yaml` does); the GUI loads it.
    OptionSet cli;
    ASSERT_TRUE(info.declare_options(&cli).ok());
    const std::vector<std::string> changed = ChangeSome(&cli);
    ASSERT_FALSE(changed.empty());
    const std::string from_cli = dir + "/" + info.name + "_cli.yaml";
    ASSERT_TRUE(cli.SaveYaml(from_cli).ok());
    const Status loaded = panel->LoadProfile(QString::fromStdString(from_cli));
    ASSERT_TRUE(loaded.ok()) << loaded.ToString();
    for (const std::string& key : changed) {
      EXPECT_EQ(FormatOptionValue(*panel->options().Get(key)), FormatOptionValue(*cli.Get(key)))
          << key;
    }

    // The GUI saves it again; the CLI's option set loads it with the same values.
    const std::string from_gui = dir + "/" + info.name + "_gui.yaml";
    ASSERT_TRUE(panel->SaveProfile(QString::fromStdString(from_gui)).ok());
    OptionSet cli_again;
    ASSERT_TRUE(info.declare_options(&cli_again).ok());
    const Status read = cli_again.LoadYaml(from_gui);
    ASSERT_TRUE(read.ok()) << read.ToString();
    for (const OptionSpec& spec : cli.specs()) {
      EXPECT_EQ(FormatOptionValue(*cli_again.Get(spec.key)), FormatOptionValue(*cli.Get(spec.key)))
          << spec.key;
    }
  }
}

// A lab laptop's 1280x800 screen holds the window with any pipeline's docks (the operator panel's
// 15 mm controls included): no pipeline makes the window's minimum size larger than the screen.
TEST(GuiPipelines, EveryPipelinesWindowFitsA1280By800Screen) {
  MainWindow window;
  std::vector<PipelinePresenter*> presenters = MakeBuiltinPresenters();
  for (PipelinePresenter* p : presenters) window.AddPipeline(p);
  window.show();
  for (PipelinePresenter* p : presenters) {
    SCOPED_TRACE(p->info().name);
    ASSERT_TRUE(window.ActivatePipeline(p->Title()));
    QApplication::processEvents();
    const QSize least = window.minimumSizeHint().expandedTo(window.minimumSize());
    EXPECT_LE(least.width(), 1280);
    EXPECT_LE(least.height(), 800 - 40);  // Room for a panel or title bar.
  }
}

// `sightline --profile FILE --set KEY=VALUE` (and --operator with them): the profile, then the
// assignments, reach the active pipeline's options; a bad one changes nothing and names itself.
TEST(GuiPipelines, CommandLineProfileAndSetReachThePipelinesOptionsAllOrNothing) {
  MainWindow window;
  for (PipelinePresenter* p : MakeBuiltinPresenters()) window.AddPipeline(p);
  auto* panel = window.findChild<ParameterPanel*>();
  ASSERT_NE(panel, nullptr);
  ASSERT_TRUE(window.ActivatePipelineByWord("button"));
  const std::string profile = testing::TempDir("gui_arguments") + "/serve.yaml";
  {
    OptionSet written;
    ASSERT_TRUE(BuiltinPipelines().Find("button")->declare_options(&written).ok());
    ASSERT_TRUE(written.ApplyOverride("button.arm.port=6001").ok());
    ASSERT_TRUE(written.SaveYaml(profile).ok());
  }
  const Status applied = window.ApplyOptionArguments(
      QString::fromStdString(profile), {"button.gui.serve=true", "button.arm.port=6002"});
  ASSERT_TRUE(applied.ok()) << applied.ToString();
  EXPECT_EQ(FormatOptionValue(*panel->options().Get("button.gui.serve")), "true");
  EXPECT_EQ(FormatOptionValue(*panel->options().Get("button.arm.port")), "6002");  // --set last.

  // A bad assignment after good ones: nothing changes, and the error names the key.
  const Status bad =
      window.ApplyOptionArguments({}, {"button.gui.serve=false", "button.arm.no_such_key=1"});
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("button.arm.no_such_key"), std::string::npos) << bad.ToString();
  EXPECT_EQ(FormatOptionValue(*panel->options().Get("button.gui.serve")), "true");
  // A missing profile names its file and changes nothing either.
  const Status missing = window.ApplyOptionArguments("/nonexistent/profile.yaml", {});
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.message().find("/nonexistent/profile.yaml"), std::string::npos);
  EXPECT_EQ(FormatOptionValue(*panel->options().Get("button.arm.port")), "6002");
}

// The mapping pipeline's pose source and its RGB-D odometry options are in its tuning panel
// (built from Describe()), and --set reaches them.
TEST(GuiPipelines, MappingsPoseSourceIsInItsTuningPanel) {
  MainWindow window;
  for (PipelinePresenter* p : MakeBuiltinPresenters()) window.AddPipeline(p);
  auto* panel = window.findChild<ParameterPanel*>();
  ASSERT_NE(panel, nullptr);
  ASSERT_TRUE(window.ActivatePipelineByWord("mapping"));
  auto* source = qobject_cast<QComboBox*>(panel->InputFor("mapping.pose.source"));
  ASSERT_NE(source, nullptr);
  QStringList choices;
  for (int i = 0; i < source->count(); ++i) choices << source->itemText(i);
  EXPECT_EQ(choices, QStringList({"auto", "recording", "rgbd", "none"}));
  EXPECT_EQ(source->currentText(), "auto");
  for (const char* key : {"mapping.pose.rgbd.method", "mapping.pose.rgbd.keyframe_translation_m",
                          "mapping.pose.rgbd.max_gap_s", "mapping.pose.rgbd.feature_guess"}) {
    EXPECT_NE(panel->InputFor(key), nullptr) << key;
  }
  ASSERT_TRUE(window.ApplyOptionArguments({}, {"mapping.pose.source=rgbd"}).ok());
  EXPECT_EQ(FormatOptionValue(*panel->options().Get("mapping.pose.source")), "rgbd");
}

}  // namespace
}  // namespace sightline
