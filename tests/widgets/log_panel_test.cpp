#include "widgets/log_panel.h"

#include <gtest/gtest.h>

#include <QLabel>
#include <QListView>
#include <QRegularExpression>
#include <QTest>

namespace sightline {
namespace {

TEST(LogPanelTest, KeepsTimestampedMessagesWithSeverity) {
  LogPanel panel;
  panel.AddMessage(LogPanel::Severity::kInfo, "Opened tum_fr1_desk");
  panel.AddMessage(LogPanel::Severity::kWarning, "Dropped 3 frames");
  panel.AddMessage(LogPanel::Severity::kError, "Camera disconnected");
  ASSERT_EQ(panel.count(), 3);
  EXPECT_TRUE(QRegularExpression(R"(^\d\d:\d\d:\d\d\.\d\d\d  Opened tum_fr1_desk$)")
                  .match(panel.MessageText(0))
                  .hasMatch())
      << panel.MessageText(0).toStdString();
  EXPECT_EQ(panel.MessageSeverity(1), LogPanel::Severity::kWarning);
  EXPECT_EQ(panel.MessageSeverity(2), LogPanel::Severity::kError);
  panel.Clear();
  EXPECT_EQ(panel.count(), 0);
}

TEST(LogPanelTest, DropsTheOldestBeyondTheLimit) {
  LogPanel panel(nullptr, 100);
  for (int i = 0; i < 250; ++i) {
    panel.AddMessage(LogPanel::Severity::kInfo, QString("message %1").arg(i));
  }
  ASSERT_EQ(panel.count(), 100);
  EXPECT_TRUE(panel.MessageText(0).endsWith("message 150"));
  EXPECT_TRUE(panel.MessageText(99).endsWith("message 249"));
}

// A long line is cut at the panel's edge; a click on it shows all of it, wrapped, and a second
// click hides it again.
TEST(LogPanelTest, AClickOnALineShowsTheWholeMessage) {
  LogPanel panel;
  panel.resize(300, 200);
  panel.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&panel));
  QString long_text = "Could not open /data/recordings/";
  for (int i = 0; i < 20; ++i) long_text += QString("folder_%1/").arg(i);
  panel.AddMessage(LogPanel::Severity::kError, "short");
  panel.AddMessage(LogPanel::Severity::kError, long_text);
  QLabel* detail = panel.detail();
  ASSERT_NE(detail, nullptr);
  EXPECT_FALSE(detail->isVisible());
  auto* view = panel.findChild<QListView*>();
  ASSERT_NE(view, nullptr);
  const QRect row = view->visualRect(view->model()->index(1, 0));
  ASSERT_FALSE(row.isEmpty());
  QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, row.center());
  EXPECT_TRUE(detail->isVisible());
  EXPECT_TRUE(detail->text().endsWith(long_text)) << detail->text().toStdString();
  EXPECT_TRUE(detail->wordWrap());
  EXPECT_LE(detail->width(), panel.width()) << "the message is not wrapped into the panel";
  QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, row.center());
  EXPECT_FALSE(detail->isVisible());
}

}  // namespace
}  // namespace sightline
