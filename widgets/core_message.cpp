#include "widgets/core_message.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <optional>
#include <vector>

#include "widgets/text_template.h"

namespace sightline {
namespace {

constexpr char kContext[] = "sightline::CoreMessage";

// StatusCodeName() of core/common/status.cpp, before the first ": ".
const char* const kCodes[] = {
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "invalid argument"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "not found"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "parse error"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "unavailable"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "out of range"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "failed precondition"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "internal error"),
};

// Where a message comes from: the part before a ": ".
const char* const kOrigins[] = {
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "%1 line %2"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "profile %1"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "parameter panel"),
};

// Word for word as core/options/option_spec.cpp, option_set.cpp and core/common/text_file.cpp
// build them (tests/translations checks the common ones against the core's real output).
const char* const kMessages[] = {
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "unknown option '%1'"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "option '%1': %2 is outside %3"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "option '%1': '%2' is not one of: %3"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "option '%1': '%2' is not a boolean (true/false)"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "option '%1': '%2' is not an integer"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "option '%1': '%2' is not a number"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "option '%1': value is not finite"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "a profile must be a map of option keys"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "option '%1' is given twice (also line %2)"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "option '%1' has no value"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "option '%1' must be a single value, not a list"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "an option key must be a word, not a list or map"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "options nest deeper than %1 levels"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "lists or maps nest deeper than %1 levels"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage",
                      "more than %1 values (aliases expanding?); a profile lists each option once"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "not a readable YAML profile: %1"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "cannot write profile %1"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "write to %1 failed (disk full?)"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "no such file"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "profile %1 is a folder, not a file"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage",
                      "profile %1 is not a regular file (a device, pipe or socket)"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "profile %1 cannot be read: %2"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage",
                      "profile %1 is %2 bytes; a profile holds at most %3"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "cannot read its size: %1"),
    QT_TRANSLATE_NOOP("sightline::CoreMessage", "read error (%1 of %2 bytes)"),
};

struct Template {
  QRegularExpression pattern;  // The English text, each %N a capture, anchored.
  const char* source;
};

std::vector<Template> Compile(const char* const* begin, const char* const* end) {
  std::vector<Template> templates;
  for (const char* const* source = begin; source != end; ++source) {
    const QString pattern = PlaceholderPattern(QString::fromUtf8(*source), QStringLiteral("(.+?)"));
    templates.push_back(
        {QRegularExpression(QRegularExpression::anchoredPattern(pattern)), *source});
  }
  return templates;
}

// `text` translated through the first template it matches in full, its parts filled in as they
// are (the templates number their parts %1, %2, %3 in order).
std::optional<QString> Match(const QString& text, const std::vector<Template>& templates) {
  for (const Template& t : templates) {
    const QRegularExpressionMatch m = t.pattern.match(text);
    if (!m.hasMatch()) continue;
    QString translated = QCoreApplication::translate(kContext, t.source);
    switch (m.lastCapturedIndex()) {
      case 1:
        return translated.arg(m.captured(1));
      case 2:
        return translated.arg(m.captured(1), m.captured(2));
      case 3:
        return translated.arg(m.captured(1), m.captured(2), m.captured(3));
      default:
        return translated;
    }
  }
  return std::nullopt;
}

// "ORIGIN: ORIGIN: MESSAGE", each part through its templates.
QString TranslateMessage(const QString& text, int depth) {
  static const std::vector<Template> messages = Compile(std::begin(kMessages), std::end(kMessages));
  static const std::vector<Template> origins = Compile(std::begin(kOrigins), std::end(kOrigins));
  if (std::optional<QString> whole = Match(text, messages)) return *whole;
  const qsizetype colon = text.indexOf(QStringLiteral(": "));
  if (colon < 0 || depth >= 8) return text;
  const QString origin = text.left(colon);
  return Match(origin, origins).value_or(origin) + QStringLiteral(": ") +
         TranslateMessage(text.mid(colon + 2), depth + 1);
}

}  // namespace

QString CoreMessage(const std::string& status_text) {
  const QString text = QString::fromStdString(status_text);
  for (const char* code : kCodes) {
    const QString prefix = QString::fromUtf8(code) + QStringLiteral(": ");
    if (text.startsWith(prefix)) {
      return QCoreApplication::translate(kContext, code) + QStringLiteral(": ") +
             TranslateMessage(text.mid(prefix.size()), 0);
    }
  }
  return TranslateMessage(text, 0);
}

QStringList CoreMessageTemplates() {
  QStringList all;
  for (const char* s : kCodes) all << QString::fromUtf8(s);
  for (const char* s : kOrigins) all << QString::fromUtf8(s);
  for (const char* s : kMessages) all << QString::fromUtf8(s);
  return all;
}

}  // namespace sightline
