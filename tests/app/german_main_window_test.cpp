// The main window in German: the pipelines are still found by their English word on the command
// line (sightline --pipeline mobility), and the button picker still puts the operator panel in the
// View menu, whose title it no longer has to match.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QTranslator>

#include "app/sightline/button_picker_presenter.h"
#include "app/sightline/main_window.h"
#include "app/sightline/mobility_presenter.h"
#include "app/sightline/translation.h"

namespace sightline {
namespace {

// Installs the German translation for one test; the other tests in this process stay English.
class GermanScope {
 public:
  GermanScope()
      : installed_(InstallTranslation(QLocale(QLocale::German, QLocale::Germany), qApp)) {}
  ~GermanScope() {
    for (QTranslator* translator : qApp->findChildren<QTranslator*>()) {
      QCoreApplication::removeTranslator(translator);
      delete translator;
    }
  }
  bool installed() const { return installed_; }

 private:
  const bool installed_;
};

TEST(MainWindow, InGermanFindsPipelinesByTheirEnglishWordAndListsTheOperatorPanel) {
  GermanScope german;
  ASSERT_TRUE(german.installed());
  MainWindow window;
  auto* mobility = new MobilityPresenter();
  auto* picker = new ButtonPickerPresenter();
  window.AddPipeline(mobility);
  window.AddPipeline(picker);
  auto* view_menu = window.findChild<QMenu*>("view_menu");
  ASSERT_NE(view_menu, nullptr);
  EXPECT_EQ(view_menu->title(), "&Ansicht");

  ASSERT_TRUE(window.ActivatePipelineByWord("mobility"));
  EXPECT_EQ(window.active_pipeline(), mobility);
  EXPECT_EQ(mobility->Title(), "Befahrbarkeitskarte");
  ASSERT_TRUE(window.ActivatePipelineByWord("button"));
  EXPECT_EQ(window.active_pipeline(), picker);

  QStringList view_entries;
  for (QAction* action : view_menu->actions()) view_entries << action->text();
  const std::string listed = view_entries.join(", ").toStdString();
  EXPECT_TRUE(view_entries.contains("Bedienfeld")) << listed;
  EXPECT_TRUE(view_entries.contains("Bedienfeld im Vollbild")) << listed;
}

}  // namespace
}  // namespace sightline
