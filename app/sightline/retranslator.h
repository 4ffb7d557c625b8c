// Turns the text of open widgets and actions from one language into another, so the GUI switches
// language without a restart and without each widget rebuilding its texts.
#pragma once

#include <QRegularExpression>
#include <QString>
#include <QWidget>
#include <optional>
#include <utility>
#include <vector>

class QAction;

namespace sightline {

class Retranslator {
 public:
  // Pairs (text in the old language, text in the new one), from the .ts files. A text with
  // placeholders ("Pipeline: %1") also matches the filled-in text ("Pipeline: Mobility map"),
  // whose filled-in parts are translated too when they are messages themselves.
  using Lookup = std::vector<std::pair<QString, QString>>;
  explicit Retranslator(const Lookup& lookup);

  // Every widget and action of the application.
  void RetranslateAll() const;
  void Retranslate(QWidget* widget) const;
  void Retranslate(QAction* action) const;

  // The new language's text for `text`, or nothing when it is not a known message.
  std::optional<QString> Translate(const QString& text) const;

 private:
  struct Pattern {
    QRegularExpression old_text;  // The old text with each %N as a capture.
    std::vector<int> numbers;     // The N of each capture, in order.
    QString new_text;
  };
  std::optional<QString> FromPattern(const QString& text) const;
  // Sets `text` through `set` when it translates to something else.
  template <typename Set>
  void Apply(const QString& text, Set set) const {
    if (text.isEmpty()) return;
    if (const std::optional<QString> translated = Translate(text)) {
      if (*translated != text) set(*translated);
    }
  }
  void RetranslateItems(QWidget* widget) const;

  std::vector<std::pair<QString, QString>> exact_;  // Sorted by old text.
  std::vector<Pattern> patterns_;
};

}  // namespace sightline
