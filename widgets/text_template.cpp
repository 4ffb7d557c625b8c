#include "widgets/text_template.h"

namespace sightline {

const QRegularExpression& PlaceholderRe() {
  static const QRegularExpression re(QStringLiteral("%(\\d+)"));
  return re;
}

QString PlaceholderPattern(const QString& text, const QString& capture, std::vector<int>* numbers) {
  QString pattern;
  qsizetype last = 0;
  for (const QRegularExpressionMatch& m : PlaceholderRe().globalMatch(text)) {
    pattern += QRegularExpression::escape(text.mid(last, m.capturedStart() - last)) + capture;
    if (numbers != nullptr) numbers->push_back(m.captured(1).toInt());
    last = m.capturedEnd();
  }
  return pattern + QRegularExpression::escape(text.mid(last));
}

}  // namespace sightline
