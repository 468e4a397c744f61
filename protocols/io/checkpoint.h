// Checkpoints: everything a stopped run needs to continue bit-identically (docs/developer-guide.md
// principles 6 and 7). The particle state is taken from the field registries: every field whose
// `checkpointed` flag is set is stored as float64/int32 without conversion, so a field added by a
// new effect is checkpointed without touching this code.
//
// Layout of checkpoint.h5:
//   /                 attributes format = "tamponade-checkpoint", format_version (2),
//                     toolkit_version, time [s], step, dt [s], checksum (contentChecksum)
//   /counters         one attribute per counter (float64 or int64)
//   /blobs/<name>     opaque bytes (uint8), e.g. protocol hash, RNG state
//   /groups/<g>/<f>   every checkpointed field of group g: rows x components, contiguous
//
// Datasets are contiguous and uncompressed: checkpoints are written on Ctrl-C/SIGTERM too, where
// speed matters more than size, and they are replaced by the next one anyway.
//
// The checksum covers time, step, dt, every counter, blob and checkpointed field's bytes: HDF5
// checksums only its metadata, so a bit flipped in the particle data would otherwise resume as a
// different run. readCheckpoint refuses a checkpoint whose contents do not match it.
//
// Atomic replacement: writeCheckpoint writes <path>.tmp, fsyncs it, renames it over <path> and
// fsyncs the folder, so a crash at any moment leaves either the previous or the new checkpoint,
// and a stale .tmp from a killed writer is never read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <utility>  // before field_registry.h, which uses std::as_const without it

#include "sim/core/field_registry.h"

namespace protocols {

struct CheckpointState {
  double time = 0;  // [s] simulated time
  std::int64_t step = 0;
  double dt = 0;                                        // [s] the time step the next step will take
  std::map<std::string, double> realCounters;           // e.g. accumulated coverage integrals
  std::map<std::string, std::int64_t> integerCounters;  // e.g. frames written, posture index
  std::map<std::string, std::vector<std::uint8_t>> blobs;  // opaque bytes
  // Particle groups by name. writeCheckpoint reads them; readCheckpoint restores into them.
  std::map<std::string, sim::FieldRegistry*> groups;
};

// A 64-bit checksum of everything the checkpoint stores for `state` (word-wise FNV-1a: it detects
// damage, it is not a cryptographic hash).
std::uint64_t contentChecksum(const CheckpointState& state);
// The same checksum of a text (e.g. the protocol a checkpoint belongs to).
std::uint64_t textChecksum(const std::string& text);

// Writes `state` atomically to `path` (conventionally <run folder>/checkpoint.h5). Throws IoError.
void writeCheckpoint(const std::filesystem::path& path, const CheckpointState& state);

// Reads the checkpoint at `path` and restores its particle fields into the registries of
// `restoreInto` (by group name). Every group must exist in the checkpoint with the same particle
// count, and the checkpointed fields of each registry must be exactly the fields stored for it;
// otherwise IoError names the group and the missing or extra fields and nothing is restored.
// A checkpoint whose contents do not match its checksum throws IoError (the registries may then
// hold the damaged values: start afresh). Returns the scalars, counters and blobs, with
// `groups` = `restoreInto`.
CheckpointState readCheckpoint(const std::filesystem::path& path,
                               const std::map<std::string, sim::FieldRegistry*>& restoreInto);

}  // namespace protocols
