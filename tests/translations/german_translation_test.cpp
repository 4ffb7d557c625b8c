// The German translation as the user meets it: every message in translations/sightline_de.ts is
// translated with its placeholders, accelerators and ellipses intact, the newest GUI parts are in
// it, and widgets built after loading it the way sightline does for LANG=de_DE speak German.
// (ts_up_to_date_test.sh checks the other direction: every tr() text of the sources is in it.)
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QLibraryInfo>
#include <QPushButton>
#include <QRegularExpression>
#include <QSet>
#include <QXmlStreamReader>
#include <vector>

#include "app/sightline/live_status_widget.h"
#include "app/sightline/mobility_presenter.h"
#include "app/sightline/mobility_views.h"
#include "app/sightline/mono_slam_presenter.h"
#include "app/sightline/playback_controller.h"
#include "app/sightline/recording_controller.h"
#include "app/sightline/translation.h"
#include "app/sightline/view_options.h"
#include "core/options/option_set.h"
#include "tests/translations/ts_text.h"
#include "widgets/operator_panel.h"
#include "widgets/option_editor.h"

namespace sightline {
namespace {

struct TsMessage {
  QString context;
  QString source;
  QString translation;
  QString type;  // "" when finished, else "unfinished", "vanished", "obsolete".
};

std::vector<TsMessage> ReadTs(const QString& path, QString* error) {
  std::vector<TsMessage> messages;
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) {
    *error = "cannot open " + path;
    return messages;
  }
  QXmlStreamReader xml(&file);
  QString context;
  TsMessage message;
  while (!xml.atEnd()) {
    xml.readNext();
    if (!xml.isStartElement()) continue;
    if (xml.name() == u"name") {
      context = xml.readElementText();
    } else if (xml.name() == u"message") {
      message = {context, {}, {}, {}};
    } else if (xml.name() == u"source") {
      message.source = xml.readElementText();
    } else if (xml.name() == u"translation") {
      message.type = xml.attributes().value("type").toString();
      message.translation = xml.readElementText();
      messages.push_back(message);
    }
  }
  if (xml.hasError()) *error = path + ": " + xml.errorString();
  return messages;
}

std::vector<TsMessage> GermanMessages() {
  QString error;
  std::vector<TsMessage> messages = ReadTs(SIGHTLINE_DE_TS, &error);
  EXPECT_TRUE(error.isEmpty()) << error.toStdString();
  return messages;
}

using test::Accelerators;
using test::Placeholders;

TEST(GermanTs, EveryMessageIsTranslatedWithItsPlaceholdersAndAccelerators) {
  const std::vector<TsMessage> messages = GermanMessages();
  ASSERT_GT(messages.size(), 200u);
  for (const TsMessage& m : messages) {
    const std::string where =
        (m.context + " \"" + m.source + "\" -> \"" + m.translation + "\"").toStdString();
    EXPECT_TRUE(m.type.isEmpty()) << where << " is " << m.type.toStdString();
    EXPECT_FALSE(m.translation.trimmed().isEmpty()) << where;
    EXPECT_EQ(Placeholders(m.translation), Placeholders(m.source)) << where;
    EXPECT_EQ(Accelerators(m.translation), Accelerators(m.source)) << where;
    // Leading blanks join texts (" (unavailable)"); a trailing ellipsis promises a dialog.
    EXPECT_EQ(m.translation.startsWith(' '), m.source.startsWith(' ')) << where;
    for (const QString ellipsis : {QStringLiteral("..."), QStringLiteral("…")}) {
      EXPECT_EQ(m.translation.endsWith(ellipsis), m.source.endsWith(ellipsis)) << where;
    }
  }
}

TEST(GermanTs, HoldsTheNewestGuiTexts) {
  // One or two texts of each GUI part added since the first translation.
  const std::vector<std::pair<QString, QString>> newest = {
      {"sightline::MobilityPresenter", "Mobility map"},
      {"sightline::MobilityTimingPanel", "3D colour:"},
      {"sightline::MobilityImagePanel", "GPR surface"},
      {"sightline::MonoSlamPresenter", "Monocular SLAM (PTAM point cloud)"},
      {"sightline::MonoSlamPresenter", "Reset map"},
      {"sightline::ScalePlot", "pairs (map units per metre)"},
      {"sightline::ButtonPickerPresenter", "Button picker (monocular SLAM)"},
      {"sightline::ButtonPickerPresenter", "Button out of reach"},
      {"sightline::OperatorPanel", "Tap a button"},
      {"sightline::OperatorPanel", "STOP"},
      {"sightline::RecordingController", "&Record..."},
      {"sightline::RecordingController", "&Stop recording"},
      {"sightline::LiveStatusWidget", "streaming"},
      {"sightline::CalibrationDialog", "Calibrate camera"},
      {"sightline::MainWindow", "&Calibrate camera..."},
      {"sightline::OptionEditor", "Default: %1%2"},
  };
  const std::vector<TsMessage> messages = GermanMessages();
  for (const auto& [context, source] : newest) {
    bool translated = false;
    for (const TsMessage& m : messages) {
      if (m.context == context && m.source == source) translated = m.type.isEmpty();
    }
    EXPECT_TRUE(translated) << context.toStdString() << " \"" << source.toStdString()
                            << "\" is missing or unfinished";
  }
}

TEST(GermanGui, NewerWidgetsSpeakGermanOnceTheTranslationIsInstalled) {
  EXPECT_FALSE(InstallTranslation(QLocale(QLocale::French, QLocale::France), qApp))
      << "there is no French translation; the GUI must stay English";
  ASSERT_TRUE(InstallTranslation(QLocale(QLocale::German, QLocale::Germany), qApp))
      << "no sightline_de.qm under :/i18n";

  MobilityTimingPanel timing;
  EXPECT_EQ(timing.color_choice()->itemText(0), "Bewertung (Regel)");
  MobilityPresenter mobility;
  EXPECT_EQ(mobility.Title(), "Befahrbarkeitskarte");
  EXPECT_STREQ(mobility.TitleSource(), "Mobility map");  // What --pipeline mobility matches.
  MonoSlamPresenter mono;
  EXPECT_EQ(mono.Title(), "Monokulares SLAM (PTAM-Punktwolke)");

  PlaybackController playback;
  QWidget window;
  RecordingController recording(&playback, &window);
  EXPECT_EQ(recording.record_action()->text(), "&Aufnehmen...");
  EXPECT_EQ(recording.stop_action()->text(), "Aufnahme &beenden");
  SensorStats streaming;
  streaming.state = SensorState::kStreaming;
  const QString status = LiveStatusWidget::Describe(streaming);
  EXPECT_TRUE(status.contains("läuft") && status.contains("Latenz")) << status.toStdString();

  OperatorPanel panel;
  EXPECT_EQ(panel.banner()->text(), "Knopf antippen");
  EXPECT_EQ(panel.stop_button()->text(), "STOPP");
  EXPECT_EQ(panel.start_button()->text(), "Neu starten");

  OptionSet options;
  ASSERT_TRUE(options.Declare(ViewOptions::Describe()).ok());
  EXPECT_TRUE(OptionTooltip(options.specs().front()).contains("Standard: "));

  // Qt's own buttons and dialogs, from qt6-translations-l10n (packaging/install-deps.sh).
  if (!QFile::exists(QLibraryInfo::path(QLibraryInfo::TranslationsPath) + "/qtbase_de.qm")) {
    GTEST_SKIP() << "qtbase_de.qm not installed (qt6-translations-l10n): Qt's dialogs stay English";
  }
  EXPECT_EQ(QCoreApplication::translate("QPlatformTheme", "Cancel"), "Abbrechen");
}

}  // namespace
}  // namespace sightline
