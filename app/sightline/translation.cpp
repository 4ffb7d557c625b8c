#include "app/sightline/translation.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QTranslator>

namespace sightline {

namespace {

// Loads `file`_<language>.qm from `dir` and installs it; false when there is none.
bool Install(const QLocale& locale, const QString& file, const QString& dir,
             QCoreApplication* app) {
  auto* translator = new QTranslator(app);
  if (!translator->load(locale, file, "_", dir) ||
      !QCoreApplication::installTranslator(translator)) {
    delete translator;
    return false;
  }
  return true;
}

}  // namespace

bool InstallTranslation(const QLocale& locale, QCoreApplication* app) {
  if (!Install(locale, "sightline", ":/i18n", app)) return false;
  // Qt's own texts (file dialogs, OK/Cancel, context menus) from qt6-translations-l10n; without
  // the package they stay English and the rest is still translated.
  Install(locale, "qtbase", QLibraryInfo::path(QLibraryInfo::TranslationsPath), app);
  return true;
}

}  // namespace sightline
