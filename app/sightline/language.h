// The GUI's language: which ones Sightline speaks, the user's saved choice, and switching while
// the window is open (Settings > Language, `sightline --lang it|es|de|en`).
#pragma once

#include <QString>
#include <QStringList>
#include <vector>

class QCoreApplication;

namespace sightline {

struct Language {
  QString code;         // "en", "de", "it", "es".
  QString native_name;  // As the menu shows it, in its own language: "Italiano".
};

// English first, then every language with a translations/sightline_<code>.ts.
const std::vector<Language>& Languages();
// True when `code` is one of Languages().
bool IsLanguage(const QString& code);

// The saved choice (QSettings "language"): a code, or "" for the system's language.
QString SavedLanguage();
void SaveLanguage(const QString& code);

// The language the system asks for, as one of Languages() (English when Sightline lacks it).
QString SystemLanguage();

// The language in effect: "" means English too.
QString CurrentLanguage();

// Installs `code`'s translation ("" = the system's language, "en" = none) in `app` and turns the
// text of every open widget and action from the previous language into the new one. Texts a
// widget builds from values (status lines, counters) follow with their next update. Returns the
// code now in effect.
QString SwitchLanguage(const QString& code, QCoreApplication* app);

// The translated text of (context, source) in `code`, from the embedded .ts files ("" when
// there is none). Tests use it to tell an English text from its translation.
QString TranslationOf(const QString& code, const QString& context, const QString& source);

// Every (context, source) message of the GUI, in .ts order, as "context\nsource".
QStringList AllMessages();

}  // namespace sightline
