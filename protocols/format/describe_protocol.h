// The normalised protocol in SI: one `key = value unit` line per setting, defaults and preset
// values included and marked, as `tamponade validate` prints it. Lets a user see exactly what a
// file means to the toolkit (units converted, defaults filled in) before anything runs.
#pragma once

#include <string>

#include "protocols/format/protocol.h"

namespace protocols {

std::string describeProtocol(const Protocol& protocol);

}  // namespace protocols
