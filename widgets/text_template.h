// Texts with %N placeholders ("option '%1': %2 is outside %3") matched in their filled-in form:
// the one pattern builder of the core-message translation (core_message.h) and the language
// switch (app/sightline/retranslator.h).
#pragma once

#include <QRegularExpression>
#include <QString>
#include <vector>

namespace sightline {

// Matches one placeholder; capture 1 is its number.
const QRegularExpression& PlaceholderRe();

// The regular expression (not anchored) of `text` with each placeholder replaced by `capture`
// (e.g. "(.*?)") and every other character literal; `numbers`, when given, receives the
// placeholders' numbers in the order of their captures.
QString PlaceholderPattern(const QString& text, const QString& capture,
                           std::vector<int>* numbers = nullptr);

}  // namespace sightline
