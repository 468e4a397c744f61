// Names shared by the frame writer and reader (internal to protocols/io): one place defines the
// layout documented in frame_writer.h.
#pragma once

#include <cstdint>

namespace protocols::layout {

inline constexpr const char* kFramesFormat = "tamponade-frames";
inline constexpr std::int64_t kFramesFormatVersion = 1;
inline constexpr const char* kCheckpointFormat = "tamponade-checkpoint";
// 2: a "checksum" attribute over the whole contents (checkpoint.h).
inline constexpr std::int64_t kCheckpointFormatVersion = 2;
// The field the sidecar uses as particle positions (sim::field::kPosition).
inline constexpr const char* kPositionField = "position";
inline constexpr const char* kTimeColumn = "time";

}  // namespace protocols::layout
