#include "widgets/log_panel.h"

#include <gtest/gtest.h>

#include <QRegularExpression>

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

}  // namespace
}  // namespace sightline
