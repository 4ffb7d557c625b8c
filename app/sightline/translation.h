// The GUI's translations: one .qm per language, compiled from translations/*.ts into :/i18n.
#pragma once

#include <QLocale>
#include <QString>

class QCoreApplication;

namespace sightline {

// Installs the translation that matches `locale` (e.g. sightline_de.qm for de_DE) in `app`, which
// also owns it, and Qt's own (qtbase_de.qm) when installed, in place of the one installed before.
// Returns false, and leaves the installed translation as it was, when Sightline has none for the
// language.
//   InstallTranslation(QLocale(), &app);  // The user's language, before the first window.
bool InstallTranslation(const QLocale& locale, QCoreApplication* app);

// Removes the installed translation: the GUI speaks English again.
void RemoveTranslation();

// The language code of the installed translation ("de"), "en" when none is installed.
QString InstalledLanguage();

}  // namespace sightline
