// One line of a pipeline's per-frame statistics for a label, each figure with its unit from
// the pipeline's statistics table: "occupancy 1.20 ms, lines 4 count, heading 12.3 deg".
#pragma once

#include <QString>
#include <QStringList>
#include <string>

#include "core/pipeline/pipeline.h"

namespace sightline {

// The statistics of `result` that `table` lists, in the table's order; `skip` drops keys
// containing it (e.g. "_points"). Flags (unit "") show as their name when set.
inline QString StatisticsText(const PipelineResult& result, const StatisticTable& table,
                              const std::string& skip = std::string()) {
  QStringList parts;
  for (const StatisticInfo& info : table) {
    if (!skip.empty() && info.key.find(skip) != std::string::npos) continue;
    const std::optional<double> value = result.Stat(info.key);
    if (!value) continue;
    std::string name = info.key.substr(info.key.find('/') + 1);
    if (info.unit == "ms" && name.size() > 3 && name.compare(name.size() - 3, 3, "_ms") == 0) {
      name.resize(name.size() - 3);
    }
    const QString label = QString::fromStdString(name);
    if (info.unit.empty()) {
      if (*value != 0) parts << label;
      continue;
    }
    parts << QStringLiteral("%1 %2 %3")
                 .arg(label)
                 .arg(*value, 0, 'g', 4)
                 .arg(QString::fromStdString(info.unit));
  }
  return parts.join(QStringLiteral(", "));
}

}  // namespace sightline
