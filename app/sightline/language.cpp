#include "app/sightline/language.h"

#include <QCoreApplication>
#include <QFile>
#include <QHash>
#include <QLocale>
#include <QSettings>
#include <QXmlStreamReader>

#include "app/sightline/retranslator.h"
#include "app/sightline/translation.h"

namespace sightline {

namespace {

constexpr char kLanguageKey[] = "language";

// One language's messages from its embedded .ts: "context\nsource" -> translation.
using Messages = QHash<QString, QString>;

QString Key(const QString& context, const QString& source) { return context + '\n' + source; }

// Reads :/i18n-ts/sightline_<code>.ts; `order` (when given) receives the keys in file order.
Messages ReadTs(const QString& code, QStringList* order) {
  Messages messages;
  QFile file(QStringLiteral(":/i18n-ts/sightline_%1.ts").arg(code));
  if (!file.open(QIODevice::ReadOnly)) return messages;
  QXmlStreamReader xml(&file);
  QString context, source;
  while (!xml.atEnd()) {
    xml.readNext();
    if (!xml.isStartElement()) continue;
    if (xml.name() == u"name") {
      context = xml.readElementText();
    } else if (xml.name() == u"source") {
      source = xml.readElementText();
    } else if (xml.name() == u"translation") {
      const bool finished = xml.attributes().value("type").isEmpty();
      const QString text = xml.readElementText();
      if (finished && !text.isEmpty()) messages.insert(Key(context, source), text);
      if (order != nullptr) order->append(Key(context, source));
    }
  }
  return messages;
}

const Messages& MessagesOf(const QString& code) {
  static QHash<QString, Messages> cache;
  auto it = cache.find(code);
  if (it == cache.end()) it = cache.insert(code, ReadTs(code, nullptr));
  return *it;
}

// The translator of every widget text from one language into another.
Retranslator::Lookup LookupBetween(const QString& from, const QString& to) {
  Retranslator::Lookup lookup;
  for (const QString& key : AllMessages()) {
    const QString context = key.section('\n', 0, 0);
    const QString source = key.section('\n', 1);
    const QString old_text = from == "en" ? source : TranslationOf(from, context, source);
    const QString new_text = to == "en" ? source : TranslationOf(to, context, source);
    if (old_text.isEmpty() || new_text.isEmpty()) continue;
    lookup.push_back({old_text, new_text});
  }
  return lookup;
}

}  // namespace

const std::vector<Language>& Languages() {
  static const std::vector<Language> languages = {
      {"en", "English"}, {"de", "Deutsch"}, {"it", "Italiano"}, {"es", "Español"}};
  return languages;
}

bool IsLanguage(const QString& code) {
  for (const Language& language : Languages()) {
    if (language.code == code) return true;
  }
  return false;
}

QString SavedLanguage() {
  const QString code = QSettings().value(kLanguageKey).toString();
  return IsLanguage(code) ? code : QString();
}

void SaveLanguage(const QString& code) { QSettings().setValue(kLanguageKey, code); }

QString SystemLanguage() {
  for (const QString& name : QLocale().uiLanguages()) {
    const QString code = name.left(2).toLower();
    if (IsLanguage(code)) return code;
  }
  return QStringLiteral("en");
}

QString CurrentLanguage() { return InstalledLanguage(); }

QString SwitchLanguage(const QString& code, QCoreApplication* app) {
  const QString from = CurrentLanguage();
  QString to = code.isEmpty() ? SystemLanguage() : code;
  if (to == "en" || !InstallTranslation(QLocale(to), app)) {
    RemoveTranslation();
    to = QStringLiteral("en");
  }
  if (from != to) Retranslator(LookupBetween(from, to)).RetranslateAll();
  return to;
}

QString TranslationOf(const QString& code, const QString& context, const QString& source) {
  return MessagesOf(code).value(Key(context, source));
}

QStringList AllMessages() {
  static const QStringList all = [] {
    QStringList order;
    ReadTs(QStringLiteral("de"), &order);
    return order;
  }();
  return all;
}

}  // namespace sightline
