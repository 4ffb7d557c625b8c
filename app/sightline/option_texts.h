// The option descriptions of the Qt-free core that the GUI's parameters dock shows (the tool tip
// of each row): every Describe() row of every registered pipeline and of the window's view
// options. The core keeps them in English; the dock translates them under the context
// "sightline::OptionText" (widgets/option_editor.cpp, OptionDescription), whose entries the
// generated option_texts.cpp marks for lupdate.
#pragma once

#include <string>
#include <vector>

namespace sightline {

// Every option description marked for translation, in English, sorted (tests check that each
// description the GUI declares is one of them, so a new option cannot slip through untranslated).
std::vector<std::string> KnownOptionTexts();

// Every option description the GUI can show, in English, sorted and without duplicates: the
// view options and the options each registry pipeline declares. The generator of
// option_texts.cpp writes exactly these.
std::vector<std::string> OptionTextsToMark();

}  // namespace sightline
