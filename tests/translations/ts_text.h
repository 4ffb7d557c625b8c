// Checks of one translated text shared by the translation tests.
#pragma once

#include <QRegularExpression>
#include <QSet>
#include <QString>

namespace sightline::test {

// The %1, %2 ... and QProgressBar's %p of a text, as a set: their order may change in a language.
inline QSet<QString> Placeholders(const QString& text) {
  QSet<QString> found;
  static const QRegularExpression re("%(\\d+|p)");
  for (const QRegularExpressionMatch& m : re.globalMatch(text)) found.insert(m.captured(0));
  return found;
}

// Menu accelerators: an '&' before a character, not "&&" and not an HTML entity (&nbsp;).
inline int Accelerators(QString text) {
  static const QRegularExpression entity("&#?\\w+;");
  text.remove(entity);
  text.remove("&&");
  return static_cast<int>(text.count('&'));
}

}  // namespace sightline::test
