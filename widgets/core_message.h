// The core's error texts that the GUI shows for common cases: a profile that does not load, a
// value out of range, an unknown option. The Qt-free core words them in English (Status messages
// naming the file and field); CoreMessage translates them piece by piece under the context
// "sightline::CoreMessage": the status code ("invalid argument"), each origin before a ": "
// ("PATH line 3", "profile PATH") and the message itself ("option '%1': %2 is outside %3"), with
// the filled-in parts (keys, values, ranges, paths) kept as they are.
#pragma once

#include <QString>
#include <QStringList>
#include <string>

namespace sightline {

// `status_text` (Status::ToString(), or a message alone) in the user's language; the parts no
// template knows (e.g. a YAML parser's own words) stay in English.
QString CoreMessage(const std::string& status_text);

// The English templates CoreMessage knows, with %1.. for the filled-in parts (tests match them
// against messages the core really produces).
QStringList CoreMessageTemplates();

}  // namespace sightline
