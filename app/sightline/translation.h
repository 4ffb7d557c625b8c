// The GUI's translations: one .qm per language, compiled from translations/*.ts into :/i18n.
#pragma once

#include <QLocale>

class QCoreApplication;

namespace sightline {

// Installs the translation that matches `locale` (e.g. sightline_de.qm for de_DE) in `app`, which
// also owns it, and Qt's own (qtbase_de.qm) when installed. Returns false, and the GUI stays
// English, when Sightline has none for the language.
//   InstallTranslation(QLocale(), &app);  // The user's language, before the first window.
bool InstallTranslation(const QLocale& locale, QCoreApplication* app);

}  // namespace sightline
