#include "widgets/parameter_panel.h"

#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLineEdit>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QToolButton>
#include <optional>

#include "widgets/option_editor.h"

namespace sightline {
namespace {

OptionSpec Spec(std::string key, OptionType type, std::string unit, double min, double max,
                double step, OptionValue default_value, std::vector<std::string> choices = {}) {
  OptionSpec spec;
  spec.key = std::move(key);
  spec.type = type;
  spec.unit = std::move(unit);
  spec.min = min;
  spec.max = max;
  spec.step = step;
  spec.choices = std::move(choices);
  spec.description = "What " + spec.key + " does.";
  spec.default_value = std::move(default_value);
  return spec;
}

OptionSet MakeOptions() {
  OptionSet options;
  EXPECT_TRUE(options
                  .Declare(Spec("mapping.ransac.max_iterations", OptionType::kInt, "", 1, 1000, 1,
                                int64_t{250}))
                  .ok());
  EXPECT_TRUE(options
                  .Declare(Spec("mapping.ransac.threshold", OptionType::kDouble, "m", 0.001, 0.5,
                                0.005, 0.05))
                  .ok());
  EXPECT_TRUE(options.Declare(Spec("mapping.enabled", OptionType::kBool, "", 0, 1, 1, true)).ok());
  EXPECT_TRUE(options
                  .Declare(Spec("mapping.method", OptionType::kChoice, "", 0, 0, 1,
                                std::string("ransac"), {"ransac", "hough"}))
                  .ok());
  EXPECT_TRUE(
      options.Declare(Spec("io.camera_name", OptionType::kString, "", 0, 0, 1, std::string("left")))
          .ok());
  return options;
}

class ParameterPanelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    panel_.SetOptions(MakeOptions());
    QObject::connect(&panel_, &ParameterPanel::OptionsChanged, [this](const OptionSet& options) {
      ++changes_;
      last_ = options;
    });
  }

  template <typename T>
  T* Input(const std::string& key) {
    T* input = qobject_cast<T*>(panel_.InputFor(key));
    EXPECT_NE(input, nullptr) << key;
    return input;
  }

  ParameterPanel panel_;
  int changes_ = 0;
  std::optional<OptionSet> last_;
};

TEST_F(ParameterPanelTest, BuildsAnInputOfTheRightKindPerOption) {
  auto* iterations = Input<QSpinBox>("mapping.ransac.max_iterations");
  ASSERT_NE(iterations, nullptr);
  EXPECT_EQ(iterations->minimum(), 1);
  EXPECT_EQ(iterations->maximum(), 1000);
  EXPECT_EQ(iterations->value(), 250);

  auto* threshold = Input<QDoubleSpinBox>("mapping.ransac.threshold");
  ASSERT_NE(threshold, nullptr);
  EXPECT_DOUBLE_EQ(threshold->minimum(), 0.001);
  EXPECT_DOUBLE_EQ(threshold->maximum(), 0.5);
  EXPECT_DOUBLE_EQ(threshold->singleStep(), 0.005);
  EXPECT_EQ(threshold->decimals(), 3);
  EXPECT_EQ(threshold->suffix(), " m");
  EXPECT_DOUBLE_EQ(threshold->value(), 0.05);
  EXPECT_TRUE(threshold->toolTip().contains("What mapping.ransac.threshold does."));
  EXPECT_TRUE(threshold->toolTip().contains("Default: 0.05 m"))
      << threshold->toolTip().toStdString();

  ASSERT_NE(Input<QCheckBox>("mapping.enabled"), nullptr);
  EXPECT_TRUE(Input<QCheckBox>("mapping.enabled")->isChecked());
  auto* method = Input<QComboBox>("mapping.method");
  ASSERT_NE(method, nullptr);
  EXPECT_EQ(method->count(), 2);
  EXPECT_EQ(method->currentText(), "ransac");
  ASSERT_NE(Input<QLineEdit>("io.camera_name"), nullptr);
  EXPECT_EQ(Input<QLineEdit>("io.camera_name")->text(), "left");
  EXPECT_EQ(panel_.InputFor("no.such.key"), nullptr);
  EXPECT_EQ(changes_, 0) << "SetOptions must not announce a change";
}

TEST_F(ParameterPanelTest, SpinBoxEditEmitsTheNewValue) {
  Input<QDoubleSpinBox>("mapping.ransac.threshold")->setValue(0.125);
  ASSERT_EQ(changes_, 1);
  EXPECT_EQ(std::get<double>(*last_->Get("mapping.ransac.threshold")), 0.125);
  EXPECT_EQ(std::get<double>(*panel_.options().Get("mapping.ransac.threshold")), 0.125);

  Input<QSpinBox>("mapping.ransac.max_iterations")->setValue(500);
  ASSERT_EQ(changes_, 2);
  EXPECT_EQ(std::get<int64_t>(*last_->Get("mapping.ransac.max_iterations")), 500);
}

TEST_F(ParameterPanelTest, OutOfRangeIsClampedToTheSpecRange) {
  Input<QDoubleSpinBox>("mapping.ransac.threshold")->setValue(100.0);
  ASSERT_EQ(changes_, 1);
  EXPECT_DOUBLE_EQ(std::get<double>(*last_->Get("mapping.ransac.threshold")), 0.5);
  Input<QSpinBox>("mapping.ransac.max_iterations")->setValue(-7);
  ASSERT_EQ(changes_, 2);
  EXPECT_EQ(std::get<int64_t>(*last_->Get("mapping.ransac.max_iterations")), 1);
}

TEST_F(ParameterPanelTest, CheckBoxComboAndLineEditEdits) {
  Input<QCheckBox>("mapping.enabled")->setChecked(false);
  Input<QComboBox>("mapping.method")->setCurrentText("hough");
  auto* name = Input<QLineEdit>("io.camera_name");
  name->setText("right");
  emit name->editingFinished();
  ASSERT_EQ(changes_, 3);
  EXPECT_FALSE(std::get<bool>(*last_->Get("mapping.enabled")));
  EXPECT_EQ(std::get<std::string>(*last_->Get("mapping.method")), "hough");
  EXPECT_EQ(std::get<std::string>(*last_->Get("io.camera_name")), "right");
}

TEST_F(ParameterPanelTest, RowResetRestoresTheDefault) {
  auto* threshold = Input<QDoubleSpinBox>("mapping.ransac.threshold");
  OptionEditor* editor = panel_.EditorFor("mapping.ransac.threshold");
  ASSERT_NE(editor, nullptr);
  EXPECT_FALSE(editor->modified());
  threshold->setValue(0.3);
  EXPECT_TRUE(editor->modified());
  auto* reset = editor->findChild<QToolButton*>();
  ASSERT_NE(reset, nullptr);
  ASSERT_TRUE(reset->isEnabled());
  reset->click();
  EXPECT_EQ(changes_, 2);
  EXPECT_DOUBLE_EQ(threshold->value(), 0.05);
  EXPECT_DOUBLE_EQ(std::get<double>(*last_->Get("mapping.ransac.threshold")), 0.05);
  EXPECT_FALSE(editor->modified());
}

TEST_F(ParameterPanelTest, ResetAllRestoresEveryDefault) {
  Input<QSpinBox>("mapping.ransac.max_iterations")->setValue(10);
  Input<QCheckBox>("mapping.enabled")->setChecked(false);
  panel_.ResetAll();
  EXPECT_EQ(Input<QSpinBox>("mapping.ransac.max_iterations")->value(), 250);
  EXPECT_TRUE(Input<QCheckBox>("mapping.enabled")->isChecked());
  EXPECT_EQ(std::get<int64_t>(*last_->Get("mapping.ransac.max_iterations")), 250);
}

TEST_F(ParameterPanelTest, ProfilesRoundTripThroughYaml) {
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  const QString path = dir.filePath("profile.yaml");
  Input<QSpinBox>("mapping.ransac.max_iterations")->setValue(42);
  Input<QDoubleSpinBox>("mapping.ransac.threshold")->setValue(0.2);
  Input<QComboBox>("mapping.method")->setCurrentText("hough");
  ASSERT_TRUE(panel_.SaveProfile(path).ok()) << panel_.message().toStdString();
  ASSERT_TRUE(QFile::exists(path));

  panel_.ResetAll();
  EXPECT_EQ(Input<QSpinBox>("mapping.ransac.max_iterations")->value(), 250);
  const int before = changes_;
  const Status loaded = panel_.LoadProfile(path);
  ASSERT_TRUE(loaded.ok()) << loaded.ToString();
  EXPECT_EQ(changes_, before + 1);
  EXPECT_EQ(Input<QSpinBox>("mapping.ransac.max_iterations")->value(), 42);
  EXPECT_DOUBLE_EQ(Input<QDoubleSpinBox>("mapping.ransac.threshold")->value(), 0.2);
  EXPECT_EQ(Input<QComboBox>("mapping.method")->currentText(), "hough");
  EXPECT_EQ(std::get<int64_t>(*panel_.options().Get("mapping.ransac.max_iterations")), 42);
}

TEST_F(ParameterPanelTest, BadProfileIsReportedAndChangesNothing) {
  QTemporaryDir dir;
  const QString path = dir.filePath("bad.yaml");
  QFile file(path);
  ASSERT_TRUE(file.open(QIODevice::WriteOnly));
  file.write("mapping:\n  ransac:\n    max_iterations: 5000000\n");
  file.close();
  Input<QSpinBox>("mapping.ransac.max_iterations")->setValue(7);
  const int before = changes_;
  EXPECT_FALSE(panel_.LoadProfile(path).ok());
  EXPECT_FALSE(panel_.message().isEmpty());
  EXPECT_EQ(changes_, before);
  EXPECT_EQ(std::get<int64_t>(*panel_.options().Get("mapping.ransac.max_iterations")), 7);

  EXPECT_FALSE(panel_.LoadProfile(dir.filePath("missing.yaml")).ok());
  EXPECT_FALSE(panel_.SaveProfile(dir.filePath("no/such/folder/p.yaml")).ok());
}

TEST_F(ParameterPanelTest, SetOptionsWithSameKeysKeepsTheRows) {
  QWidget* input = panel_.InputFor("mapping.ransac.max_iterations");
  OptionSet options = MakeOptions();
  ASSERT_TRUE(options.Set("mapping.ransac.max_iterations", int64_t{77}).ok());
  panel_.SetOptions(options);
  EXPECT_EQ(panel_.InputFor("mapping.ransac.max_iterations"), input);
  EXPECT_EQ(qobject_cast<QSpinBox*>(input)->value(), 77);
  EXPECT_EQ(changes_, 0);
}

TEST_F(ParameterPanelTest, FilterHidesOtherRows) {
  panel_.show();
  panel_.SetFilter("ransac");
  EXPECT_TRUE(panel_.InputFor("mapping.ransac.threshold")->isVisible());
  EXPECT_FALSE(panel_.InputFor("io.camera_name")->isVisible());
  panel_.SetFilter("");
  EXPECT_TRUE(panel_.InputFor("io.camera_name")->isVisible());
}

TEST(OptionEditorTest, DecimalsFollowStepAndDefault) {
  EXPECT_EQ(DecimalsFor(Spec("a", OptionType::kDouble, "", 0, 1, 0.01, 0.5)), 2);
  EXPECT_EQ(DecimalsFor(Spec("a", OptionType::kDouble, "", 0, 10, 1, 2.0)), 1);
  EXPECT_EQ(DecimalsFor(Spec("a", OptionType::kDouble, "", 0, 1, 0.1, 0.0125)), 4);
}

}  // namespace
}  // namespace sightline
