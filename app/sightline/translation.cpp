#include "app/sightline/translation.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QPointer>
#include <QTranslator>
#include <algorithm>
#include <vector>

namespace sightline {

namespace {

// The translators installed by InstallTranslation, Sightline's and Qt's.
std::vector<QPointer<QTranslator>>& Installed() {
  static std::vector<QPointer<QTranslator>> installed;
  return installed;
}

QString& InstalledCode() {
  static QString code = QStringLiteral("en");
  return code;
}

// Loads `file`_<language>.qm from `dir`; nullptr when there is none.
QTranslator* Load(const QLocale& locale, const QString& file, const QString& dir,
                  QCoreApplication* app) {
  auto* translator = new QTranslator(app);
  if (!translator->load(locale, file, "_", dir)) {
    delete translator;
    return nullptr;
  }
  return translator;
}

}  // namespace

void RemoveTranslation() {
  for (const QPointer<QTranslator>& translator : Installed()) {
    if (translator.isNull()) continue;
    QCoreApplication::removeTranslator(translator);
    translator->deleteLater();
  }
  Installed().clear();
  InstalledCode() = QStringLiteral("en");
}

bool InstallTranslation(const QLocale& locale, QCoreApplication* app) {
  QTranslator* own = Load(locale, "sightline", ":/i18n", app);
  if (own == nullptr) return false;
  RemoveTranslation();
  QCoreApplication::installTranslator(own);
  Installed().push_back(own);
  // The .qm's own language ("sightline_de.qm" -> "de"), whatever variant the locale named.
  InstalledCode() = own->language().left(2);
  if (InstalledCode().isEmpty()) InstalledCode() = locale.name().left(2);
  // Qt's own texts (file dialogs, OK/Cancel, context menus) from qt6-translations-l10n; without
  // the package they stay English and the rest is still translated.
  QTranslator* qt = Load(locale, "qtbase", QLibraryInfo::path(QLibraryInfo::TranslationsPath), app);
  if (qt != nullptr) {
    QCoreApplication::installTranslator(qt);
    Installed().push_back(qt);
  }
  return true;
}

QString InstalledLanguage() {
  // A translator deleted behind our back (a test's clean-up) leaves English.
  const bool any = std::any_of(Installed().begin(), Installed().end(),
                               [](const QPointer<QTranslator>& t) { return !t.isNull(); });
  return any ? InstalledCode() : QStringLiteral("en");
}

}  // namespace sightline
