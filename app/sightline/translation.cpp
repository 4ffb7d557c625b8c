#include "app/sightline/translation.h"

#include <QCoreApplication>
#include <QTranslator>

namespace sightline {

bool InstallTranslation(const QLocale& locale, QCoreApplication* app) {
  auto* translator = new QTranslator(app);
  if (!translator->load(locale, "sightline", "_", ":/i18n")) {
    delete translator;
    return false;
  }
  return QCoreApplication::installTranslator(translator);
}

}  // namespace sightline
