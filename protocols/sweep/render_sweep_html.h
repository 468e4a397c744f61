// sweep.html: the sweep's plots as inline SVG, one panel per region of [plots] regions: coverage
// at the end of the schedule against the first varied key, one line per combination of the other
// keys' values; then the table of every point.
#pragma once

#include <string>
#include <vector>

#include "protocols/sweep/sweep_collect.h"

namespace protocols {

std::string renderSweepHtml(const SweepManifest& manifest, const std::vector<SweepRow>& rows);

}  // namespace protocols
