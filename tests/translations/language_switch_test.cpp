// Every language the GUI speaks, as a user meets it: each translations/sightline_<code>.ts is
// complete (every message finished, placeholders, accelerators and ellipses kept, the same
// messages as the others), the core texts the GUI shows are marked for translation, and after
// Settings > Language switches the open window (the main window with every dock and menu, and the
// operator panel) no visible text is left in another language. The choice is saved.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFormLayout>
#include <QGroupBox>
#include <QHash>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QSet>
#include <QSettings>
#include <QTabBar>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <algorithm>
#include <cctype>
#include <map>
#include <string>
#include <vector>

#include "app/sightline/builtin_presenters.h"
#include "app/sightline/button_picker_presenter.h"
#include "app/sightline/core_texts.h"
#include "app/sightline/language.h"
#include "app/sightline/main_window.h"
#include "app/sightline/option_texts.h"
#include "app/sightline/view_options.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/sensors/driver_registry.h"
#include "tests/translations/ts_text.h"
#include "widgets/core_message.h"
#include "widgets/image_view.h"
#include "widgets/operator_panel.h"
#include "widgets/option_editor.h"
#include "widgets/parameter_panel.h"

namespace sightline {
namespace {

struct TsEntry {
  QString key;  // "context\nsource"
  QString source, translation, type;
};

std::vector<TsEntry> ReadTs(const QString& code) {
  std::vector<TsEntry> entries;
  QFile file(QStringLiteral("%1/sightline_%2.ts").arg(QString(SIGHTLINE_TS_DIR), code));
  EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << file.fileName().toStdString();
  QXmlStreamReader xml(&file);
  QString context;
  TsEntry entry;
  while (!xml.atEnd()) {
    xml.readNext();
    if (!xml.isStartElement()) continue;
    if (xml.name() == u"name") context = xml.readElementText();
    if (xml.name() == u"source") entry.source = xml.readElementText();
    if (xml.name() == u"translation") {
      entry.key = context + '\n' + entry.source;
      entry.type = xml.attributes().value("type").toString();
      entry.translation = xml.readElementText();
      entries.push_back(entry);
    }
  }
  EXPECT_FALSE(xml.hasError()) << file.fileName().toStdString() << ": "
                               << xml.errorString().toStdString();
  return entries;
}

using test::Accelerators;
using test::Placeholders;

class LanguageTs : public ::testing::TestWithParam<const char*> {};

TEST_P(LanguageTs, EveryMessageIsFinishedWithItsPlaceholdersAndAccelerators) {
  const QString code = GetParam();
  const std::vector<TsEntry> entries = ReadTs(code);
  ASSERT_GT(entries.size(), 280u);
  int finished = 0;
  for (const TsEntry& e : entries) {
    const std::string where = (code + ": " + e.key.section('\n', 0, 0) + " \"" + e.source +
                               "\" -> \"" + e.translation + "\"")
                                  .toStdString();
    EXPECT_TRUE(e.type.isEmpty()) << where << " is " << e.type.toStdString();
    EXPECT_FALSE(e.translation.trimmed().isEmpty()) << where;
    EXPECT_EQ(Placeholders(e.translation), Placeholders(e.source)) << where;
    EXPECT_EQ(Accelerators(e.translation), Accelerators(e.source)) << where;
    EXPECT_EQ(e.translation.startsWith(' '), e.source.startsWith(' ')) << where;
    for (const QString ellipsis : {QStringLiteral("..."), QStringLiteral("…")}) {
      EXPECT_EQ(e.translation.endsWith(ellipsis), e.source.endsWith(ellipsis)) << where;
    }
    finished += e.type.isEmpty() && !e.translation.trimmed().isEmpty();
  }
  std::printf("%s: %d of %zu messages finished\n", qPrintable(code), finished, entries.size());
}

TEST_P(LanguageTs, HoldsTheSameMessagesAsEveryOtherLanguage) {
  const QString code = GetParam();
  QStringList mine, german;
  for (const TsEntry& e : ReadTs(code)) mine << e.key;
  for (const TsEntry& e : ReadTs("de")) german << e.key;
  for (const QString& key : german) {
    EXPECT_TRUE(mine.contains(key)) << code.toStdString() << " lacks " << key.toStdString();
  }
  for (const QString& key : mine) {
    EXPECT_TRUE(german.contains(key)) << "de lacks " << key.toStdString();
  }
}

INSTANTIATE_TEST_SUITE_P(Languages, LanguageTs, ::testing::Values("de", "it", "es"));

TEST(CoreTexts, EverySensorDescriptionTheGuiShowsIsMarkedForTranslation) {
  const std::vector<std::string> known = KnownCoreTexts();
  for (const DriverInfo& driver : BuiltinDrivers()) {
    EXPECT_NE(std::find(known.begin(), known.end(), driver.description), known.end())
        << "\"" << driver.description << "\" (driver " << driver.name
        << ") is not in app/sightline/core_texts.cpp: the Sensors menu would show it in English";
  }
}

// Every option description the parameters dock can show -> one key declaring it: the window's
// view options, what each presenter declares and what each registry pipeline declares.
std::map<std::string, std::string> DeclaredOptionDescriptions() {
  std::map<std::string, std::string> declared;
  auto add = [&declared](const OptionSet& options) {
    for (const OptionSpec& spec : options.specs()) declared.emplace(spec.description, spec.key);
  };
  OptionSet view;
  EXPECT_TRUE(view.Declare(ViewOptions::Describe()).ok());
  add(view);
  for (PipelinePresenter* presenter : MakeBuiltinPresenters()) {
    OptionSet options;
    const Status status = presenter->DeclareOptions(&options);
    EXPECT_TRUE(status.ok()) << presenter->TitleSource() << ": " << status.ToString();
    add(options);
    delete presenter;
  }
  const PipelineRegistry registry = BuiltinPipelines();
  for (const PipelineInfo& pipeline : registry.pipelines()) {
    if (!pipeline.declare_options) continue;
    OptionSet options;
    EXPECT_TRUE(pipeline.declare_options(&options).ok()) << pipeline.name;
    add(options);
  }
  return declared;
}

TEST(OptionTexts, EveryOptionDescriptionTheGuiShowsIsMarkedForTranslation) {
  const std::vector<std::string> known = KnownOptionTexts();
  const std::map<std::string, std::string> declared = DeclaredOptionDescriptions();
  ASSERT_GT(declared.size(), 300u) << "too few options found to judge the list";
  EXPECT_TRUE(std::is_sorted(known.begin(), known.end()));
  for (const auto& [description, key] : declared) {
    EXPECT_FALSE(description.empty()) << "option " << key << " has no description";
    if (description.empty()) continue;
    EXPECT_TRUE(std::binary_search(known.begin(), known.end(), description))
        << "\"" << description << "\" (option " << key
        << ") is not in app/sightline/option_texts.cpp: the parameters dock would show it in "
           "English. Run `cmake --build build --target update_option_texts`, then "
           "update_translations, and translate the new entries";
  }
  for (const std::string& text : known) {
    EXPECT_TRUE(declared.count(text))
        << "\"" << text << "\" in app/sightline/option_texts.cpp describes no option any more: "
        << "run `cmake --build build --target update_option_texts`";
  }
  std::printf("%zu option descriptions, %zu marked for translation\n", declared.size(),
              known.size());
}

// The tuning panel speaks of what an option does and of the published method it follows, never
// of "the seed" (the document a pipeline was specified from): "seed" is only a random
// generator's seed or a simulated scene's seed.
TEST(OptionTexts, NoDescriptionSpeaksOfTheSpecificationDocument) {
  const std::map<std::string, std::string> declared = DeclaredOptionDescriptions();
  ASSERT_GT(declared.size(), 300u) << "too few options found to judge the list";
  int checked = 0;
  for (const auto& [description, key] : declared) {
    std::string lower = description;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (size_t at = lower.find("seed"); at != std::string::npos; at = lower.find("seed", at + 1)) {
      const std::string before = lower.substr(at >= 20 ? at - 20 : 0, at >= 20 ? 20 : at);
      const std::string after = lower.substr(at, 12);
      const bool generator = before.find("random") != std::string::npos ||
                             before.find("generator") != std::string::npos ||
                             before.find("max_iterations, ") != std::string::npos;
      const bool simulated_scenes = after.rfind("seeds 1", 0) == 0;  // "seeds 1-5", "seeds 1 and 4"
      EXPECT_TRUE(generator || simulated_scenes)
          << "option " << key << " says \"seed\" where the user cannot know what it is: \""
          << description << "\"";
      ++checked;
    }
  }
  EXPECT_GT(checked, 0) << "the random generators' seeds should have been seen";
}

// Every text a user can read in `root` and below: labels, buttons, group and dock titles, tabs,
// table headers, placeholders, and every menu of a menu bar with its entries.
void CollectTexts(QWidget* root, QStringList* texts) {
  std::vector<QWidget*> widgets = {root};
  for (QWidget* w : root->findChildren<QWidget*>()) {
    if (w->isVisibleTo(root)) widgets.push_back(w);
  }
  for (QWidget* w : widgets) {
    if (auto* label = qobject_cast<QLabel*>(w)) *texts << label->text();
    if (auto* button = qobject_cast<QAbstractButton*>(w)) *texts << button->text();
    if (auto* group = qobject_cast<QGroupBox*>(w)) *texts << group->title();
    if (auto* dock = qobject_cast<QDockWidget*>(w)) *texts << dock->windowTitle();
    if (auto* line = qobject_cast<QLineEdit*>(w)) *texts << line->placeholderText();
    if (auto* image = qobject_cast<ImageView*>(w)) *texts << image->title() << image->message();
    if (auto* tabs = qobject_cast<QTabBar*>(w)) {
      for (int i = 0; i < tabs->count(); ++i) *texts << tabs->tabText(i);
    }
    if (auto* view = qobject_cast<QAbstractItemView*>(w); view && view->model()) {
      for (int i = 0; i < view->model()->columnCount(); ++i) {
        *texts << view->model()->headerData(i, Qt::Horizontal).toString();
      }
    }
    if (auto* bar = qobject_cast<QMenuBar*>(w)) {
      std::vector<QMenu*> menus;
      for (QAction* a : bar->actions()) {
        if (a->menu()) menus.push_back(a->menu());
      }
      for (size_t i = 0; i < menus.size(); ++i) {
        *texts << menus[i]->title();
        for (QAction* a : menus[i]->actions()) {
          if (a->menu()) menus.push_back(a->menu());
          if (!a->isSeparator() && !a->menu()) *texts << a->text();
        }
      }
    }
  }
  texts->removeAll(QString());
}

// For one language: every text of every language, with the language it is right for.
struct Texts {
  QHash<QString, QSet<QString>> languages_of;  // text -> codes whose translation it is
};

Texts AllTexts() {
  Texts all;
  for (const QString& key : AllMessages()) {
    const QString source = key.section('\n', 1);
    all.languages_of[source].insert("en");
    for (const QString code : {"de", "it", "es"}) {
      const QString text = TranslationOf(code, key.section('\n', 0, 0), source);
      if (!text.isEmpty()) all.languages_of[text].insert(code);
    }
  }
  return all;
}

class LanguageSwitch : public ::testing::Test {
 protected:
  void SetUp() override {
    SwitchLanguage("en", qApp);
    window_ = std::make_unique<MainWindow>();
    for (PipelinePresenter* presenter : MakeBuiltinPresenters()) {
      if (auto* p = qobject_cast<ButtonPickerPresenter*>(presenter)) picker_ = p;
      window_->AddPipeline(presenter);
      presenters_.push_back(presenter);
    }
    ASSERT_NE(picker_, nullptr);
    window_->show();
    // The button picker brings the operator panel (a tab beside the log).
    ASSERT_TRUE(window_->ActivatePipeline(picker_->Title()));
    QApplication::processEvents();
  }
  void TearDown() override {
    window_.reset();
    SwitchLanguage("en", qApp);
  }

  // Switches through Settings > Language as a user does and returns the texts left in another
  // language, with the language they belong to.
  QStringList SwitchAndFindForeignTexts(const QString& code, int* checked) {
    QMenu* menu = window_->findChild<QMenu*>("language_menu");
    EXPECT_NE(menu, nullptr);
    if (menu == nullptr) return {};
    for (QAction* action : menu->actions()) {
      if (action->data().toString() == code && !action->isSeparator()) action->trigger();
    }
    QApplication::processEvents();
    QStringList texts;
    CollectTexts(window_.get(), &texts);
    CollectTexts(picker_->panel(), &texts);
    *checked = static_cast<int>(texts.size());
    const Texts all = AllTexts();
    QStringList foreign;
    for (const QString& text : texts) {
      const auto it = all.languages_of.find(text);
      if (it == all.languages_of.end() || it->contains(code)) continue;
      foreign << QStringLiteral("\"%1\" (%2)").arg(text, QStringList(it->values()).join('/'));
    }
    foreign.removeDuplicates();
    return foreign;
  }

  // SIGHTLINE_LANGUAGE_SHOTS=DIR: the operator panel and the window in each language, as PNGs
  // (docs/images/operator-panel-<code>.png were made so).
  void SaveShots(const QString& code) {
    const QString dir = qEnvironmentVariable("SIGHTLINE_LANGUAGE_SHOTS");
    if (dir.isEmpty()) return;
    picker_->panel()->grab().save(dir + "/operator-panel-" + code + ".png");
    window_->grab().save(dir + "/window-" + code + ".png");
  }

  // The rows of the parameters dock whose tool tips (the row's name and its input) do not begin
  // with the option's description in `code`, or lack the translated "Default:" line (whose value
  // may be empty, as the tool tip's trailing space is trimmed).
  QStringList UntranslatedParameterRows(const QString& code, int* checked) {
    auto* panel = window_->findChild<ParameterPanel*>();
    EXPECT_NE(panel, nullptr);
    if (panel == nullptr) return {};
    const QString default_line = TranslationOf(code, "sightline::OptionEditor", "Default: %1%2")
                                     .section('%', 0, 0)
                                     .trimmed();
    EXPECT_FALSE(default_line.isEmpty());
    QStringList wrong;
    for (const OptionSpec& spec : panel->options().specs()) {
      OptionEditor* editor = panel->EditorFor(spec.key);
      auto* form = editor ? qobject_cast<QFormLayout*>(editor->parentWidget()->layout()) : nullptr;
      QWidget* label = form ? form->labelForField(editor) : nullptr;
      if (label == nullptr) {
        wrong << QString::fromStdString(spec.key) + " (no row)";
        continue;
      }
      const QString description =
          TranslationOf(code, "sightline::OptionText", QString::fromStdString(spec.description));
      for (const QString& tip : {label->toolTip(), editor->input()->toolTip()}) {
        ++*checked;
        if (description.isEmpty() || !tip.startsWith(description + '\n') ||
            !tip.contains('\n' + default_line)) {
          wrong << QStringLiteral("%1: \"%2\"").arg(QString::fromStdString(spec.key), tip);
        }
      }
    }
    wrong.removeDuplicates();
    return wrong;
  }

  std::unique_ptr<MainWindow> window_;
  ButtonPickerPresenter* picker_ = nullptr;
  std::vector<PipelinePresenter*> presenters_;
};

TEST_F(LanguageSwitch, EveryLanguageInTurnLeavesNoTextOfAnotherOneAndIsSaved) {
  for (const QString code : {"it", "es", "de", "en", "es", "it"}) {
    int checked = 0;
    const QStringList foreign = SwitchAndFindForeignTexts(code, &checked);
    EXPECT_GT(checked, 60) << "too few texts found to judge the switch to " << code.toStdString();
    EXPECT_TRUE(foreign.isEmpty())
        << "after switching to " << code.toStdString() << ", " << foreign.size()
        << " texts of other languages: " << foreign.join(", ").toStdString();
    EXPECT_EQ(CurrentLanguage(), code);
    SaveShots(code);
    EXPECT_EQ(QSettings().value("language").toString(), code) << "the choice is not saved";
    EXPECT_EQ(SavedLanguage(), code);
    const QString view = code == "en" ? QStringLiteral("&View")
                                      : TranslationOf(code, "sightline::MainWindow", "&View");
    EXPECT_EQ(window_->findChild<QMenu*>("view_menu")->title(), view);
    // The pipeline stays selectable by its (now translated) title.
    EXPECT_TRUE(window_->ActivatePipeline(picker_->Title())) << code.toStdString();
  }
}

TEST_F(LanguageSwitch, OperatorPanelSpeaksTheNewLanguageAtOnce) {
  int checked = 0;
  SwitchAndFindForeignTexts("it", &checked);
  EXPECT_EQ(picker_->panel()->stop_button()->text(),
            TranslationOf("it", "sightline::OperatorPanel", "STOP"));
  // No picture yet: the panel holds, and says why in the detail line.
  EXPECT_EQ(picker_->panel()->banner()->text(),
            TranslationOf("it", "sightline::OperatorPanel", "Holding: nothing sent"));
  EXPECT_EQ(picker_->panel()->detail_label()->text(),
            TranslationOf("it", "sightline::ButtonPickerPresenter", "Paused"));
  SwitchAndFindForeignTexts("es", &checked);
  EXPECT_EQ(picker_->panel()->stop_button()->text(), "PARAR");
  EXPECT_EQ(picker_->panel()->start_button()->text(), "Empezar de nuevo");
}

TEST_F(LanguageSwitch, ParametersDockDescribesEveryOptionInTheNewLanguage) {
  for (const QString code : {"it", "es", "de"}) {
    int texts = 0;
    SwitchAndFindForeignTexts(code, &texts);
    // The rows built in the previous language follow the switch...
    int checked = 0;
    QStringList wrong = UntranslatedParameterRows(code, &checked);
    EXPECT_GT(checked, 4) << code.toStdString();
    EXPECT_TRUE(wrong.isEmpty()) << "after switching to " << code.toStdString() << ", "
                                 << wrong.size()
                                 << " rows not in it: " << wrong.join(", ").toStdString();
    // ...and every pipeline's rows are built in it.
    for (PipelinePresenter* presenter : presenters_) {
      ASSERT_TRUE(window_->ActivatePipeline(presenter->Title())) << presenter->TitleSource();
      QApplication::processEvents();
      wrong = UntranslatedParameterRows(code, &checked);
      EXPECT_TRUE(wrong.isEmpty())
          << presenter->TitleSource() << " in " << code.toStdString() << ": " << wrong.size()
          << " rows not in it: " << wrong.join(", ").toStdString();
    }
    EXPECT_GT(checked, 600) << "too few option rows found in " << code.toStdString();
  }
}

// A profile the parameters dock cannot load: what the core says (in English, with the file and
// field) and the template CoreMessage must know it by, with its filled-in parts.
struct BadProfile {
  const char* yaml;  // nullptr: the file is missing.
  const char* code;
  const char* message;
  QStringList parts;
};

QString Fill(QString text, const QStringList& parts) {
  for (const QString& part : parts) text = text.arg(part);
  return text;
}

TEST(CoreMessages, ProfileAndValueErrorsOfTheCoreReadInTheChosenLanguage) {
  const std::vector<BadProfile> profiles = {
      {"view:\n  cloud_stride: 0\n",
       "invalid argument",
       "option '%1': %2 is outside %3",
       {"view.cloud_stride", "0", "[1, 16] px"}},
      {"view:\n  cloud_stride: many\n",
       "invalid argument",
       "option '%1': '%2' is not an integer",
       {"view.cloud_stride", "many"}},
      {"view:\n  max_depth_m: far\n",
       "invalid argument",
       "option '%1': '%2' is not a number",
       {"view.max_depth_m", "far"}},
      {"view:\n  bogus: 1\n", "not found", "unknown option '%1'", {"view.bogus"}},
      {"- 1\n- 2\n", "parse error", "a profile must be a map of option keys", {}},
      {"view:\n  max_depth_m: [1, 2]\n",
       "parse error",
       "option '%1' must be a single value, not a list",
       {"view.max_depth_m"}},
      {"view:\n  cloud_stride: 2\nview.cloud_stride: 3\n",
       "parse error",
       "option '%1' is given twice (also line %2)",
       {"view.cloud_stride", "2"}},
      {nullptr, "not found", "no such file", {}},
  };
  QTemporaryDir dir;
  ASSERT_TRUE(dir.isValid());
  OptionSet options;
  ASSERT_TRUE(options.Declare(ViewOptions::Describe()).ok());
  ParameterPanel panel;
  panel.SetOptions(options);
  for (size_t i = 0; i < profiles.size(); ++i) {
    const BadProfile& bad = profiles[i];
    const QString path = dir.filePath(QStringLiteral("bad%1.yaml").arg(i));
    if (bad.yaml != nullptr) {
      QFile file(path);
      ASSERT_TRUE(file.open(QIODevice::WriteOnly));
      file.write(bad.yaml);
    }
    OptionSet copy = options;
    const std::string english = copy.LoadYaml(path.toStdString()).ToString();
    const QString english_message = Fill(bad.message, bad.parts);
    // The template is the core's wording, and English stays as the core wrote it.
    ASSERT_TRUE(CoreMessageTemplates().contains(bad.message)) << bad.message;
    EXPECT_TRUE(QString::fromStdString(english).startsWith(QString(bad.code) + ": ")) << english;
    EXPECT_TRUE(QString::fromStdString(english).endsWith(english_message))
        << english << " does not end in \"" << english_message.toStdString() << "\"";
    SwitchLanguage("en", qApp);
    EXPECT_EQ(CoreMessage(english), QString::fromStdString(english));
    for (const QString code : {"it", "es", "de"}) {
      SwitchLanguage(code, qApp);
      const QString translated = CoreMessage(english);
      const QString expected_code = TranslationOf(code, "sightline::CoreMessage", bad.code);
      const QString expected_message =
          Fill(TranslationOf(code, "sightline::CoreMessage", bad.message), bad.parts);
      const std::string where =
          code.toStdString() + ": " + english + " -> " + translated.toStdString();
      EXPECT_FALSE(expected_code.isEmpty() || expected_message.isEmpty()) << where;
      EXPECT_TRUE(translated.startsWith(expected_code + ": ")) << where;
      EXPECT_TRUE(translated.endsWith(expected_message)) << where;
      EXPECT_TRUE(translated.contains(QDir::toNativeSeparators(path).section('/', -1)))
          << where << ": the file's name is kept";
      EXPECT_NE(translated, QString::fromStdString(english)) << where;
      // The dock shows it so.
      EXPECT_FALSE(panel.LoadProfile(path).ok());
      EXPECT_EQ(panel.message(), translated) << where;
    }
    // The message shown follows a switch of language (from German).
    SwitchLanguage("it", qApp);
    QApplication::processEvents();
    EXPECT_EQ(panel.message(), CoreMessage(english));
    EXPECT_TRUE(panel.message().startsWith(TranslationOf("it", "sightline::CoreMessage", bad.code)))
        << panel.message().toStdString();
  }
  SwitchLanguage("en", qApp);
}

TEST(LanguageChoice, SystemLanguageIsTheDefaultAndUnknownCodesAreRefused) {
  QSettings().remove("language");
  EXPECT_EQ(SavedLanguage(), QString()) << "nothing saved: the system's language applies";
  QLocale::setDefault(QLocale(QLocale::Italian, QLocale::Italy));
  EXPECT_EQ(SystemLanguage(), "it");
  EXPECT_EQ(SwitchLanguage(QString(), qApp), "it");
  QLocale::setDefault(QLocale(QLocale::French, QLocale::France));
  EXPECT_EQ(SystemLanguage(), "en") << "no French translation: English";
  QLocale::setDefault(QLocale::c());
  EXPECT_FALSE(IsLanguage("fr"));
  EXPECT_TRUE(IsLanguage("es"));
  EXPECT_EQ(SwitchLanguage("en", qApp), "en");
  EXPECT_EQ(QCoreApplication::translate("sightline::OperatorPanel", "STOP"), "STOP");
}

}  // namespace
}  // namespace sightline
