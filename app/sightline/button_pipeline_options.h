// GUI options of the button picker. Keys "button.gui.*".
#pragma once

#include <string>

#include "core/options/option_table.h"

namespace sightline {

struct ButtonGuiOptions {
  bool serve = false;  // Serve targets to the arm (button.arm.*: address, port, token).

  static OptionTable<ButtonGuiOptions> Describe() {
    using O = ButtonGuiOptions;
    return OptionTable<O>("button.gui")
        .Bool("serve", &O::serve,
              "Serve the targets to the arm over TCP (button.arm.bind_address, port, token); "
              "127.0.0.1:5757 by default.");
  }
};

}  // namespace sightline
