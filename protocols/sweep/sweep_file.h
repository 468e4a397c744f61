// Reading a sweep file (docs/sweeps.md): the base protocol, the combination rule, the varied keys
// with their values, and the plots' regions. The points are made by planSweep().
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "protocols/format/protocol_error.h"
#include "protocols/sweep/sweep_plan.h"

namespace protocols {

// The plan without its points. Every problem of the file is appended to `problems`.
SweepPlan readSweepFile(const std::filesystem::path& file, std::vector<Diagnostic>& problems);

// Why `path` ("tamponade.fill", "schedule.postures.0.name") is not a protocol key one can vary,
// with how to fix it in `fix`; "" when it is one.
std::string sweepKeyProblem(const std::string& path, std::string& fix);

}  // namespace protocols
