// Texts of the Qt-free core that the GUI shows: the sensor drivers' descriptions in the Sensors
// menu. The core keeps them in English; the GUI translates them under the context
// "sightline::CoreText", whose entries core_texts.cpp marks for lupdate.
#pragma once

#include <QString>
#include <string>
#include <vector>

namespace sightline {

// `english` in the user's language (as it is when no translation has it).
QString CoreText(const std::string& english);

// Every core text the GUI translates, in English (tests check that each text the core hands the
// GUI is one of them, so a new core text cannot slip through untranslated).
std::vector<std::string> KnownCoreTexts();

}  // namespace sightline
