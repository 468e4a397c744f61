// A sweep point's protocol document: the base protocol with each varied key set to the point's
// value. The values keep the sweep file's place, so a value the protocol refuses is reported at
// the line the user wrote it (protocols/format/parse_protocol_document.h).
#pragma once

#include <toml++/toml.h>
#include <filesystem>
#include <string>
#include <vector>

#include "protocols/format/protocol_error.h"
#include "protocols/sweep/sweep_plan.h"

namespace protocols {

// The base document with the point's values set. A path the base cannot hold (an index past
// its postures) is appended to `problems`.
toml::table pointDocument(std::string_view baseText, const SweepPlan& plan, const SweepPoint& point,
                          std::vector<Diagnostic>& problems);

// The point's document as a protocol file of its own: a relative eye.mesh made absolute (the file
// lives in the sweep's folder), the title naming the point, and a header comment.
std::string pointProtocolText(toml::table document, const SweepPlan& plan, const SweepPoint& point);

}  // namespace protocols
