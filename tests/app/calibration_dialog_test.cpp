// The calibration dialog headless on calib_chessboard: the figures it shows match the reference
// (RMS left 0.408, right 0.458, stereo 0.447 px, baseline 83.6 mm), the table lists every view,
// the corner and coverage views have images, and the saved YAML loads back.
#include "app/sightline/calibration_dialog.h"

#include <gtest/gtest.h>

#include <QRegularExpression>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTest>

#include "core/io/camera_yaml.h"
#include "core/io/stereo_calibration_file.h"
#include "tests/support/test_data.h"
#include "widgets/image_view.h"

namespace sightline {
namespace {

// The number after `label` in `text`, or NaN.
double NumberAfter(const QString& text, const QString& label) {
  const QRegularExpression re(QRegularExpression::escape(label) + "\\s*([0-9.]+)");
  const auto match = re.match(text);
  return match.hasMatch() ? match.captured(1).toDouble() : std::nan("");
}

bool RunAndWait(CalibrationDialog* dialog, QSignalSpy* finished, QSignalSpy* failed) {
  return QTest::qWaitFor([&] { return finished->count() + failed->count() > 0; }, 120000);
}

TEST(CalibrationDialog, StereoCalibrationShowsTheReferenceFigures) {
  SIGHTLINE_REQUIRE_DATA(dir, "calib_chessboard");
  CalibrationDialog dialog;
  dialog.show();
  QSignalSpy finished(&dialog, &CalibrationDialog::Finished);
  QSignalSpy failed(&dialog, &CalibrationDialog::Failed);
  dialog.Calibrate(true, QString::fromStdString(dir), "*", 9, 6, 0.025);
  ASSERT_TRUE(RunAndWait(&dialog, &finished, &failed));
  ASSERT_EQ(failed.count(), 0) << failed.front().front().toString().toStdString();
  const QString figures = dialog.FiguresText();
  EXPECT_NEAR(NumberAfter(figures, "RMS left"), 0.408, 0.01) << figures.toStdString();
  EXPECT_NEAR(NumberAfter(figures, "right"), 0.458, 0.01) << figures.toStdString();
  EXPECT_NEAR(NumberAfter(figures, "stereo"), 0.447, 0.01) << figures.toStdString();
  EXPECT_NEAR(NumberAfter(figures, "baseline"), 83.6, 0.836) << figures.toStdString();
  ASSERT_EQ(dialog.view_errors()->rowCount(), 13);
  EXPECT_EQ(dialog.view_errors()->item(0, 0)->text(), "left01.jpg | right01.jpg");
  EXPECT_GT(dialog.view_errors()->item(1, 1)->text().toDouble(), 1.0);  // left02: the worst.
  EXPECT_FALSE(dialog.corner_view()->image().isNull());
  EXPECT_EQ(dialog.corner_view()->image().width(), 640);
  EXPECT_FALSE(dialog.coverage_view()->image().isNull());

  const std::string path = ::sightline::testing::TempDir("dialog_stereo") + "/rig.yaml";
  QString error;
  ASSERT_TRUE(dialog.SaveTo(QString::fromStdString(path), &error)) << error.toStdString();
  auto rig = ReadStereoCalibration(path);
  ASSERT_TRUE(rig.ok()) << rig.status().ToString();
  EXPECT_NEAR(rig->BaselineM(), 0.0836, 0.000836);
}

TEST(CalibrationDialog, MonoCalibrationOfTheLeftImages) {
  SIGHTLINE_REQUIRE_DATA(dir, "calib_chessboard");
  CalibrationDialog dialog;
  QSignalSpy finished(&dialog, &CalibrationDialog::Finished);
  QSignalSpy failed(&dialog, &CalibrationDialog::Failed);
  dialog.Calibrate(false, QString::fromStdString(dir), "left*.jpg", 9, 6, 0.025);
  ASSERT_TRUE(RunAndWait(&dialog, &finished, &failed));
  ASSERT_EQ(failed.count(), 0) << failed.front().front().toString().toStdString();
  EXPECT_NEAR(NumberAfter(dialog.FiguresText(), "RMS"), 0.408, 0.01);
  EXPECT_NEAR(NumberAfter(dialog.FiguresText(), "fx"), 536.06, 536.06 * 0.01);
  EXPECT_EQ(dialog.view_errors()->rowCount(), 13);
  const std::string path = ::sightline::testing::TempDir("dialog_mono") + "/camera.yaml";
  QString error;
  ASSERT_TRUE(dialog.SaveTo(QString::fromStdString(path), &error)) << error.toStdString();
  EXPECT_TRUE(ReadCameraYaml(path).ok());
}

TEST(CalibrationDialog, AWrongBoardSizeIsReportedNotCrashed) {
  SIGHTLINE_REQUIRE_DATA(dir, "calib_chessboard");
  CalibrationDialog dialog;
  QSignalSpy finished(&dialog, &CalibrationDialog::Finished);
  QSignalSpy failed(&dialog, &CalibrationDialog::Failed);
  dialog.Calibrate(false, QString::fromStdString(dir), "left0[1-3].jpg", 9, 7, 0.025);
  ASSERT_TRUE(RunAndWait(&dialog, &finished, &failed));
  ASSERT_EQ(failed.count(), 1);
  EXPECT_TRUE(failed.front().front().toString().contains("no 9x7 chessboard"));
  QString error;
  EXPECT_FALSE(dialog.SaveTo("/tmp/never.yaml", &error));
  EXPECT_FALSE(error.isEmpty());
}

}  // namespace
}  // namespace sightline
